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

}  // namespace rlpos
