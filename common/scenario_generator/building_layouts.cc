#include "common/scenario_generator/building_layouts.h"

#include <algorithm>

namespace rlpos {
namespace {

constexpr double kVenueHeight = 60.0;

// Heights, storeys and rooms of one style's buildings.
struct BuildingDraws {
  int min_height, max_height;  // m, uniform
  int min_rooms, max_rooms;    // per axis, uniform
  std::vector<std::string> types;
  std::vector<int> type_weights;
  std::string walls;
};

// A building on [x0, x1] x [y0, y1]: height uniform, floors = height / storey (a storey of 3 or
// 4 m, at least one floor), rooms uniform per axis, type by weight.
BuildingSpec DrawBuilding(const std::string& name, double x0, double x1, double y0, double y1,
                          const BuildingDraws& draws, PortableRandom& random) {
  BuildingSpec b;
  b.name = name;
  b.xmin = x0;
  b.xmax = x1;
  b.ymin = y0;
  b.ymax = y1;
  const long long height = random.UniformInt(draws.min_height, draws.max_height);
  const long long storey = random.UniformInt(3, 4);
  b.height = static_cast<double>(height);
  b.floors = static_cast<int>(std::max(1LL, height / storey));
  b.rooms_x = static_cast<int>(random.UniformInt(draws.min_rooms, draws.max_rooms));
  b.rooms_y = static_cast<int>(random.UniformInt(draws.min_rooms, draws.max_rooms));
  b.type = draws.types[random.Weighted(draws.type_weights)];
  b.walls = draws.walls;
  return b;
}

std::string HeightRange(const std::vector<BuildingSpec>& buildings) {
  double lo = kVenueHeight, hi = 0;
  for (const auto& b : buildings) {
    lo = std::min(lo, b.height);
    hi = std::max(hi, b.height);
  }
  return std::to_string(static_cast<int>(lo)) + "-" + std::to_string(static_cast<int>(hi)) + " m";
}

// Urban: n x n blocks separated by streets, each block one tall building (1 in 8 an open
// plaza), set back 0-2 m from the block's edge.
std::optional<Layout> DrawUrban(PortableRandom& random) {
  Layout layout;
  const double side = static_cast<double>(100 + 20 * random.UniformInt(0, 2));
  layout.venue = {side, side, kVenueHeight};
  const long long street = random.UniformInt(10, 16);
  const long long block = random.UniformInt(
      18, std::min<long long>(30, (static_cast<long long>(side) - 3 * street) / 2));
  const long long n = (static_cast<long long>(side) - street) / (block + street);
  const long long used = n * block + (n - 1) * street;
  const long long start = (static_cast<long long>(side) - used) / 2;
  const BuildingDraws draws{
      20, 45, 2, 4, {"office", "commercial", "residential"}, {1, 1, 1}, "concrete_with_windows"};
  for (long long i = 0; i < n; ++i) {
    for (long long j = 0; j < n; ++j) {
      if (random.Chance(1, 8))
        continue;  // a plaza
      const double setback = static_cast<double>(random.UniformInt(0, 2));
      const double x0 = static_cast<double>(start + i * (block + street)) + setback;
      const double y0 = static_cast<double>(start + j * (block + street)) + setback;
      const double size = static_cast<double>(block) - 2 * setback;
      layout.buildings.push_back(DrawBuilding("block" + std::to_string(i) + std::to_string(j), x0,
                                              x0 + size, y0, y0 + size, draws, random));
    }
  }
  if (layout.buildings.size() < 3)
    return std::nullopt;
  layout.summary = std::to_string(n) + " x " + std::to_string(n) + " blocks (" +
                   std::to_string(layout.buildings.size()) + " buildings of " +
                   HeightRange(layout.buildings) + "), streets " + std::to_string(street) +
                   " m wide";
  return layout;
}

// Two footprints closer than `gap` (m) on both axes.
bool TooClose(const BuildingSpec& a, const BuildingSpec& b, double gap) {
  return a.xmin < b.xmax + gap && b.xmin < a.xmax + gap && a.ymin < b.ymax + gap &&
         b.ymin < a.ymax + gap;
}

bool Fits(const Layout& layout, const BuildingSpec& b, double gap) {
  for (const auto& other : layout.buildings) {
    if (TooClose(b, other, gap))
      return false;
  }
  return true;
}

// Campus cluster centres, at least 45 m apart, 25 m in from the venue's edges.
std::optional<std::vector<std::pair<long long, long long>>> DrawClusterCentres(
    const Venue& venue, long long count, PortableRandom& random) {
  std::vector<std::pair<long long, long long>> centres;
  for (int tries = 0; tries < 100 && static_cast<long long>(centres.size()) < count; ++tries) {
    const long long x = random.UniformInt(25, static_cast<long long>(venue.width) - 25);
    const long long y = random.UniformInt(25, static_cast<long long>(venue.depth) - 25);
    bool apart = true;
    for (const auto& c : centres)
      apart = apart && (c.first - x) * (c.first - x) + (c.second - y) * (c.second - y) >= 45 * 45;
    if (apart)
      centres.emplace_back(x, y);
  }
  if (static_cast<long long>(centres.size()) < count)
    return std::nullopt;
  return centres;
}

// Campus: 2-3 clusters of 2-4 mid-rise buildings, 4 m apart at least, open space between.
std::optional<Layout> DrawCampus(PortableRandom& random) {
  Layout layout;
  layout.venue = {static_cast<double>(120 + 20 * random.UniformInt(0, 2)), 100.0, kVenueHeight};
  const long long clusters = random.UniformInt(2, 3);
  const auto centres = DrawClusterCentres(layout.venue, clusters, random);
  if (!centres)
    return std::nullopt;
  const BuildingDraws draws{
      12, 30, 2, 4, {"office", "residential"}, {2, 1}, "concrete_with_windows"};
  for (std::size_t k = 0; k < centres->size(); ++k) {
    const long long wanted = random.UniformInt(2, 4);
    int placed = 0;
    for (int tries = 0; tries < 40 && placed < wanted; ++tries) {
      const long long w = random.UniformInt(10, 24), d = random.UniformInt(10, 20);
      const long long x0 = (*centres)[k].first + random.UniformInt(-15, 15) - w / 2;
      const long long y0 = (*centres)[k].second + random.UniformInt(-15, 15) - d / 2;
      BuildingSpec b =
          DrawBuilding("c" + std::to_string(k) + "-b" + std::to_string(placed),
                       static_cast<double>(x0), static_cast<double>(x0 + w),
                       static_cast<double>(y0), static_cast<double>(y0 + d), draws, random);
      if (x0 < 2 || y0 < 2 || x0 + w > layout.venue.width - 2 || y0 + d > layout.venue.depth - 2)
        continue;
      if (!Fits(layout, b, 4.0))
        continue;
      layout.buildings.push_back(b);
      ++placed;
    }
    if (placed == 0)
      return std::nullopt;
  }
  layout.summary = std::to_string(clusters) + " clusters of mid-rise buildings (" +
                   std::to_string(layout.buildings.size()) + " buildings of " +
                   HeightRange(layout.buildings) + ")";
  return layout;
}

// Suburb: 20 m lots, 2 in 5 holding a low house (8-12 x 7-11 m) 3 m in from the lot's edges.
std::optional<Layout> DrawSuburb(PortableRandom& random) {
  Layout layout;
  const long long side = 100 + 20 * random.UniformInt(0, 1);
  layout.venue = {static_cast<double>(side), static_cast<double>(side), kVenueHeight};
  const BuildingDraws draws{5, 10, 1, 2, {"residential"}, {1}, "wood"};
  for (long long i = 0; i < side / 20; ++i) {
    for (long long j = 0; j < side / 20; ++j) {
      if (!random.Chance(2, 5))
        continue;
      const long long w = random.UniformInt(8, 12), d = random.UniformInt(7, 11);
      const long long x0 = 20 * i + random.UniformInt(3, 17 - w);
      const long long y0 = 20 * j + random.UniformInt(3, 17 - d);
      layout.buildings.push_back(DrawBuilding("house" + std::to_string(layout.buildings.size()),
                                              static_cast<double>(x0), static_cast<double>(x0 + w),
                                              static_cast<double>(y0), static_cast<double>(y0 + d),
                                              draws, random));
    }
  }
  if (layout.buildings.size() < 4)
    return std::nullopt;
  layout.summary = std::to_string(layout.buildings.size()) + " houses of " +
                   HeightRange(layout.buildings) + " on 20 m lots";
  return layout;
}

}  // namespace

std::optional<Layout> DrawLayout(GeneratorStyle style, PortableRandom& random) {
  switch (style) {
    case GeneratorStyle::kUrban:
      return DrawUrban(random);
    case GeneratorStyle::kCampus:
      return DrawCampus(random);
    case GeneratorStyle::kSuburb:
      return DrawSuburb(random);
    case GeneratorStyle::kOpen:
      break;
  }
  return Layout{{100.0, 100.0, kVenueHeight}, {}, "free space"};
}

}  // namespace rlpos
