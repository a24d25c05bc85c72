#pragma once
// Warnings about dropped network messages, rate limited: a hostile peer can send thousands of
// bad samples a second, and the log must neither drown nor slow the daemon. At most `burst`
// lines per `period_s`; the next line that gets through says how many were suppressed.
#include <functional>
#include <string>

namespace rlpos {

class DropLog {
 public:
  explicit DropLog(std::string topic, int burst = 10, double period_s = 10.0,
                   std::function<double()> clock = {});
  // "dropped <topic> sample from <sender>: <reason>" at warning level (or counted).
  void Drop(const std::string& sender, const std::string& reason);
  long long dropped() const { return dropped_; }

 private:
  std::string topic_;
  int burst_;
  double period_s_;
  std::function<double()> clock_;
  double window_start_ = -1;
  int in_window_ = 0;
  long long suppressed_ = 0, dropped_ = 0;
};

}  // namespace rlpos
