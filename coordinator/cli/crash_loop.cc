#include "coordinator/cli/crash_loop.h"

#include "common/scenario/number_text.h"

namespace rlpos {

std::string CrashLoopGuard::Describe() const {
  return std::to_string(short_in_a_row_) + " times in a row within " + FormatNumber(short_life_s_) +
         " s of starting";
}

}  // namespace rlpos
