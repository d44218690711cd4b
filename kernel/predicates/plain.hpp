// The unfiltered baseline the benchmarks and papers/ compare the predicates against: the
// evaluation trees of semistatic.hpp in doubles, the sign of the rounded value taken as is. NOT
// robust (wrong near degeneracies; Kettner et al.'s grid shows it) and used by no algorithm.
// The sign is taken without a branch: on random input it is a coin flip, and a branch on it would
// charge the baseline a misprediction that the predicate's own cost does not include.
#pragma once

#include "kernel/predicates/semistatic.hpp"  // the shared evaluation trees
#include "kernel/sign.hpp"
#include "kernel/vec.hpp"

namespace dtlab::plain {

inline Sign sign_without_branch(double v) noexcept { return static_cast<Sign>(int(v > 0.0) - int(v < 0.0)); }

inline Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  const double d1x = b.x - a.x, d1y = b.y - a.y;
  const double d2x = c.x - a.x, d2y = c.y - a.y;
  return sign_without_branch(d1x * d2y - d1y * d2x);
}

inline Sign orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  const double r0x = b.x - a.x, r0y = b.y - a.y, r0z = b.z - a.z;
  const double r1x = c.x - a.x, r1y = c.y - a.y, r1z = c.z - a.z;
  const double r2x = d.x - a.x, r2y = d.y - a.y, r2z = d.z - a.z;
  return sign_without_branch(stage::orient3d_det_translated(r0x, r0y, r0z, r1x, r1y, r1z, r2x, r2y, r2z));
}

inline Sign incircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept {
  const double ax = a.x - d.x, ay = a.y - d.y;
  const double bx = b.x - d.x, by = b.y - d.y;
  const double cx = c.x - d.x, cy = c.y - d.y;
  const double la = ax * ax + ay * ay;
  const double lb = bx * bx + by * by;
  const double lc = cx * cx + cy * cy;
  return sign_without_branch((la * (bx * cy - by * cx) - lb * (ax * cy - ay * cx)) + lc * (ax * by - ay * bx));
}

inline Sign insphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) noexcept {
  const double ax = a.x - e.x, ay = a.y - e.y, az = a.z - e.z;
  const double bx = b.x - e.x, by = b.y - e.y, bz = b.z - e.z;
  const double cx = c.x - e.x, cy = c.y - e.y, cz = c.z - e.z;
  const double dx = d.x - e.x, dy = d.y - e.y, dz = d.z - e.z;
  return sign_without_branch(stage::insphere_det_translated(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz));
}

}  // namespace dtlab::plain
