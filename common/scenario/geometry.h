#pragma once
// The JSON forms of points, boxes and rings of a venue (common/geometry), with errors that name
// the path.
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "common/geometry/footprint.h"
#include "common/geometry/vec3.h"

namespace rlpos {

// [x, y, z].
Vec3 ReadVec3(const nlohmann::json& v, const std::string& path);
nlohmann::json Vec3Json(const Vec3& v);
// [x, y]: a point on the ground (z 0).
Vec3 ReadGroundPoint(const nlohmann::json& v, const std::string& path);
// [lo, hi] with lo < hi (or lo <= hi when `allow_point`).
std::pair<double, double> ReadInterval(const nlohmann::json& v, const std::string& path,
                                       bool allow_point);

// The most vertices a ring of a document may have (OpenStreetMap's longest way has 2000), and
// the most holes a footprint may have: checking a ring is quadratic at worst.
constexpr std::size_t kMaxRingPoints = 10000;
constexpr std::size_t kMaxHoles = 1000;
// [[x, y], ...]: a ring's vertices, at least 3. The ring is open: a last point that repeats the
// first (the closed form GeoJSON and OpenStreetMap write) is dropped. Whether it is simple is the
// scenario checks' question (RingDefect).
Ring ReadRing(const nlohmann::json& v, const std::string& path);
nlohmann::json RingJson(const Ring& ring);
// [ring, ...] (at most kMaxHoles).
std::vector<Ring> ReadRings(const nlohmann::json& v, const std::string& path);
nlohmann::json RingsJson(const std::vector<Ring>& rings);

}  // namespace rlpos
