#pragma once
// Points and axis-aligned boxes of a venue (metres; z up).

namespace rlpos {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

// An axis-aligned box [xmin,xmax] x [ymin,ymax] x [zmin,zmax].
struct Box {
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0, zmin = 0, zmax = 0;
  // The boundary counts as inside, as in ns-3's Box::IsInside.
  bool Contains(const Vec3& p) const {
    return p.x >= xmin && p.x <= xmax && p.y >= ymin && p.y <= ymax && p.z >= zmin && p.z <= zmax;
  }
};

}  // namespace rlpos
