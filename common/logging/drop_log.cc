#include "common/logging/drop_log.h"

#include <chrono>

#include "common/logging/log.h"

namespace rlpos {

DropLog::DropLog(std::string topic, int burst, double period_s, std::function<double()> clock)
    : topic_(std::move(topic)), burst_(burst), period_s_(period_s), clock_(std::move(clock)) {
  if (!clock_) {
    clock_ = [] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
          .count();
    };
  }
}

void DropLog::Drop(const std::string& sender, const std::string& reason) {
  ++dropped_;
  const double now = clock_();
  if (window_start_ < 0 || now - window_start_ >= period_s_) {
    window_start_ = now;
    in_window_ = 0;
  }
  if (in_window_ >= burst_) {
    ++suppressed_;
    return;
  }
  ++in_window_;
  std::string line = "dropped " + topic_ + " sample from " + sender + ": " + reason;
  if (suppressed_ > 0) {
    line += " (" + std::to_string(suppressed_) + " more dropped before, not shown)";
    suppressed_ = 0;
  }
  Log(LogLevel::kWarning, line);
}

}  // namespace rlpos
