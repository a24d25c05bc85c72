#include "worker/positioning/positioners/tracking_oracle.h"

#include "worker/env/gym/reward.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/positioning/positioners/placement_search.h"

namespace rlpos {

namespace {

// The oracle's own options, no packet-level re-score (the analytic best).
OracleOptions AnalyticOnly() {
  OracleOptions options;
  options.packet_candidates = 0;
  return options;
}

bool SamePositions(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].x != b[i].x || a[i].y != b[i].y || a[i].z != b[i].z)
      return false;
  }
  return a.size() == b.size();
}

}  // namespace

struct TrackingOracle::State {
  State(const Scenario& s, std::size_t budget)
      : scenario(s),
        analytic(s),
        links(s, OracleGridStep(s, options), budget),
        reward(MakeReward(s.env.reward)) {}

  Scenario scenario;  // its UEs where the last decision saw them (the centroid start reads them)
  OracleOptions options = AnalyticOnly();
  AnalyticEvaluator analytic;
  ZoneLinkTable links;
  std::unique_ptr<Reward> reward;
  Placement previous;  // empty before the first decision
};

TrackingOracle::TrackingOracle(const Scenario& scenario, std::size_t link_budget_bytes)
    : state_(std::make_unique<State>(scenario, link_budget_bytes)) {}

TrackingOracle::~TrackingOracle() = default;

Placement TrackingOracle::Decide(const std::vector<Vec3>& ue_positions) {
  State& s = *state_;
  const std::vector<Vec3> before = s.analytic.UePositions();
  // No UE moved (a static scenario, a crowd that dwells): the search would find the previous
  // decision again, the best of the same starts' ends and itself.
  if (!s.previous.empty() && SamePositions(before, ue_positions))
    return s.previous;
  s.analytic.SetUePositions(ue_positions);
  s.links.MoveUes(s.analytic, before);
  for (std::size_t i = 0; i < ue_positions.size(); ++i)
    s.scenario.ues[i].position = ue_positions[i];
  std::vector<Placement> extra;
  if (!s.previous.empty())
    extra.push_back(s.previous);
  s.previous = AnalyticOracle(s.scenario, s.analytic, s.links, *s.reward, s.options, extra)
                   .front()
                   .placement;
  return s.previous;
}

}  // namespace rlpos
