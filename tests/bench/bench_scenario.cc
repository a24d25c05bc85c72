#include "tests/bench/bench_scenario.h"

#include <cstdio>
#include <cstdlib>

#include "common/config/config_error.h"
#include "worker/env/network/scenario_loading.h"

std::optional<rlpos::Scenario> LoadBenchScenario(const char* path, const char* duration_s) {
  double duration = 0.0;
  if (duration_s != nullptr) {
    char* end = nullptr;
    duration = std::strtod(duration_s, &end);
    if (*end != '\0' || !(duration > 0)) {
      std::fprintf(stderr, "error: duration: %s is not a positive number of seconds\n", duration_s);
      return std::nullopt;
    }
  }
  try {
    rlpos::Scenario s = rlpos::LoadScenario(path, {});
    if (duration_s != nullptr)
      s.simulation.duration = s.simulation.warmup + duration;
    return s;
  } catch (const rlpos::ConfigError& e) {
    std::fprintf(stderr, "error: %s: %s\n", path, e.describe().c_str());
    return std::nullopt;
  }
}
