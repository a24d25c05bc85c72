#pragma once
// Polling with a deadline, for tests that wait on another process or on DDS.
#include <chrono>
#include <thread>

namespace rlpos::testing {

// Calls `done` every `period_ms` until it returns true or `timeout_s` passed; returns its last
// answer.
template <typename F>
bool WaitFor(F done, double timeout_s = 5.0, int period_ms = 10) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  for (;;) {
    if (done())
      return true;
    if (std::chrono::steady_clock::now() >= deadline)
      return done();
    std::this_thread::sleep_for(std::chrono::milliseconds(period_ms));
  }
}

}  // namespace rlpos::testing
