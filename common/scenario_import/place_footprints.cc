#include "common/scenario_import/place_footprints.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace rlpos {
namespace {

// Clipped slivers smaller than this (m^2) are not buildings.
constexpr double kMinPieceArea = 1.0;
// A part whose outline lies this close (m) to a building's box may belong to it.
constexpr double kPartSlack = 1.0;

bool Same(const Point2& a, const Point2& b) {
  return a.x == b.x && a.y == b.y;
}

void DropRepeats(Ring& ring) {
  Ring out;
  for (const auto& p : ring) {
    if (out.empty() || !Same(out.back(), p))
      out.push_back(p);
  }
  while (out.size() > 1 && Same(out.front(), out.back()))
    out.pop_back();
  ring = std::move(out);
}

// Removes spikes, edges that double back along the one before (a -> b -> a, or back part of
// the way); returns how many.
int RemoveSpikes(Ring& ring) {
  int removed = 0;
  for (bool again = true; again && ring.size() >= 3;) {
    again = false;
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point2& a = ring[(i + n - 1) % n];
      const Point2& b = ring[i];
      const Point2& c = ring[(i + 1) % n];
      const double cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
      const double dot = (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y);
      if (cross == 0 && dot < 0) {
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
        DropRepeats(ring);
        ++removed;
        again = true;
        break;
      }
    }
  }
  return removed;
}

void Orient(Ring& ring, bool counter_clockwise) {
  if ((SignedArea(ring) > 0) != counter_clockwise)
    std::reverse(ring.begin(), ring.end());
}

bool Within(const Bounds2& inner, const Bounds2& outer, double slack) {
  return inner.xmin >= outer.xmin - slack && inner.ymin >= outer.ymin - slack &&
         inner.xmax <= outer.xmax + slack && inner.ymax <= outer.ymax + slack;
}

bool Meet(const Bounds2& a, const Bounds2& b) {
  return a.xmin < b.xmax && b.xmin < a.xmax && a.ymin < b.ymax && b.ymin < a.ymax;
}

// One polygon of a feature, projected and checked.
struct Candidate {
  std::size_t feature = 0;
  Footprint footprint;
  Bounds2 box;
  bool replaced = false;  // an outline with parts inside it
};

// A part belongs to an outline when most of its corners lie in the outline.
bool PartInside(const Candidate& part, const Candidate& outline) {
  if (!Within(part.box, outline.box, kPartSlack))
    return false;
  std::size_t inside = 0;
  for (const auto& p : part.footprint.outer)
    inside += Contains(outline.footprint, p) ? 1 : 0;
  return 2 * inside >= part.footprint.outer.size();
}

// The piece rounded to the centimetre, unless rounding breaks it.
Footprint Rounded(const Footprint& piece) {
  Footprint out = piece;
  auto round_ring = [](Ring& ring) {
    for (auto& p : ring)
      p = {RoundToCentimetre(p.x), RoundToCentimetre(p.y)};
    DropRepeats(ring);
  };
  round_ring(out.outer);
  for (auto& hole : out.holes)
    round_ring(hole);
  return FootprintDefect(out).empty() ? out : piece;
}

class FootprintBuilder {
 public:
  FootprintBuilder(const PlaceData& data, const LocalProjection& projection,
                   const VenueFrame& venue, FootprintCounts& counts,
                   std::vector<ImportWarning>& warnings)
      : data_(data),
        projection_(projection),
        venue_(venue),
        rect_{0, 0, venue.width, venue.depth},
        counts_(counts),
        warnings_(warnings) {}

  std::vector<Candidate> Candidates() {
    std::vector<Candidate> out;
    for (std::size_t i = 0; i < data_.features.size(); ++i) {
      const PlaceFeature& f = data_.features[i];
      bool in_venue = false;
      for (const auto& polygon : f.polygons) {
        auto candidate = Project(i, polygon, in_venue);
        if (candidate)
          out.push_back(std::move(*candidate));
      }
      if (in_venue)
        counts_.rings_repaired += f.rings_repaired;
    }
    return out;
  }

 private:
  void Warn(const PlaceFeature& f, const std::string& message) {
    warnings_.push_back({f.source, message});
  }

  // A projected ring with its spikes removed (each counted as a repair).
  Ring Cleaned(const GeoRing& geo, const PlaceFeature& f, const char* what) {
    Ring ring = ProjectRing(geo, projection_, venue_);
    const int spikes = RemoveSpikes(ring);
    if (spikes > 0) {
      ++counts_.rings_repaired;
      Warn(f, std::string(what) + ": " + std::to_string(spikes) +
                  " spike(s) (an edge drawn out and back) removed");
    }
    return ring;
  }

  std::optional<Candidate> Project(std::size_t index, const GeoPolygon& polygon, bool& in_venue) {
    const PlaceFeature& f = data_.features[index];
    const Ring projected = ProjectRing(polygon.outer, projection_, venue_);
    if (projected.empty() || !Meet(BoundsOf(projected), rect_))
      return std::nullopt;  // outside the venue: not ours to judge
    in_venue = true;
    Candidate c;
    c.feature = index;
    c.footprint.outer = Cleaned(polygon.outer, f, "outline");
    const std::string defect = RingDefect(c.footprint.outer);
    if (!defect.empty()) {
      ++counts_.rings_dropped;
      Warn(f, "outline is not a simple polygon (" + defect + "): dropped");
      return std::nullopt;
    }
    Orient(c.footprint.outer, true);
    for (const auto& geo_hole : polygon.holes) {
      Ring hole = Cleaned(geo_hole, f, "inner ring");
      std::string why = RingDefect(hole);
      if (why.empty()) {
        Orient(hole, false);
        c.footprint.holes.push_back(hole);
        why = FootprintDefect(c.footprint);
        if (!why.empty())
          c.footprint.holes.pop_back();
      }
      if (!why.empty()) {
        ++counts_.rings_dropped;
        Warn(f, "inner ring (courtyard) is not valid (" + why + "): dropped, the ground is built");
      }
    }
    c.box = BoundsOf(c.footprint.outer);
    return c;
  }

  const PlaceData& data_;
  const LocalProjection& projection_;
  VenueFrame venue_;
  Bounds2 rect_;
  FootprintCounts& counts_;
  std::vector<ImportWarning>& warnings_;
};

std::string BaseName(const PlaceFeature& f) {
  const auto name = f.tags.find("name");
  if (name == f.tags.end() || name->second.empty())
    return f.id;
  return name->second + " (" + f.id + ")";
}

}  // namespace

BuildingSpec PlaceBuildingSpec(const PlaceBuilding& building) {
  BuildingSpec spec;
  spec.name = building.name;
  spec.SetFootprint(building.footprint);
  spec.height = building.height.height;
  spec.min_height = building.height.min_height;
  spec.floors = building.height.floors;
  return spec;
}

double RoundToCentimetre(double metres) {
  return std::round(metres * 100) / 100;
}

Point2 ToVenue(const LonLat& p, const LocalProjection& projection, const VenueFrame& venue) {
  const Point2 local = projection.Forward(p);
  return {RoundToCentimetre(local.x + venue.width / 2),
          RoundToCentimetre(local.y + venue.depth / 2)};
}

Ring ProjectRing(const GeoRing& geo, const LocalProjection& projection, const VenueFrame& venue) {
  Ring ring;
  for (const auto& p : geo)
    ring.push_back(ToVenue(p, projection, venue));
  DropRepeats(ring);
  return ring;
}

std::vector<PlaceBuilding> BuildFootprints(const PlaceData& data, const LocalProjection& projection,
                                           const VenueFrame& venue, const HeightRules& rules,
                                           FootprintCounts& counts,
                                           std::vector<ImportWarning>& warnings) {
  std::vector<Candidate> candidates =
      FootprintBuilder(data, projection, venue, counts, warnings).Candidates();
  // Parts replace the outline they stand in (OpenStreetMap's 3-D convention: the outline is
  // for flat maps, the parts carry the shape and heights).
  for (auto& outline : candidates) {
    if (data.features[outline.feature].is_part)
      continue;
    for (const auto& part : candidates) {
      if (data.features[part.feature].is_part && PartInside(part, outline)) {
        outline.replaced = true;
        break;
      }
    }
    if (outline.replaced) {
      ++counts.outlines_replaced;
      warnings.push_back({data.features[outline.feature].source,
                          "outline replaced by the building:part polygons inside it"});
    }
  }
  const Bounds2 rect{0, 0, venue.width, venue.depth};
  std::vector<PlaceBuilding> buildings;
  std::map<std::size_t, ResolvedHeight> heights;  // per feature, warned about once
  std::map<std::size_t, int> pieces_of;
  for (const auto& c : candidates) {
    if (c.replaced)
      continue;
    std::vector<Footprint> pieces;
    const bool inside = Within(c.box, rect, 0);
    if (inside) {
      pieces.push_back(c.footprint);
    } else {
      for (const auto& piece : ClipToRectangle(c.footprint, rect)) {
        Footprint rounded = Rounded(piece);
        if (Area(rounded) >= kMinPieceArea)
          pieces.push_back(std::move(rounded));
      }
      if (!pieces.empty())
        ++counts.clipped;
    }
    const PlaceFeature& f = data.features[c.feature];
    for (auto& piece : pieces) {
      auto height = heights.find(c.feature);
      if (height == heights.end()) {
        height = heights.emplace(c.feature, ResolveHeight(f, rules, warnings)).first;
        counts.bad_heights += height->second.bad_values;
      }
      Orient(piece.outer, true);
      for (auto& hole : piece.holes)
        Orient(hole, false);
      const int k = ++pieces_of[c.feature];
      PlaceBuilding b;
      b.name = BaseName(f) + (k > 1 ? " #" + std::to_string(k) : "");
      b.source = f.source;
      b.footprint = std::move(piece);
      b.height = height->second;
      b.is_part = f.is_part;
      buildings.push_back(std::move(b));
    }
  }
  return buildings;
}

}  // namespace rlpos
