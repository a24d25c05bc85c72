#include "worker/daemon/sim_command.h"

#include <filesystem>
#include <stdexcept>

#include "common/scenario/names.h"
#include "common/scenario/number_text.h"

namespace rlpos {

std::string WorkerPoliciesDir(const std::string& work_dir) {
  return (std::filesystem::path(work_dir) / "policies").string();
}

namespace {

// `name` as `names` spells it (CheckJobOrder let only those through): no text of the wire
// reaches the command line.
template <std::size_t N>
std::string Spelt(const std::string& name, const std::array<std::string_view, N>& names) {
  for (std::string_view known : names) {
    if (known == name)
      return std::string(known);
  }
  throw std::invalid_argument("\"" + name + "\" is none of " + Alternatives(names));
}

// The run, the duration and the fidelity go on the command line: track takes them there.
std::vector<std::string> TrackCommandLine(const JobOrder& order, const std::string& sim_binary,
                                          const std::string& scenario,
                                          const std::string& policy_dir) {
  const JobParams& p = order.params;
  if (!p.rng_run || !p.duration_s)
    throw std::invalid_argument("a track job needs its RngRun and duration");
  std::vector<std::string> command{sim_binary, "track", "--scenario", scenario, "--positioner"};
  if (order.policy) {
    if (policy_dir.empty())
      throw std::invalid_argument("an rl track job needs its policy's folder");
    command.insert(command.end(), {"rl", "--policy", policy_dir});
  } else {
    command.push_back(Spelt(p.positioner, kTrackPositioners));
  }
  command.insert(command.end(),
                 {"--duration", FormatNumber(*p.duration_s), "--RngRun", std::to_string(*p.rng_run),
                  "--fidelity", Spelt(p.fidelity, kFidelities), "--json"});
  return command;
}

}  // namespace

std::vector<std::string> SimCommandLine(const JobOrder& order, const std::string& sim_binary,
                                        const std::string& folder, const std::string& policy_dir) {
  namespace fs = std::filesystem;
  const std::string scenario = (fs::path(folder) / kScenarioFileName).string();
  const JobParams& p = order.params;
  switch (p.kind) {
    case JobKind::kTrain:
      // The seed, the fidelity and the episodes are in the scenario file, as every setting is.
      return {sim_binary, "train", "--scenario",
              scenario,   "--out", (fs::path(folder) / kOutFolderName).string(),
              "--json"};
    case JobKind::kPosition: {
      if (order.policy) {
        if (policy_dir.empty())
          throw std::invalid_argument("an rl position job needs its policy's folder");
        return {sim_binary, "position", "--scenario", scenario, "--positioner",
                "rl",       "--policy", policy_dir,   "--json"};
      }
      // One of the names CheckJobOrder lets through, spelt by us, not copied from the wire.
      std::string positioner(kPlacingPositioners.front());
      for (std::string_view name : kPlacingPositioners) {
        if (name == p.positioner)
          positioner = name;
      }
      return {sim_binary, "position", "--scenario", scenario, "--positioner", positioner, "--json"};
    }
    case JobKind::kEval:
      break;
    case JobKind::kTrack:
      return TrackCommandLine(order, sim_binary, scenario, policy_dir);
  }
  // Duration, run and warm-up are in the scenario file. One --position per UAV.
  std::vector<std::string> command{sim_binary, "eval", "--scenario", scenario};
  for (const Vec3& position : order.placement.value_or(Placement{})) {
    command.push_back("--position");
    command.push_back(FormatPosition(position));
  }
  command.insert(command.end(), {"--json", "--no-progress"});
  return command;
}

}  // namespace rlpos
