#include "worker/env/gym/moves.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string_view>

#include "common/scenario/scenario_checks.h"
#include "worker/env/gym/general_observation.h"

namespace rlpos {

// The names are compared at every step: as string_views they compare their lengths first.
using namespace std::string_view_literals;

Vec3 MoveDisplacement(const Scenario& s, int action) {
  const std::string_view move = s.env.actions.at(static_cast<std::size_t>(action));
  const double d = s.env.step;
  Vec3 delta{0, 0, 0};
  if (move == "up"sv)
    delta.z = d;
  if (move == "down"sv)
    delta.z = -d;
  if (move == "forward"sv)
    delta.y = d;
  if (move == "backward"sv)
    delta.y = -d;
  if (move == "right"sv)
    delta.x = d;
  if (move == "left"sv)
    delta.x = -d;
  return delta;
}

int ToBestAction(const Scenario& s) {
  const auto& actions = s.env.actions;
  const auto it = std::find(actions.begin(), actions.end(), "to_best");
  return it == actions.end() ? -1 : static_cast<int>(it - actions.begin());
}

Vec3 StepTowards(const Scenario& s, const Obstacles& buildings, std::size_t uav, const Vec3& target,
                 const Placement& from) {
  const Vec3& at = from.at(uav);
  const double offset[3] = {target.x - at.x, target.y - at.y, target.z - at.z};
  int order[3] = {0, 1, 2};
  std::stable_sort(order, order + 3,
                   [&offset](int a, int b) { return std::abs(offset[a]) > std::abs(offset[b]); });
  for (const int axis : order) {
    if (offset[axis] == 0.0)
      break;
    const double length = std::min(s.env.step, std::abs(offset[axis]));
    Vec3 delta{0, 0, 0};
    (axis == 0 ? delta.x : axis == 1 ? delta.y : delta.z) = std::copysign(length, offset[axis]);
    const Vec3 to = DisplacementTarget(s, buildings, uav, delta, from);
    if (to.x != at.x || to.y != at.y || to.z != at.z)
      return delta;
  }
  return {0, 0, 0};
}

Placement ApplyMove(const Scenario& s, const Obstacles& buildings, std::size_t uav, int action,
                    const Placement& from) {
  return ApplyDisplacement(s, buildings, uav, MoveDisplacement(s, action), from);
}

Vec3 TargetAlone(const Scenario& s, const Obstacles& buildings, std::size_t uav, const Vec3& delta,
                 const Vec3& at) {
  Vec3 to{at.x + delta.x, at.y + delta.y, at.z + delta.z};
  const Box& z = s.uavs.at(uav).zone;
  to.x = std::clamp(to.x, z.xmin, z.xmax);
  to.y = std::clamp(to.y, z.ymin, z.ymax);
  to.z = std::clamp(to.z, z.zmin, z.zmax);
  return buildings.SolidAt(to) >= 0 ? at : to;
}

Vec3 DisplacementTarget(const Scenario& s, const Obstacles& buildings, std::size_t uav,
                        const Vec3& delta, const Placement& from) {
  const Vec3 to = TargetAlone(s, buildings, uav, delta, from.at(uav));
  return OverlapsAnother(from, uav, to) ? from[uav] : to;
}

Placement ApplyDisplacement(const Scenario& s, const Obstacles& buildings, std::size_t uav,
                            const Vec3& delta, const Placement& from) {
  const Vec3 to = TargetAlone(s, buildings, uav, delta, from.at(uav));
  if (OverlapsAnother(from, uav, to))
    return from;
  Placement placement = from;
  placement[uav] = to;
  return placement;
}

namespace {

// A lattice coordinate: `from` plus a whole number of `step`s within [lo, hi]. mt19937_64 is
// specified to the bit and the modulo is integer, so the draw is the same on every platform.
double LatticePoint(double from, double lo, double hi, double step, std::mt19937_64& engine) {
  const auto below = static_cast<long long>(std::floor((from - lo) / step + 1e-9));
  const auto above = static_cast<long long>(std::floor((hi - from) / step + 1e-9));
  const auto choices = static_cast<unsigned long long>(below + above + 1);
  const long long k = static_cast<long long>(engine() % choices) - below;
  return from + static_cast<double>(k) * step;
}

}  // namespace

Placement RandomStart(const Scenario& s, const Obstacles& buildings, std::uint64_t seed) {
  std::mt19937_64 engine(seed ^ 0x5eedc0ffee5717a7ULL);  // not the ns-3 RngRun's stream
  Placement placement = s.InitialPlacement();
  const double d = s.env.step;
  for (std::size_t u = 0; u < placement.size(); ++u) {
    const Box& zone = s.uavs[u].zone;
    const Vec3 from = placement[u];
    for (int attempt = 0; attempt < 64; ++attempt) {
      const Vec3 to{LatticePoint(from.x, zone.xmin, zone.xmax, d, engine),
                    LatticePoint(from.y, zone.ymin, zone.ymax, d, engine),
                    LatticePoint(from.z, zone.zmin, zone.zmax, d, engine)};
      if (buildings.SolidAt(to) < 0 && !OverlapsAnother(placement, u, to)) {
        placement[u] = to;
        break;
      }
    }
  }
  return placement;
}

BoxSpace DisplacementBounds(const Scenario& s) {
  const double d = s.env.step;
  return {{-d, -d, -d}, {d, d, d}};
}

namespace {

// Appends the bounds of one field of env.observations to `box`.
void AddFieldBounds(const Scenario& s, const std::string& field, BoxSpace& box) {
  const double n = static_cast<double>(s.ues.size());
  auto per_uav = [&](double Box::*lo, double Box::*hi) {
    for (const auto& uav : s.uavs)
      box.low.push_back(uav.zone.*lo), box.high.push_back(uav.zone.*hi);
  };
  if (field == "x")
    per_uav(&Box::xmin, &Box::xmax);
  else if (field == "y")
    per_uav(&Box::ymin, &Box::ymax);
  else if (field == "z")
    per_uav(&Box::zmin, &Box::zmax);
  else if (field == "n_los" || field == "demands_met")
    box.low.push_back(0), box.high.push_back(n);
  else if (field == "throughput")
    box.low.push_back(0), box.high.push_back(s.TotalDemandMbps());
  else if (field == "snr") {
    for (std::size_t i = 0; i < s.ues.size(); ++i)
      box.low.push_back(kObservedSnrLowDb), box.high.push_back(kObservedSnrHighDb);
  } else
    AddGeneralBounds(s, field, box);
}

}  // namespace

BoxSpace ObservationBounds(const Scenario& s) {
  BoxSpace box;
  bool plain = false;  // a field of the scenario's own (not a general one): the one-hot follows
  for (const auto& field : s.env.observations) {
    plain = plain || !IsGeneralObservation(field);
    AddFieldBounds(s, field, box);
  }
  if (s.uavs.size() > 1 && plain) {
    for (std::size_t u = 0; u < s.uavs.size(); ++u)
      box.low.push_back(0), box.high.push_back(1);
  }
  return box;
}

std::optional<SlotBlock> UeSlotBlock(const Scenario& s) {
  BoxSpace before;  // the fields ahead of "ues" (the one-hot, if any, comes after them all)
  for (const auto& field : s.env.observations) {
    if (field == "ues")
      return SlotBlock{static_cast<int>(before.Dim()), s.env.observed_ues, kUeSlotWidth};
    AddFieldBounds(s, field, before);
  }
  return std::nullopt;
}

// Called at every step: each field is compared until its branch is found, once.
std::vector<double> MakeObservation(const Scenario& s, const StepInfo& info) {
  std::vector<double> obs;
  obs.reserve(3 * info.positions.size() + 3 + info.snr_db.size() + s.uavs.size());
  bool plain = false;  // as in ObservationBounds
  for (const std::string_view field : s.env.observations) {
    bool general = false;
    if (field == "x"sv) {
      for (const auto& p : info.positions)
        obs.push_back(p.x);
    } else if (field == "y"sv) {
      for (const auto& p : info.positions)
        obs.push_back(p.y);
    } else if (field == "z"sv) {
      for (const auto& p : info.positions)
        obs.push_back(p.z);
    } else if (field == "n_los"sv) {
      obs.push_back(info.n_los);
    } else if (field == "demands_met"sv) {
      obs.push_back(info.demands_met);
    } else if (field == "throughput"sv) {
      obs.push_back(info.throughput_mbps);
    } else if (field == "snr"sv) {
      // Clipped to the bounds so that the observation always lies in its space.
      for (double snr : info.snr_db)
        obs.push_back(std::clamp(snr, kObservedSnrLowDb, kObservedSnrHighDb));
    } else {
      general = true;
      AddGeneralObservation(s, info, field, obs);
    }
    plain = plain || !general;
  }
  if (s.uavs.size() > 1 && plain) {
    for (std::size_t u = 0; u < s.uavs.size(); ++u)
      obs.push_back(static_cast<int>(u) == info.active_uav ? 1.0 : 0.0);
  }
  return obs;
}

}  // namespace rlpos
