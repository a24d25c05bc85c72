#pragma once
// Typed readers and writers of the rlpos topics. Each message type has its topic name and QoS
// fixed in topics.cc (the contract between the daemons):
//   WorkerStatus     reliable, transient-local, keep last 1, automatic liveliness (lease from
//                    the participant's config); the worker disposes it when it stops
//                    cleanly, so that readers tell "stopped" (disposed) from "lost" (no
//                    writers)
//   JobAssignment    reliable, transient-local, key (worker, slot); the writer keeps the last
//                    sample of each slot, readers keep all; a coordinator that stops does NOT
//                    dispose its assignments (a restart must not stop the workers' jobs); a
//                    settled job's slot is disposed, and unregistered only when its worker
//                    stops cleanly (Cyclone 0.10 keeps a little of every key a writer ever
//                    wrote: keys reused per slot keep that bounded)
//   JobEvent         reliable, transient-local, key (worker, slot): the worker keeps its
//                    slot's last event until the job is settled, so a restarted coordinator
//                    still gets results, then disposes it; readers keep all
//   CampaignRequest  reliable, volatile, keep all
//   CampaignReply    reliable, volatile, keep all: the client waits for the coordinator's
//                    writer before it asks, and each reply is unregistered once written, so
//                    nothing is kept per request
// Strings and documents are checked against the IDL's bounds both ways, by one field list per
// message (message_fields.h) and with one error, MessageError: Write throws it for a field too
// long; Take records it in decode_error for a sample that does not decode.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "idl/dds/message_error.h"
#include "idl/dds/messages.h"
#include "idl/dds/participant.h"

namespace rlpos {

enum class InstanceState { kAlive, kDisposed, kNoWriters };

template <typename M>
struct Received {
  M data;             // only the key fields when !valid
  bool valid = true;  // false: a state change only (disposed, or the writer is gone)
  InstanceState state = InstanceState::kAlive;
  std::uint64_t writer = 0;  // the publication handle of the writer (see WriterParticipant)
  std::string decode_error;  // non-empty: the sample broke a bound or an enum; drop it
};

// Decodes one received sample of M's C type (rlpos_messages.h) as Reader::Take does: bounds
// and enum values checked (decode_error: the MessageError's what()), only the key fields when
// !valid. Public so that the decoders are fuzz-tested without a network.
template <typename M>
Received<M> DecodeSample(const void* c_sample, bool valid);

// The C sample of a message as Writer hands it to Cyclone. Its octet sequences borrow the
// message's texts: `message` must outlive it. Throws MessageError for a field over its bound.
// Public, like DecodeSample, so that both directions are tested without a network.
template <typename M>
class EncodedSample {
 public:
  explicit EncodedSample(const M& message);
  ~EncodedSample();
  EncodedSample(const EncodedSample&) = delete;
  EncodedSample& operator=(const EncodedSample&) = delete;

  const void* c_sample() const;  // M's C type

 private:
  struct Storage;
  std::unique_ptr<Storage> storage_;
};

template <typename M>
class Writer {
 public:
  explicit Writer(Participant& participant);
  ~Writer();
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  void Write(const M& message);
  // Disposes the instance with `key`'s key fields (the others are ignored).
  void Dispose(const M& key);
  // Forgets the instance: the writer keeps nothing of it any more (and a reader, once it has
  // taken its samples, neither).
  void Unregister(const M& key);
  int MatchedReaders() const;

 private:
  std::int32_t topic_ = 0, writer_ = 0;
};

template <typename M>
class Reader {
 public:
  explicit Reader(Participant& participant);
  ~Reader();
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  // Everything received since the last Take, in reception order.
  std::vector<Received<M>> Take();
  // The GUID (hex) of the participant that owns the writer `publication_handle`, or "" when
  // that writer is not (or no longer) matched. Cached per handle.
  std::string WriterParticipant(std::uint64_t publication_handle);
  // True while some writer of participant `guid` is matched to this reader.
  bool HasMatchedWriterOf(const std::string& guid);
  int MatchedWriters() const;
  std::int32_t handle() const { return reader_; }

 private:
  std::int32_t topic_ = 0, reader_ = 0;
  std::map<std::uint64_t, std::string> participants_;  // publication handle -> participant
};

}  // namespace rlpos
