// Stage 1 of every predicate: the semi-static filter.
//
// The determinant is evaluated in doubles on the computed coordinate differences; its error is
// bounded by C * prod(m), where m are the maxima of those differences' magnitudes (one per
// coordinate column for the orientations, one for all in the in-circle/in-sphere tests) and C
// comes from a forward error analysis of exactly these evaluation trees:
// derive_bounds.py prints the constants below. Valid on the supported coordinate range
// (coordinate_range.hpp), where nothing overflows or underflows.
//
// Each function returns the certified sign, or std::nullopt when |det| <= bound.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernel/sign.hpp"
#include "kernel/vec.hpp"

namespace dtlab::stage {

namespace semistatic_bound {
inline constexpr double kOrient2d = 8.881784197001256e-16;
inline constexpr double kOrient3d = 5.107025913275724e-15;
inline constexpr double kIncircle = 1.421085471520202e-14;
inline constexpr double kInsphere = 1.2456702336294277e-13;
}  // namespace semistatic_bound

// One branch, on "decided" (taken almost always, so well predicted); the sign itself without a
// branch: on random input it is a coin flip that a branch would mispredict half the time.
inline Sign sign_of(double det) noexcept { return static_cast<Sign>(int(det > 0.0) - int(det < 0.0)); }
inline FilteredSign certify(double det, double bound) noexcept {
  if (std::fabs(det) > bound) return sign_of(det);
  return std::nullopt;
}

// The 3D filters also come with a static bound (the _bounded forms, static_filter.hpp): a bound
// valid for every call on a known point set, tried before the operands' maxima are taken;
// kNoStaticBound (infinity) is none.
inline constexpr double kNoStaticBound = std::numeric_limits<double>::infinity();

// orient2d(a, b, c) = det(b - a, c - a): positive iff a, b, c turn counter-clockwise.
inline FilteredSign orient2d_semistatic(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  const double d1x = b.x - a.x, d1y = b.y - a.y;
  const double d2x = c.x - a.x, d2y = c.y - a.y;
  const double det = d1x * d2y - d1y * d2x;
  const double mx = std::max(std::fabs(d1x), std::fabs(d2x));
  const double my = std::max(std::fabs(d1y), std::fabs(d2y));
  return certify(det, semistatic_bound::kOrient2d * mx * my);
}

// The orientation determinant det(r0, r1, r2) of the rows b - a, c - a, d - a, for doubles or
// vectors of doubles, as insphere_det_translated below (facet_batch.hpp).
template <class T>
[[gnu::always_inline]] inline T orient3d_det_translated(T r0x, T r0y, T r0z, T r1x, T r1y, T r1z, T r2x, T r2y,
                                                        T r2z) noexcept {
  return (r0x * (r1y * r2z - r1z * r2y) - r1x * (r0y * r2z - r0z * r2y)) + r2x * (r0y * r1z - r0z * r1y);
}

// orient3d(a, b, c, d) = det(b - a, c - a, d - a): positive iff d lies on the side of plane
// abc from which a, b, c turn counter-clockwise (Medit's positive tetrahedron).
inline FilteredSign orient3d_semistatic_bounded(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                                                double static_bound) noexcept {
  const double r0x = b.x - a.x, r0y = b.y - a.y, r0z = b.z - a.z;
  const double r1x = c.x - a.x, r1y = c.y - a.y, r1z = c.z - a.z;
  const double r2x = d.x - a.x, r2y = d.y - a.y, r2z = d.z - a.z;
  const double det = orient3d_det_translated(r0x, r0y, r0z, r1x, r1y, r1z, r2x, r2y, r2z);
  if (std::fabs(det) > static_bound) return sign_of(det);
  const double mx = std::max({std::fabs(r0x), std::fabs(r1x), std::fabs(r2x)});
  const double my = std::max({std::fabs(r0y), std::fabs(r1y), std::fabs(r2y)});
  const double mz = std::max({std::fabs(r0z), std::fabs(r1z), std::fabs(r2z)});
  return certify(det, semistatic_bound::kOrient3d * mx * my * mz);
}
inline FilteredSign orient3d_semistatic(const Vec3& a, const Vec3& b, const Vec3& c,
                                        const Vec3& d) noexcept {
  return orient3d_semistatic_bounded(a, b, c, d, kNoStaticBound);
}

// incircle(a, b, c, d): positive iff d lies inside the circle through a, b, c when these turn
// counter-clockwise (the sign flips with their orientation). Rows (p - d, |p - d|^2).
inline FilteredSign incircle_semistatic(const Vec2& a, const Vec2& b, const Vec2& c,
                                        const Vec2& d) noexcept {
  const double ax = a.x - d.x, ay = a.y - d.y;
  const double bx = b.x - d.x, by = b.y - d.y;
  const double cx = c.x - d.x, cy = c.y - d.y;
  const double la = ax * ax + ay * ay;
  const double lb = bx * bx + by * by;
  const double lc = cx * cx + cy * cy;
  const double det =
      (la * (bx * cy - by * cx) - lb * (ax * cy - ay * cx)) + lc * (ax * by - ay * bx);
  double m = std::max({std::fabs(ax), std::fabs(ay), std::fabs(bx), std::fabs(by), std::fabs(cx),
                       std::fabs(cy)});
  const double m2 = m * m;
  return certify(det, semistatic_bound::kIncircle * m2 * m2);
}

// The in-sphere determinant on the differences to e (rows (p - e, |p - e|^2)), for doubles or
// for vectors of doubles (facet_batch.hpp): the same operations in the same order, so each
// lane of a vector is bitwise the scalar value, and one error bound serves both. Always inlined:
// an out-of-line copy shared by callers compiled for different vector units (facet_batch.cpp's
// AVX2 and default clones) would pass vectors in the registers of only one of them.
template <class T>
[[gnu::always_inline]] inline T insphere_det_translated(T ax, T ay, T az, T bx, T by, T bz, T cx, T cy, T cz, T dx, T dy, T dz) noexcept {
  // 2x2 minors of the (y, z) columns, shared by the four 3x3 minors.
  const T ab = ay * bz - az * by, ac = ay * cz - az * cy, ad = ay * dz - az * dy;
  const T bc = by * cz - bz * cy, bd = by * dz - bz * dy, cd = cy * dz - cz * dy;
  const T mbcd = (bx * cd - cx * bd) + dx * bc;
  const T macd = (ax * cd - cx * ad) + dx * ac;
  const T mabd = (ax * bd - bx * ad) + dx * ab;
  const T mabc = (ax * bc - bx * ac) + cx * ab;
  const T la = (ax * ax + ay * ay) + az * az;
  const T lb = (bx * bx + by * by) + bz * bz;
  const T lc = (cx * cx + cy * cy) + cz * cz;
  const T ld = (dx * dx + dy * dy) + dz * dz;
  return ((la * mbcd - lb * macd) + lc * mabd) - ld * mabc;
}

// insphere(a, b, c, d, e): positive iff e lies inside the sphere through a, b, c, d when
// orient3d(a, b, c, d) > 0 (the sign flips with their orientation).
inline FilteredSign insphere_semistatic_bounded(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                                                const Vec3& e, double static_bound) noexcept {
  const double ax = a.x - e.x, ay = a.y - e.y, az = a.z - e.z;
  const double bx = b.x - e.x, by = b.y - e.y, bz = b.z - e.z;
  const double cx = c.x - e.x, cy = c.y - e.y, cz = c.z - e.z;
  const double dx = d.x - e.x, dy = d.y - e.y, dz = d.z - e.z;
  const double det = insphere_det_translated(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz);
  if (std::fabs(det) > static_bound) return sign_of(det);
  // The maximum as a tree (depth 4, not a chain of 11).
  const double mx = std::max(std::max(std::fabs(ax), std::fabs(bx)), std::max(std::fabs(cx), std::fabs(dx)));
  const double my = std::max(std::max(std::fabs(ay), std::fabs(by)), std::max(std::fabs(cy), std::fabs(dy)));
  const double mz = std::max(std::max(std::fabs(az), std::fabs(bz)), std::max(std::fabs(cz), std::fabs(dz)));
  const double m = std::max(std::max(mx, my), mz);
  const double m2 = m * m;
  return certify(det, semistatic_bound::kInsphere * m2 * m2 * m);
}
inline FilteredSign insphere_semistatic(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                                        const Vec3& e) noexcept {
  return insphere_semistatic_bounded(a, b, c, d, e, kNoStaticBound);
}

}  // namespace dtlab::stage
