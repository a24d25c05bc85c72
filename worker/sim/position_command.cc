#include <fstream>
#include <iostream>

#include "campaign/offsets.h"
#include "config/config_error.h"
#include "gym/analytic_evaluator.h"
#include "gym/reward.h"
#include "positioners/positioners.h"
#include "scenario/scenario_parser.h"
#include "sim/commands.h"
#include "sim/scenario_loading.h"

namespace rlpos::sim {

int RunPosition(const CommonOptions& options, const PositionOptions& p) {
  const Scenario s = LoadScenarioFor(options, {});
  Vec3 position;
  nlohmann::json candidates = nlohmann::json::array();
  if (p.positioner == "baseline") {
    position = BaselinePosition(s);
  } else if (p.positioner == "centroid") {
    position = CentroidPosition(s);
  } else if (p.positioner == "oracle") {
    const auto ranked = OracleSearch(s, OracleOptions{});
    position = ranked.front().position;
    for (std::size_t i = 0; i < ranked.size() && i < 5; ++i) {
      const auto& c = ranked[i];
      candidates.push_back({{"position", {c.position.x, c.position.y, c.position.z}},
                            {"analytic_reward", c.analytic_reward},
                            // null: not re-scored at packet level
                            {"packet_reward", c.packet_reward ? nlohmann::json(*c.packet_reward)
                                                              : nlohmann::json(nullptr)},
                            {"n_los", c.n_los}});
    }
  } else if (p.positioner == "offsets") {
    if (p.offset < 1 || p.offset > kOffsetCount) {
      throw ConfigError("--offset", "is required for the offsets positioner: 1 to 5");
    }
    if (p.from.empty() == p.policy.empty()) {
      throw ConfigError("--from", "give exactly one of --from x,y,z or --policy DIR (the centre)");
    }
    const Vec3 center = p.from.empty() ? RlPosition(s, p.policy) : ParsePosition(p.from, "--from");
    position = OffsetPosition(center, p.offset, OffsetGeometryOf(s));
  } else {
    position = RlPosition(s, p.policy);
  }
  // Every positioner is scored the same way: the analytic model at its position.
  AnalyticEvaluator analytic(s);
  const StepInfo info = analytic.Evaluate(position);
  const double reward = (*MakeReward(s.env.reward))(
      RewardInputOf(s, info.n_los, info.throughput_mbps, info.demands_met));
  nlohmann::json out = {{"scenario", s.name},
                        {"positioner", p.positioner},
                        {"position", {position.x, position.y, position.z}},
                        {"n_los", info.n_los},
                        {"n_ues", s.ues.size()},
                        {"analytic_throughput_mbps", info.throughput_mbps},
                        {"demands_met", info.demands_met},
                        {"reward", reward}};
  if (!candidates.empty())
    out["candidates"] = candidates;
  if (p.json) {
    std::cout << out.dump(2) << std::endl;
  } else {
    std::printf(
        "%s in %s: (%.1f, %.1f, %.1f), nLoS %d/%zu, analytic throughput %.1f Mbit/s, "
        "reward %.4f\n",
        p.positioner.c_str(), s.name.c_str(), position.x, position.y, position.z, info.n_los,
        s.ues.size(), info.throughput_mbps, reward);
  }
  return kExitOk;
}

}  // namespace rlpos::sim
