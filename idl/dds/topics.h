#pragma once
// Typed readers and writers of the rlpos topics. Each message type has its topic name and QoS
// fixed in topics.cc (the contract between the daemons):
//   WorkerStatus     reliable, transient-local, keep last 1, automatic liveliness (lease from
//                    the participant's config); the worker disposes it when it stops
//                    cleanly, so that readers tell "stopped" (disposed) from "lost" (no
//                    writers)
//   JobAssignment    reliable, transient-local, keep last 1; a coordinator that stops does NOT
//                    dispose its assignments (a restart must not stop the workers' jobs)
//   JobEvent         reliable, transient-local (the worker keeps its last event per job, so a
//                    restarted coordinator still gets results); readers keep all
//   CampaignRequest  reliable, volatile, keep all
//   CampaignReply    reliable, transient-local, keep last 1
#include <cstdint>
#include <vector>

#include "dds/messages.h"
#include "dds/participant.h"

namespace rlpos {

enum class InstanceState { kAlive, kDisposed, kNoWriters };

template <typename M>
struct Received {
  M data;             // only the key fields when !valid
  bool valid = true;  // false: a state change only (disposed, or the writer is gone)
  InstanceState state = InstanceState::kAlive;
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
  int MatchedWriters() const;
  std::int32_t handle() const { return reader_; }

 private:
  std::int32_t topic_ = 0, reader_ = 0;
};

}  // namespace rlpos
