#include "worker/env/gym/general_observation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "common/geometry/footprint.h"
#include "common/scenario/names.h"
#include "worker/env/gym/moves.h"

namespace rlpos {
namespace {

void Add(BoxSpace& box, double low, double high, std::size_t count = 1) {
  box.low.insert(box.low.end(), count, low);
  box.high.insert(box.high.end(), count, high);
}

double Offset(double metres) {
  return std::clamp(metres / kObservedRangeM, -kObservedOffsetLimit, kObservedOffsetLimit);
}

double Unit(double value, double low, double high) {
  return high > low ? std::clamp((value - low) / (high - low), 0.0, 1.0) : 0.0;
}

double HorizontalDistanceSquared(const Vec3& a, const Vec3& b) {
  return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}

// Indices of `points` by horizontal distance from `from`, nearest first (ties: lower index).
template <typename PositionOf>
std::vector<std::size_t> Nearest(std::size_t count, const Vec3& from, PositionOf position_of) {
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return HorizontalDistanceSquared(position_of(a), from) <
           HorizontalDistanceSquared(position_of(b), from);
  });
  return order;
}

const Vec3& ActivePosition(const Scenario& s, const StepInfo& info) {
  if (info.active_uav < 0 || static_cast<std::size_t>(info.active_uav) >= info.positions.size() ||
      info.positions.size() != s.uavs.size())
    throw std::logic_error("general observation: the step's info does not match the UAVs");
  return info.positions[static_cast<std::size_t>(info.active_uav)];
}

void AddUes(const Scenario& s, const StepInfo& info, std::vector<double>& out) {
  const std::size_t n = s.ues.size();
  if (info.los.size() != n || info.snr_db.size() != n || info.serving.size() != n)
    throw std::logic_error("general observation: the step's info does not match the UEs");
  const Vec3& uav = ActivePosition(s, info);
  const auto order =
      Nearest(n, uav, [&](std::size_t i) -> const Vec3& { return s.ues[i].position; });
  const auto slots = static_cast<std::size_t>(s.env.observed_ues);
  for (std::size_t k = 0; k < slots; ++k) {
    if (k >= n) {
      out.insert(out.end(), kUeSlotWidth, 0.0);
      continue;
    }
    const std::size_t i = order[k];
    const Vec3& ue = s.ues[i].position;
    out.push_back(1.0);
    out.push_back(Offset(ue.x - uav.x));
    out.push_back(Offset(ue.y - uav.y));
    out.push_back(Offset(ue.z - uav.z));
    out.push_back(info.los[i] ? 1.0 : 0.0);
    out.push_back(Unit(info.snr_db[i], kObservedSnrLowDb, kObservedSnrHighDb));
    out.push_back(info.serving[i] == info.active_uav ? 1.0 : 0.0);
  }
}

void AddHeights(const Scenario& s, const StepInfo& info, std::vector<double>& out) {
  const Vec3& uav = ActivePosition(s, info);
  const int cells = s.env.height_map;
  const double size = s.env.step;
  const double half = cells / 2;  // cells is odd: the UAV is over the middle cell's centre
  for (int row = 0; row < cells; ++row) {
    const double y0 = uav.y + (row - half - 0.5) * size;
    for (int col = 0; col < cells; ++col) {
      const double x0 = uav.x + (col - half - 0.5) * size;
      double top = 0.0;
      const Footprint cell{{{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}},
                           {}};
      for (const BuildingSpec& b : s.buildings) {
        // The bounding box first (a box building's whole test), then a footprint's own shape.
        if (b.xmin < x0 + size && b.xmax > x0 && b.ymin < y0 + size && b.ymax > y0 &&
            (!b.HasFootprint() || InteriorsOverlap(b.footprint, cell, 0.0)))
          top = std::max(top, b.height);
      }
      out.push_back(std::min(top / kObservedRangeM, kObservedHeightLimit));
    }
  }
}

void AddOthers(const Scenario& s, const StepInfo& info, std::vector<double>& out) {
  const Vec3& uav = ActivePosition(s, info);
  const std::vector<std::size_t> others =
      OtherUavsNearestFirst(info, static_cast<std::size_t>(info.active_uav));
  for (std::size_t k = 0; k < static_cast<std::size_t>(kOtherUavSlots); ++k) {
    if (k >= others.size()) {
      out.insert(out.end(), kOtherUavSlotWidth, 0.0);
      continue;
    }
    const Vec3& p = info.positions[others[k]];
    out.push_back(1.0);
    out.push_back(Offset(p.x - uav.x));
    out.push_back(Offset(p.y - uav.y));
    out.push_back(Offset(p.z - uav.z));
  }
}

// A look-around field copied from the step's info, which must hold `count` values.
void AddComputed(const std::vector<double>& values, std::size_t count, const char* field,
                 std::vector<double>& out) {
  if (values.size() != count) {
    throw std::logic_error(std::string("general observation: the step's info has no ") + field +
                           " values");
  }
  out.insert(out.end(), values.begin(), values.end());
}

std::size_t CoverageCells(const Scenario& s) {
  return static_cast<std::size_t>(s.env.coverage_map) *
         static_cast<std::size_t>(s.env.coverage_map);
}

}  // namespace

std::vector<std::size_t> OtherUavsNearestFirst(const StepInfo& info, std::size_t uav) {
  const Vec3& from = info.positions.at(uav);
  std::vector<std::size_t> others;
  for (std::size_t u : Nearest(info.positions.size(), from,
                               [&](std::size_t i) -> const Vec3& { return info.positions[i]; })) {
    if (u != uav)
      others.push_back(u);
  }
  return others;
}

bool IsGeneralObservation(std::string_view field) {
  return IsOneOf(field, kGeneralObservations);
}

bool IsModelObservation(std::string_view field) {
  return field == "coverage" || field == "lookahead";
}

double CoverageRewardBound(const Scenario& s) {
  const RewardSpec& r = s.env.reward;
  return std::max(1e-9, std::max(0.0, r.w1) + std::max(0.0, r.w2) + std::max(0.0, r.w3));
}

void AddGeneralBounds(const Scenario& s, std::string_view field, BoxSpace& box) {
  if (field == "zone") {
    Add(box, 0.0, 1.0, 3);
  } else if (field == "ues") {
    for (int k = 0; k < s.env.observed_ues; ++k) {
      Add(box, 0.0, 1.0);
      Add(box, -kObservedOffsetLimit, kObservedOffsetLimit, 3);
      Add(box, 0.0, 1.0, 3);
    }
  } else if (field == "heights") {
    Add(box, 0.0, kObservedHeightLimit,
        static_cast<std::size_t>(s.env.height_map) * static_cast<std::size_t>(s.env.height_map));
  } else if (field == "others") {
    for (int k = 0; k < kOtherUavSlots; ++k) {
      Add(box, 0.0, 1.0);
      Add(box, -kObservedOffsetLimit, kObservedOffsetLimit, 3);
    }
  } else if (field == "coverage") {
    Add(box, 0.0, 1.0, 2 * CoverageCells(s));
    Add(box, -kPointerStepLimit, kPointerStepLimit, 3);
  } else if (field == "lookahead") {
    Add(box, -1.0, 1.0, s.env.actions.size());
  } else if (field == "best") {
    Add(box, 0.0, 1.0);
  }
}

void AddGeneralObservation(const Scenario& s, const StepInfo& info, std::string_view field,
                           std::vector<double>& out) {
  if (field == "zone") {
    const Vec3& p = ActivePosition(s, info);
    const Box& zone = s.uavs[static_cast<std::size_t>(info.active_uav)].zone;
    out.push_back(Unit(p.x, zone.xmin, zone.xmax));
    out.push_back(Unit(p.y, zone.ymin, zone.ymax));
    out.push_back(Unit(p.z, zone.zmin, zone.zmax));
  } else if (field == "ues") {
    AddUes(s, info, out);
  } else if (field == "heights") {
    AddHeights(s, info, out);
  } else if (field == "others") {
    AddOthers(s, info, out);
  } else if (field == "coverage") {
    AddComputed(info.coverage, 2 * CoverageCells(s) + 3, "coverage", out);
  } else if (field == "lookahead") {
    AddComputed(info.lookahead, s.env.actions.size(), "lookahead", out);
  } else if (field == "best") {
    out.push_back(std::clamp(info.below_best * kLookaheadGain / CoverageRewardBound(s), 0.0, 1.0));
  }
}

}  // namespace rlpos
