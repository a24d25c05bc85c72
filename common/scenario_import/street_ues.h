#pragma once
// Where the UEs of an imported place stand: outdoors (off every footprint, kUeClearance from
// its walls and from the venue's edges), on the half-metre grid, 1.5 m up; on the map's
// streets where the venue has some, else anywhere outdoors. With K groups, K centres are drawn
// along the streets and each UE near its group's centre, in a square of half side U{8..15} m
// (the generator's clusters). Draws come from PortableRandom: the same seed, the same spots.
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/geometry.h"
#include "common/scenario_generator/portable_random.h"
#include "common/scenario_import/place_footprints.h"

namespace rlpos {

// m: a UE keeps this far from every wall and from the venue's edges (as generated UEs do).
constexpr double kUeClearance = 1.0;

struct StreetSegment {
  Point2 a, b;
};

// The streets' pieces inside the venue (projected, clipped to its rectangle).
std::vector<StreetSegment> StreetSegments(const std::vector<std::vector<LonLat>>& streets,
                                          const LocalProjection& projection,
                                          const VenueFrame& venue);

struct UeGround {
  VenueFrame venue;
  std::vector<Footprint> footprints;
  std::vector<StreetSegment> streets;
};

// `p` is outdoors: inside the venue by kUeClearance, outside every footprint by as much.
bool Outdoors(const UeGround& ground, const Point2& p);

struct UeSpots {
  std::vector<Vec3> positions;
  std::string summary;  // "10 UEs along the streets in 2 groups"
};

// `count` spots in `groups` groups (0: each UE drawn on its own); nullopt when some spot could
// not be found in this draw (the caller draws again).
std::optional<UeSpots> DrawUeSpots(const UeGround& ground, int count, int groups,
                                   PortableRandom& random);

}  // namespace rlpos
