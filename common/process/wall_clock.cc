#include "common/process/wall_clock.h"

#include <chrono>

namespace rlpos {

double WallClockSeconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

}  // namespace rlpos
