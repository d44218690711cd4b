// A point's coordinates by axis, for code written once over Vec2 and Vec3 (tiles, grids).
#pragma once

namespace dtlab::distributed {

template <class Vec>
constexpr int kDimOf = sizeof(Vec) / sizeof(double);

template <class Vec>
double coordinate(const Vec& p, int axis) {
  if constexpr (kDimOf<Vec> == 3) return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
  else return axis == 0 ? p.x : p.y;
}

template <class Vec>
void set_coordinate(Vec& p, int axis, double v) {
  if (axis == 0) p.x = v;
  else if (axis == 1) p.y = v;
  else if constexpr (kDimOf<Vec> == 3) p.z = v;
}

}  // namespace dtlab::distributed
