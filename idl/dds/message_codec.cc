// EncodedSample and DecodeSample (dds/topics.h): each message's field list (dds/message_fields.h)
// run one way or the other.
#include <memory>

#include "idl/dds/message_fields.h"
#include "idl/dds/topics.h"

namespace rlpos {

template <typename M>
struct EncodedSample<M>::Storage {
  typename codec::Message<M>::C c{};
  codec::SequenceBuffers buffers;
};

template <typename M>
EncodedSample<M>::EncodedSample(const M& message) : storage_(std::make_unique<Storage>()) {
  codec::Encoder encoder(storage_->buffers);
  codec::Message<M>::Fields(encoder, message, storage_->c);
}

template <typename M>
EncodedSample<M>::~EncodedSample() = default;

template <typename M>
const void* EncodedSample<M>::c_sample() const {
  return &storage_->c;
}

template <typename M>
Received<M> DecodeSample(const void* c_sample, bool valid) {
  using C = typename codec::Message<M>::C;
  Received<M> r;
  r.valid = valid;
  codec::Decoder decoder(!valid);
  try {
    // Into r.data itself: the key fields, decoded first, stay when a later field is refused.
    codec::Message<M>::Fields(decoder, r.data, *static_cast<const C*>(c_sample));
  } catch (const MessageError& e) {
    r.decode_error = e.what();
  }
  return r;
}

template class EncodedSample<msg::WorkerStatus>;
template class EncodedSample<msg::JobAssignment>;
template class EncodedSample<msg::JobEvent>;
template class EncodedSample<msg::CampaignRequest>;
template class EncodedSample<msg::CampaignReply>;
template Received<msg::WorkerStatus> DecodeSample(const void*, bool);
template Received<msg::JobAssignment> DecodeSample(const void*, bool);
template Received<msg::JobEvent> DecodeSample(const void*, bool);
template Received<msg::CampaignRequest> DecodeSample(const void*, bool);
template Received<msg::CampaignReply> DecodeSample(const void*, bool);

}  // namespace rlpos
