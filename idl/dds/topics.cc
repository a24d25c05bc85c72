#include "idl/dds/topics.h"

#include <dds/dds.h>

#include <memory>

#include "idl/dds/topic_names.h"
#include "rlpos_messages.h"

namespace rlpos {
namespace {

using QosPtr = std::unique_ptr<dds_qos_t, void (*)(dds_qos_t*)>;

QosPtr NewQos() {
  return QosPtr(dds_create_qos(), dds_delete_qos);
}

template <typename M>
struct Traits;

template <>
struct Traits<msg::WorkerStatus> {
  static constexpr const char* kTopic = topic::kWorkerStatus;
  static const dds_topic_descriptor_t* Descriptor() { return &rlpos_msg_WorkerStatus_desc; }
  static void Qos(dds_qos_t* qos, bool writer) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
    // Automatic liveliness rides on the participant's lease (short in the loopback config).
    if (writer) {
      dds_qset_liveliness(qos, DDS_LIVELINESS_AUTOMATIC, DDS_INFINITY);
      // A worker that stops cleanly disposes its status itself; a lost one must show as
      // no-writers, and Cyclone would otherwise dispose on its behalf.
      dds_qset_writer_data_lifecycle(qos, false);
    }
  }
};

template <>
struct Traits<msg::JobAssignment> {
  static constexpr const char* kTopic = topic::kJobAssignment;
  static const dds_topic_descriptor_t* Descriptor() { return &rlpos_msg_JobAssignment_desc; }
  static void Qos(dds_qos_t* qos, bool writer) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
    if (writer) {
      dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
      dds_qset_writer_data_lifecycle(qos, false);
    } else {
      // Every sample of a slot, in order: an emptied slot followed by its next job, and no
      // other writer's sample of the same slot can take the coordinator's place unread.
      dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
    }
  }
};

template <>
struct Traits<msg::JobEvent> {
  static constexpr const char* kTopic = topic::kJobEvent;
  static const dds_topic_descriptor_t* Descriptor() { return &rlpos_msg_JobEvent_desc; }
  static void Qos(dds_qos_t* qos, bool writer) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
    if (writer) {
      dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
    } else {
      dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
    }
  }
};

template <>
struct Traits<msg::CampaignRequest> {
  static constexpr const char* kTopic = topic::kCampaignRequest;
  static const dds_topic_descriptor_t* Descriptor() { return &rlpos_msg_CampaignRequest_desc; }
  static void Qos(dds_qos_t* qos, bool) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_VOLATILE);
    dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  }
};

template <>
struct Traits<msg::CampaignReply> {
  static constexpr const char* kTopic = topic::kCampaignReply;
  static const dds_topic_descriptor_t* Descriptor() { return &rlpos_msg_CampaignReply_desc; }
  static void Qos(dds_qos_t* qos, bool) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_VOLATILE);
    dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  }
};

template <typename M>
std::int32_t CreateTopic(Participant& participant) {
  return CheckDds(dds_create_topic(participant.handle(), Traits<M>::Descriptor(), Traits<M>::kTopic,
                                   nullptr, nullptr),
                  std::string("DDS topic ") + Traits<M>::kTopic);
}

InstanceState StateOf(const dds_sample_info_t& info) {
  switch (info.instance_state) {
    case DDS_IST_NOT_ALIVE_DISPOSED:
      return InstanceState::kDisposed;
    case DDS_IST_NOT_ALIVE_NO_WRITERS:
      return InstanceState::kNoWriters;
    default:
      return InstanceState::kAlive;
  }
}

}  // namespace

template <typename M>
Writer<M>::Writer(Participant& participant) {
  topic_ = CreateTopic<M>(participant);
  QosPtr qos = NewQos();
  Traits<M>::Qos(qos.get(), true);
  writer_ = CheckDds(dds_create_writer(participant.handle(), topic_, qos.get(), nullptr),
                     std::string("DDS writer of ") + Traits<M>::kTopic);
}

template <typename M>
Writer<M>::~Writer() {
  dds_delete(writer_);
}

template <typename M>
void Writer<M>::Write(const M& message) {
  const EncodedSample<M> sample(message);
  CheckDds(dds_write(writer_, sample.c_sample()), std::string("writing ") + Traits<M>::kTopic);
}

template <typename M>
void Writer<M>::Dispose(const M& key) {
  const EncodedSample<M> sample(key);
  CheckDds(dds_dispose(writer_, sample.c_sample()),
           std::string("disposing in ") + Traits<M>::kTopic);
}

template <typename M>
void Writer<M>::Unregister(const M& key) {
  const EncodedSample<M> sample(key);
  CheckDds(dds_unregister_instance(writer_, sample.c_sample()),
           std::string("unregistering in ") + Traits<M>::kTopic);
}

template <typename M>
int Writer<M>::MatchedReaders() const {
  dds_publication_matched_status_t status{};
  CheckDds(dds_get_publication_matched_status(writer_, &status), "publication status");
  return static_cast<int>(status.current_count);
}

template <typename M>
Reader<M>::Reader(Participant& participant) {
  topic_ = CreateTopic<M>(participant);
  QosPtr qos = NewQos();
  Traits<M>::Qos(qos.get(), false);
  reader_ = CheckDds(dds_create_reader(participant.handle(), topic_, qos.get(), nullptr),
                     std::string("DDS reader of ") + Traits<M>::kTopic);
}

template <typename M>
Reader<M>::~Reader() {
  dds_delete(reader_);
}

template <typename M>
std::vector<Received<M>> Reader<M>::Take() {
  constexpr std::size_t kBatch = 64;
  std::vector<Received<M>> out;
  for (;;) {
    void* samples[kBatch] = {nullptr};
    dds_sample_info_t infos[kBatch];
    const dds_return_t n = dds_take(reader_, samples, infos, kBatch, kBatch);
    CheckDds(n, std::string("taking from ") + Traits<M>::kTopic);
    for (dds_return_t i = 0; i < n; ++i) {
      Received<M> r = DecodeSample<M>(samples[i], infos[i].valid_data);
      r.state = StateOf(infos[i]);
      r.writer = infos[i].publication_handle;
      out.push_back(std::move(r));
    }
    if (n > 0)
      dds_return_loan(reader_, samples, n);
    if (static_cast<std::size_t>(n) < kBatch)
      return out;
  }
}

template <typename M>
std::string Reader<M>::WriterParticipant(std::uint64_t publication_handle) {
  if (const auto it = participants_.find(publication_handle); it != participants_.end()) {
    return it->second;
  }
  dds_builtintopic_endpoint_t* endpoint =
      dds_get_matched_publication_data(reader_, publication_handle);
  if (!endpoint)
    return "";
  static const char kHex[] = "0123456789abcdef";
  std::string guid;
  for (const unsigned char byte : endpoint->participant_key.v) {
    guid += kHex[byte >> 4];
    guid += kHex[byte & 15];
  }
  dds_builtintopic_free_endpoint(endpoint);
  // Writers come and go (clients, restarted workers): keep the cache from growing without end.
  if (participants_.size() >= 4096)
    participants_.clear();
  participants_.emplace(publication_handle, guid);
  return guid;
}

template <typename M>
bool Reader<M>::HasMatchedWriterOf(const std::string& guid) {
  // Every matched writer, however many there are: a peer that adds writers to the topic must
  // not hide the one looked for.
  std::vector<dds_instance_handle_t> handles(64);
  for (;;) {
    const dds_return_t n = dds_get_matched_publications(reader_, handles.data(), handles.size());
    if (n < 0)
      return false;
    const bool complete = static_cast<std::size_t>(n) <= handles.size();
    handles.resize(static_cast<std::size_t>(n));
    if (complete)
      break;
  }
  for (const dds_instance_handle_t handle : handles) {
    if (WriterParticipant(handle) == guid)
      return true;
  }
  return false;
}

template <typename M>
int Reader<M>::MatchedWriters() const {
  dds_subscription_matched_status_t status{};
  CheckDds(dds_get_subscription_matched_status(reader_, &status), "subscription status");
  return static_cast<int>(status.current_count);
}

template class Writer<msg::WorkerStatus>;
template class Writer<msg::JobAssignment>;
template class Writer<msg::JobEvent>;
template class Writer<msg::CampaignRequest>;
template class Writer<msg::CampaignReply>;
template class Reader<msg::WorkerStatus>;
template class Reader<msg::JobAssignment>;
template class Reader<msg::JobEvent>;
template class Reader<msg::CampaignRequest>;
template class Reader<msg::CampaignReply>;

}  // namespace rlpos
