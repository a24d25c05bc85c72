#include "gym/moves.h"

#include <algorithm>

#include "scenario/scenario_checks.h"

namespace rlpos {

Vec3 ApplyMove(const Scenario& s, int action, const Vec3& from) {
  const std::string& move = s.env.actions.at(static_cast<std::size_t>(action));
  const double d = s.env.step;
  Vec3 delta{0, 0, 0};
  if (move == "up") delta.z = d;
  if (move == "down") delta.z = -d;
  if (move == "forward") delta.y = d;
  if (move == "backward") delta.y = -d;
  if (move == "right") delta.x = d;
  if (move == "left") delta.x = -d;
  return ApplyDisplacement(s, delta, from);
}

Vec3 ApplyDisplacement(const Scenario& s, const Vec3& delta, const Vec3& from) {
  Vec3 to{from.x + delta.x, from.y + delta.y, from.z + delta.z};
  const Box& z = s.uav.zone;
  to.x = std::clamp(to.x, z.xmin, z.xmax);
  to.y = std::clamp(to.y, z.ymin, z.ymax);
  to.z = std::clamp(to.z, z.zmin, z.zmax);
  return BuildingContaining(s, to) >= 0 ? from : to;
}

BoxSpace DisplacementBounds(const Scenario& s) {
  const double d = s.env.step;
  return {{-d, -d, -d}, {d, d, d}};
}

BoxSpace ObservationBounds(const Scenario& s) {
  BoxSpace box;
  const double n = static_cast<double>(s.ues.size());
  for (const auto& field : s.env.observations) {
    if (field == "x") box.low.push_back(s.uav.zone.xmin), box.high.push_back(s.uav.zone.xmax);
    if (field == "y") box.low.push_back(s.uav.zone.ymin), box.high.push_back(s.uav.zone.ymax);
    if (field == "z") box.low.push_back(s.uav.zone.zmin), box.high.push_back(s.uav.zone.zmax);
    if (field == "n_los" || field == "demands_met") box.low.push_back(0), box.high.push_back(n);
    if (field == "throughput") box.low.push_back(0), box.high.push_back(s.TotalDemandMbps());
    if (field == "snr") {
      for (std::size_t i = 0; i < s.ues.size(); ++i) box.low.push_back(-20), box.high.push_back(60);
    }
  }
  return box;
}

std::vector<double> MakeObservation(const Scenario& s, const StepInfo& info) {
  std::vector<double> obs;
  for (const auto& field : s.env.observations) {
    if (field == "x") obs.push_back(info.position.x);
    if (field == "y") obs.push_back(info.position.y);
    if (field == "z") obs.push_back(info.position.z);
    if (field == "n_los") obs.push_back(info.n_los);
    if (field == "demands_met") obs.push_back(info.demands_met);
    if (field == "throughput") obs.push_back(info.throughput_mbps);
    if (field == "snr") {
      // Clipped to the bounds so that the observation always lies in its space.
      for (double snr : info.snr_db) obs.push_back(std::clamp(snr, -20.0, 60.0));
    }
  }
  return obs;
}

}  // namespace rlpos
