#include "common/scenario/geometry.h"

#include "common/config/config_error.h"
#include "common/config/object_reader.h"

namespace rlpos {

using nlohmann::json;

Vec3 ReadVec3(const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 3) {
    throw ConfigError(path,
                      "expected [x, y, z], got " +
                          (v.is_array() ? "an array of " + std::to_string(v.size()) : TypeName(v)));
  }
  return {CheckedNumber(v[0], JoinPath(path, 0), {}), CheckedNumber(v[1], JoinPath(path, 1), {}),
          CheckedNumber(v[2], JoinPath(path, 2), {})};
}

std::pair<double, double> ReadInterval(const json& v, const std::string& path, bool allow_point) {
  if (!v.is_array() || v.size() != 2) {
    throw ConfigError(path, "expected [min, max], got " + TypeName(v));
  }
  const double lo = CheckedNumber(v[0], JoinPath(path, 0), {});
  const double hi = CheckedNumber(v[1], JoinPath(path, 1), {});
  if (hi < lo || (!allow_point && hi == lo)) {
    throw ConfigError(path, "min must be below max");
  }
  return {lo, hi};
}

Vec3 ReadGroundPoint(const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 2) {
    throw ConfigError(path,
                      "expected [x, y], got " +
                          (v.is_array() ? "an array of " + std::to_string(v.size()) : TypeName(v)));
  }
  return {CheckedNumber(v[0], JoinPath(path, 0), {}), CheckedNumber(v[1], JoinPath(path, 1), {}),
          0.0};
}

json Vec3Json(const Vec3& v) {
  return json::array({v.x, v.y, v.z});
}

Ring ReadRing(const json& v, const std::string& path) {
  if (!v.is_array())
    throw ConfigError(path, "expected [[x, y], ...], got " + TypeName(v));
  if (v.size() > kMaxRingPoints + 1) {
    throw ConfigError(
        path, std::to_string(v.size()) + " points; at most " + std::to_string(kMaxRingPoints));
  }
  Ring ring;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3 p = ReadGroundPoint(v[i], JoinPath(path, i));
    ring.push_back({p.x, p.y});
  }
  const bool closed =
      ring.size() > 1 && ring.front().x == ring.back().x && ring.front().y == ring.back().y;
  if (closed)
    ring.pop_back();
  if (ring.size() < 3) {
    throw ConfigError(path, "expected at least 3 points [x, y], got " +
                                std::to_string(ring.size()) +
                                (closed ? " besides the repeated first one" : ""));
  }
  if (ring.size() > kMaxRingPoints) {
    throw ConfigError(
        path, std::to_string(ring.size()) + " points; at most " + std::to_string(kMaxRingPoints));
  }
  return ring;
}

json RingJson(const Ring& ring) {
  json out = json::array();
  for (const auto& p : ring)
    out.push_back(json::array({p.x, p.y}));
  return out;
}

std::vector<Ring> ReadRings(const json& v, const std::string& path) {
  if (!v.is_array())
    throw ConfigError(path, "expected [[[x, y], ...], ...], got " + TypeName(v));
  if (v.size() > kMaxHoles) {
    throw ConfigError(path,
                      std::to_string(v.size()) + " rings; at most " + std::to_string(kMaxHoles));
  }
  std::vector<Ring> rings;
  for (std::size_t i = 0; i < v.size(); ++i)
    rings.push_back(ReadRing(v[i], JoinPath(path, i)));
  return rings;
}

json RingsJson(const std::vector<Ring>& rings) {
  json out = json::array();
  for (const auto& ring : rings)
    out.push_back(RingJson(ring));
  return out;
}

}  // namespace rlpos
