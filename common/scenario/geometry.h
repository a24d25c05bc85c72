#pragma once
// Points and boxes of a venue (metres; z up), and their JSON forms with errors that name the path.
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

namespace rlpos {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

// An axis-aligned box [xmin,xmax] x [ymin,ymax] x [zmin,zmax].
struct Box {
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0, zmin = 0, zmax = 0;
  bool Contains(const Vec3& p) const {
    return p.x >= xmin && p.x <= xmax && p.y >= ymin && p.y <= ymax && p.z >= zmin && p.z <= zmax;
  }
};

// [x, y, z].
Vec3 ReadVec3(const nlohmann::json& v, const std::string& path);
nlohmann::json Vec3Json(const Vec3& v);
// [x, y]: a point on the ground (z 0).
Vec3 ReadGroundPoint(const nlohmann::json& v, const std::string& path);
// [lo, hi] with lo < hi (or lo <= hi when `allow_point`).
std::pair<double, double> ReadInterval(const nlohmann::json& v, const std::string& path,
                                       bool allow_point);

}  // namespace rlpos
