#include "worker/env/gym/multi_agent.h"

#include <algorithm>
#include <stdexcept>

#include "common/scenario/scenario_checks.h"
#include "worker/env/gym/moves.h"

namespace rlpos {
namespace {

bool Displaced(const Vec3& a, const Vec3& b) {
  return a.x != b.x || a.y != b.y || a.z != b.z;
}

}  // namespace

Placement ApplyJointDisplacement(const Scenario& s, const Obstacles& buildings,
                                 const std::vector<Vec3>& displacements, const Placement& from) {
  if (displacements.size() != from.size()) {
    throw std::invalid_argument("ApplyJointDisplacement: " + std::to_string(displacements.size()) +
                                " displacements for " + std::to_string(from.size()) + " UAVs");
  }
  Placement to(from.size());
  for (std::size_t u = 0; u < from.size(); ++u)
    to[u] = TargetAlone(s, buildings, u, displacements[u], from[u]);
  // Each pass refuses one move, so at most one pass per UAV (plus the last, finding none).
  for (;;) {
    std::size_t refused = to.size();
    for (std::size_t u = to.size(); u-- > 0 && refused == to.size();) {
      if (Displaced(to[u], from[u]) && OverlapsAnother(to, u, to[u]))
        refused = u;
    }
    if (refused == to.size())
      return to;
    to[refused] = from[refused];
  }
}

std::vector<double> AgentObservation(const Scenario& s, const StepInfo& info, std::size_t uav) {
  StepInfo view = info;  // MakeObservation reads only positions and the per-UE figures
  view.active_uav = static_cast<int>(uav);
  return MakeObservation(s, view);
}

BoxSpace StateBounds(const Scenario& s) {
  BoxSpace box;
  const auto add = [&box](double lo, double hi) {
    box.low.push_back(lo);
    box.high.push_back(hi);
  };
  for (const auto& uav : s.uavs) {
    add(uav.zone.xmin, uav.zone.xmax);
    add(uav.zone.ymin, uav.zone.ymax);
    add(uav.zone.zmin, uav.zone.zmax);
  }
  const double last_uav = static_cast<double>(s.uavs.size()) - 1.0;
  for (std::size_t i = 0; i < s.ues.size(); ++i) {
    add(0, 1);
    add(kObservedSnrLowDb, kObservedSnrHighDb);
    add(0, last_uav);
  }
  add(0, s.TotalDemandMbps());
  add(0, static_cast<double>(s.ues.size()));
  return box;
}

std::vector<double> MakeState(const Scenario& s, const StepInfo& info) {
  const std::size_t n_ues = s.ues.size();
  if (info.positions.size() != s.uavs.size() || info.los.size() != n_ues ||
      info.snr_db.size() != n_ues || info.serving.size() != n_ues) {
    throw std::logic_error("MakeState: the step's info does not match the scenario's UAVs and UEs");
  }
  std::vector<double> state;
  state.reserve(3 * s.uavs.size() + 3 * n_ues + 2);
  for (const auto& p : info.positions) {
    state.push_back(p.x);
    state.push_back(p.y);
    state.push_back(p.z);
  }
  for (std::size_t i = 0; i < n_ues; ++i) {
    state.push_back(info.los[i] ? 1.0 : 0.0);
    state.push_back(std::clamp(info.snr_db[i], kObservedSnrLowDb, kObservedSnrHighDb));
    state.push_back(info.serving[i]);
  }
  state.push_back(std::clamp(info.throughput_mbps, 0.0, s.TotalDemandMbps()));
  state.push_back(info.demands_met);
  return state;
}

}  // namespace rlpos
