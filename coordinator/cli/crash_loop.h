#pragma once
// When the embedded runner stops restarting a daemon: never for being killed (SIGKILL or
// SIGTERM from outside: chaos, the OOM killer, an operator), however often; only for a crash
// loop: the last `deaths` lives each ended by the daemon itself (an exit or a crash signal)
// within `short_life_s` of their start. A life that ran a while, or was killed, resets the
// count.
#include <string>

namespace rlpos {

class CrashLoopGuard {
 public:
  explicit CrashLoopGuard(int deaths = 3, double short_life_s = 5.0)
      : deaths_(deaths), short_life_s_(short_life_s) {}

  // A life that started at `started_s` ended at `ended_s` (any monotonic clock, seconds);
  // `killed`: by SIGKILL or SIGTERM.
  void Died(double started_s, double ended_s, bool killed) {
    const bool crashed_early = !killed && ended_s - started_s < short_life_s_;
    short_in_a_row_ = crashed_early ? short_in_a_row_ + 1 : 0;
  }
  bool CrashLooping() const { return short_in_a_row_ >= deaths_; }
  // "3 times in a row within 5 s of starting"
  std::string Describe() const;

 private:
  int deaths_;
  double short_life_s_;
  int short_in_a_row_ = 0;
};

}  // namespace rlpos
