// Measures of book §1 and §8.2 in doubles: areas, volumes, circumcentres, radii, edge lengths.
// Everything is computed relative to vertex a (differences first), which keeps the error
// relative to the element's size rather than to its distance from the origin. Whether an
// element is flat is decided by the exact orient2d / orient3d, so a flat element always gets
// the documented infinite radius (and quality.cpp an infinite Q), whatever the rounding.
#include "kernel/constructions.hpp"

#include <cmath>
#include <limits>

#include "kernel/predicates.hpp"

namespace dtlab {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The circumcentre minus a, from the edge vectors at a.
//   2D: u = (|ba|^2 perp(ca) - |ca|^2 perp(ba)) / (2 cross(ba, ca)), perp(v) = (v.y, -v.x)
//       written out per coordinate below.
Vec2 circumcenter_offset(const Vec2& ba, const Vec2& ca) {
  const double bl = dot(ba, ba);
  const double cl = dot(ca, ca);
  const double den = 2.0 * cross(ba, ca);
  return {(ca.y * bl - ba.y * cl) / den, (ba.x * cl - ca.x * bl) / den};
}

//   3D: u = (|ba|^2 ca x da + |ca|^2 da x ba + |da|^2 ba x ca) / (2 det(ba, ca, da)).
Vec3 circumcenter_offset(const Vec3& ba, const Vec3& ca, const Vec3& da) {
  const Vec3 cxd = cross(ca, da);
  const Vec3 dxb = cross(da, ba);
  const Vec3 bxc = cross(ba, ca);
  const double den = 2.0 * dot(ba, cxd);
  const Vec3 num = dot(ba, ba) * cxd + dot(ca, ca) * dxb + dot(da, da) * bxc;
  return {num.x / den, num.y / den, num.z / den};
}

}  // namespace

double signed_area(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  return 0.5 * cross(b - a, c - a);
}

double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  return dot(b - a, cross(c - a, d - a)) / 6.0;
}

Vec2 circumcenter(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  if (orient2d(a, b, c) == Sign::Zero) return {kNaN, kNaN};
  return a + circumcenter_offset(b - a, c - a);
}

Vec3 circumcenter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  if (orient3d(a, b, c, d) == Sign::Zero) return {kNaN, kNaN, kNaN};
  return a + circumcenter_offset(b - a, c - a, d - a);
}

double circumradius(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  if (orient2d(a, b, c) == Sign::Zero) return kInfinity;
  const double r = norm(circumcenter_offset(b - a, c - a));
  return std::isfinite(r) ? r : kInfinity;
}

double circumradius(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  if (orient3d(a, b, c, d) == Sign::Zero) return kInfinity;
  const double r = norm(circumcenter_offset(b - a, c - a, d - a));
  return std::isfinite(r) ? r : kInfinity;
}

double inradius(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  if (orient2d(a, b, c) == Sign::Zero) return 0.0;
  const std::array<double, 3> e = edge_lengths(a, b, c);
  // 2 * area / perimeter, with 2 * area = |cross|.
  return std::fabs(cross(b - a, c - a)) / (e[0] + e[1] + e[2]);
}

double inradius(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  if (orient3d(a, b, c, d) == Sign::Zero) return 0.0;
  const Vec3 ba = b - a, ca = c - a, da = d - a;
  // 3 V / A with 6 V = |det| and 2 A = sum of |cross| over the faces: r = |det| / sum |cross|.
  const double twice_area = norm(cross(ba, ca)) + norm(cross(ba, da)) + norm(cross(ca, da)) +
                            norm(cross(c - b, d - b));
  return std::fabs(dot(ba, cross(ca, da))) / twice_area;
}

std::array<double, 3> edge_lengths(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  return {norm(c - b), norm(a - c), norm(b - a)};
}

std::array<double, 6> edge_lengths(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  return {norm(b - a), norm(c - a), norm(d - a), norm(c - b), norm(d - b), norm(d - c)};
}

}  // namespace dtlab
