#pragma once
// Shared helpers of the DDS tests. Every participant of these tests is loopback-only with a tag
// of its own (network hygiene: never the default config, never another run's traffic).
#include <chrono>
#include <optional>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

#include "idl/dds/dds_config.h"
#include "idl/dds/topics.h"
#include "tests/support/wait_for.h"

namespace rlpos {

// Readable gtest failures.
inline void PrintTo(InstanceState state, std::ostream* os) {
  *os << (state == InstanceState::kAlive      ? "kAlive"
          : state == InstanceState::kDisposed ? "kDisposed"
                                              : "kNoWriters");
}

}  // namespace rlpos

namespace rlpos::testing {

// A fresh loopback tag "rlpos-test-<pid>-<n>" on domain 1 + pid % 200.
DdsOptions TestOptions();

// This test binary, for starting it again as a second DDS process.
std::string SelfExecutable();

// The flag that makes the test binary a child writer instead of running the tests:
//   rlpos_dds_tests --rlpos-child-writer DOMAIN TAG WORKER_ID
// It writes a WorkerStatus {WORKER_ID, host "child", its pid, 3 slots, 1 busy, jobs {"j#1"}},
// prints "ready", then waits; SIGTERM makes it dispose the status and exit 0 (a clean stop),
// SIGKILL leaves it to the lease (a lost worker). It exits 3 by itself after 60 s.
inline constexpr char kChildWriterFlag[] = "--rlpos-child-writer";
int RunChildWriter(int argc, char** argv);

// The flag that makes the test binary a listener, the positive control of a "not seen" check:
//   rlpos_dds_tests --rlpos-child-reader DOMAIN TAG WORKER_ID
// It prints "ready" once its reader exists, then "heard" and exits 0 once a WorkerStatus of
// WORKER_ID arrived; it exits 3 if none did within 30 s.
inline constexpr char kChildReaderFlag[] = "--rlpos-child-reader";
int RunChildReader(int argc, char** argv);

// The flag that makes the test binary a bystander that becomes a coordinator late:
//   rlpos_dds_tests --rlpos-child-late-coordinator DOMAIN TAG
// It reads campaign requests and writes replies; on the first request it forges a reply
// ("forged000000"), and only then opens a second request reader and reply writer, which
// answer that request (ok, campaign "0123456789ab", 3 jobs) if it reaches them. Exits 0 once
// the client is gone, 3 if the request never reached the late reader within 30 s.
inline constexpr char kChildLateCoordinatorFlag[] = "--rlpos-child-late-coordinator";
int RunChildLateCoordinator(int argc, char** argv);

// Takes from `reader` every 10 ms until a sample satisfies `match` or `timeout_s` passed.
// Samples taken before it are appended to `skipped` when given.
template <typename M, typename P>
std::optional<Received<M>> AwaitSample(Reader<M>& reader, P match, double timeout_s = 5.0,
                                       std::vector<Received<M>>* skipped = nullptr) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  for (;;) {
    for (auto& r : reader.Take()) {
      if (match(r))
        return std::move(r);
      if (skipped)
        skipped->push_back(std::move(r));
    }
    if (std::chrono::steady_clock::now() >= deadline)
      return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

// "Nothing else arrived", checked with a positive control: write a marker after what must not
// arrive; one writer's samples arrive in the order it wrote them, so once the marker is in, what
// came before it is all that ever will. Returns the samples taken before the first valid one
// whose data `is_marker` accepts, or nullopt when no marker arrived within `timeout_s`.
template <typename M, typename P>
std::optional<std::vector<Received<M>>> TakenBeforeMarker(Reader<M>& reader, P is_marker,
                                                          double timeout_s = 5.0) {
  std::vector<Received<M>> before;
  const auto marker = [&](const Received<M>& r) { return r.valid && is_marker(r.data); };
  if (!AwaitSample(reader, marker, timeout_s, &before))
    return std::nullopt;
  return before;
}

// The valid samples taken until `count` of them arrived or `timeout_s` passed.
template <typename M>
std::vector<M> AwaitData(Reader<M>& reader, std::size_t count, double timeout_s = 5.0) {
  std::vector<M> out;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (out.size() < count && std::chrono::steady_clock::now() < deadline) {
    for (auto& r : reader.Take()) {
      if (r.valid)
        out.push_back(std::move(r.data));
    }
    if (out.size() < count)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return out;
}

}  // namespace rlpos::testing
