#include <cstdio>
#include <fstream>
#include <iostream>

#include "common/config/config_error.h"
#include "common/job/offsets.h"
#include "common/scenario/number_text.h"
#include "common/scenario/placement_json.h"
#include "common/scenario/scenario_parser.h"
#include "worker/env/gym/reward.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/positioning/positioners/positioners.h"
#include "worker/programs/rlpos_sim/commands.h"

namespace rlpos::sim {

namespace {}  // namespace

int RunPosition(const CommonOptions& options, const PositionOptions& p) {
  const Scenario s = LoadScenarioFor(options, {});
  Placement placement;
  nlohmann::json candidates = nlohmann::json::array();
  if (p.positioner == "baseline") {
    placement = BaselinePlacement(s);
  } else if (p.positioner == "centroid") {
    placement = CentroidPlacement(s);
  } else if (p.positioner == "oracle") {
    const auto ranked = OracleSearch(s, OracleOptions{});
    placement = ranked.front().placement;
    for (std::size_t i = 0; i < ranked.size() && i < 5; ++i) {
      const auto& c = ranked[i];
      nlohmann::json candidate = {
          {"position", PlacementJson({c.placement.front()})[0]},
          {"analytic_reward", c.analytic_reward},
          // null: not re-scored at packet level
          {"packet_reward",
           c.packet_reward ? nlohmann::json(*c.packet_reward) : nlohmann::json(nullptr)},
          {"n_los", c.n_los}};
      if (s.uavs.size() > 1)
        candidate["positions"] = PlacementJson(c.placement);
      candidates.push_back(candidate);
    }
  } else if (p.positioner == "offsets") {
    if (s.uavs.size() > 1) {
      throw ConfigError("--positioner", "offsets move one UAV; scenario " + s.name + " has " +
                                            std::to_string(s.uavs.size()));
    }
    if (p.offset < 1 || p.offset > kOffsetCount) {
      throw ConfigError("--offset", "is required for the offsets positioner: 1 to 5");
    }
    if (p.from.empty() == p.policy.empty()) {
      throw ConfigError("--from", "give exactly one of --from x,y,z or --policy DIR (the centre)");
    }
    const Vec3 center =
        p.from.empty() ? RlPlacement(options, p.policy).front() : ParsePosition(p.from, "--from");
    placement = {OffsetPosition(center, p.offset, OffsetGeometryOf(s))};
  } else {
    placement = RlPlacement(options, p.policy);
  }
  // Every positioner is scored the same way: the analytic model at its placement.
  AnalyticEvaluator analytic(s);
  const StepInfo info = analytic.Evaluate(placement);
  const double reward = (*MakeReward(s.env.reward))(
      RewardInputOf(s, info.n_los, info.throughput_mbps, info.demands_met));
  const Vec3& first = placement.front();
  nlohmann::json out = {{"scenario", s.name},
                        {"positioner", p.positioner},
                        {"position", {first.x, first.y, first.z}},  // the first UAV's
                        {"n_los", info.n_los},
                        {"n_ues", s.ues.size()},
                        {"analytic_throughput_mbps", info.throughput_mbps},
                        {"demands_met", info.demands_met},
                        {"reward", reward}};
  if (s.uavs.size() > 1) {
    out["positions"] = PlacementJson(placement);
    out["serving_uav"] = info.serving;
  }
  if (!candidates.empty())
    out["candidates"] = candidates;
  if (p.json) {
    std::cout << out.dump(2) << std::endl;
  } else {
    std::printf("%s in %s: %s, in LoS %d/%zu, analytic throughput %.1f Mbit/s, reward %.4f\n",
                p.positioner.c_str(), s.name.c_str(), DescribePlacement(placement).c_str(),
                info.n_los, s.ues.size(), info.throughput_mbps, reward);
  }
  return kExitOk;
}

}  // namespace rlpos::sim
