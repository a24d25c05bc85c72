#pragma once
// A Cyclone wait set over readers: a daemon sleeps until one of them has data or a timeout.
#include <cstdint>

#include "idl/dds/participant.h"

namespace rlpos {

class WaitSet {
 public:
  explicit WaitSet(Participant& participant);
  ~WaitSet();
  WaitSet(const WaitSet&) = delete;
  WaitSet& operator=(const WaitSet&) = delete;

  // Wakes up when the reader has any sample (data or a state change) not yet taken.
  void Attach(std::int32_t reader);
  // Returns false on timeout.
  bool Wait(double timeout_s);

 private:
  std::int32_t waitset_ = 0;
};

}  // namespace rlpos
