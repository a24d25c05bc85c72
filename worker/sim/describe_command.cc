// rlpos-sim describe metrics: the eval metrics table (metrics/eval_metrics.h) as Markdown, the
// text between the docs' "BEGIN GENERATED metrics" and "END GENERATED metrics" markers.
#include <iostream>

#include "metrics/eval_metrics.h"
#include "sim/commands.h"

namespace rlpos::sim {

int RunDescribe(const std::string& what) {
  if (what != "metrics") {
    std::cerr << "rlpos-sim: error: describe: unknown table \"" << what << "\" (known: metrics)"
              << std::endl;
    return kExitBadInput;
  }
  std::cout << EvalMetricsMarkdown();
  return kExitOk;
}

}  // namespace rlpos::sim
