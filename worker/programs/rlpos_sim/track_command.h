#pragma once
// rlpos-sim track --scenario S --positioner P [--policy DIR] --duration T --RngRun N
// [--fidelity analytic|packet] [--json] [--set PATH=VALUE]...: one run in which the UEs walk their
// trajectories and the UAVs follow the positioner within their speed limits
// (worker/positioning/track), scored every decision interval by the analytic model or by ns-3's
// packets. rl flies a policy for any scenario
// (--policy) online. Prints the run's means; --json adds the per-interval series.
#include <CLI/CLI.hpp>
#include <string>

#include "worker/programs/rlpos_sim/commands.h"

namespace rlpos::sim {

struct TrackCommand {
  CLI::App* command = nullptr;
  std::string positioner;
  std::string policy;     // rl: a policy for any scenario
  double duration = 0.0;  // s; checked against env.decision_interval by the run
  long long run = 0;
  std::string fidelity = "analytic";
  bool json = false;
};

// Adds `track` to `app`; the scenario file goes into `options` (--set: the caller adds it).
void AddTrack(CLI::App& app, TrackCommand& track, CommonOptions& options);
int RunTrackCommand(const CommonOptions& options, const TrackCommand& track);

}  // namespace rlpos::sim
