#include "kernel/intersections.hpp"

#include <algorithm>
#include <array>

#include "kernel/predicates.hpp"

namespace dtlab {

namespace {

int sign_of(Sign s) noexcept { return s == Sign::Positive ? 1 : s == Sign::Negative ? -1 : 0; }

}  // namespace

bool on_segment2(const Vec2& p, const Vec2& a, const Vec2& b) noexcept {
  if (orient2d(a, b, p) != Sign::Zero) return false;
  // Collinear: inside the bounding box of [a, b] (coordinate comparisons are exact).
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool segments_intersect2(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept {
  const int abc = sign_of(orient2d(a, b, c)), abd = sign_of(orient2d(a, b, d));
  const int cda = sign_of(orient2d(c, d, a)), cdb = sign_of(orient2d(c, d, b));
  if (abc * abd < 0 && cda * cdb < 0) return true;  // proper crossing
  // Otherwise they meet only if an endpoint lies on the other segment.
  return on_segment2(c, a, b) || on_segment2(d, a, b) || on_segment2(a, c, d) || on_segment2(b, c, d);
}

bool in_triangle2(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  const int s = sign_of(orient2d(a, b, c));
  return sign_of(orient2d(a, b, p)) * s >= 0 && sign_of(orient2d(b, c, p)) * s >= 0 &&
         sign_of(orient2d(c, a, p)) * s >= 0;
}

bool collinear3(const Vec3& a, const Vec3& b, const Vec3& c) noexcept {
  // The cross product (b - a) x (c - a) vanishes iff all three coordinate projections are
  // collinear.
  return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == Sign::Zero &&
         orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == Sign::Zero &&
         orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == Sign::Zero;
}

Vec2 project(const Vec3& p, int drop_axis) noexcept {
  switch (drop_axis) {
    case 0: return {p.y, p.z};
    case 1: return {p.z, p.x};
    default: return {p.x, p.y};
  }
}

int projection_axis(const Vec3& a, const Vec3& b, const Vec3& c) noexcept {
  for (const int axis : {2, 0, 1})
    if (orient2d(project(a, axis), project(b, axis), project(c, axis)) != Sign::Zero) return axis;
  return 2;  // collinear: the caller's precondition is broken; any answer is as good
}

bool segment_meets_triangle2(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  return in_triangle2(p, a, b, c) || in_triangle2(q, a, b, c) || segments_intersect2(p, q, a, b) ||
         segments_intersect2(p, q, b, c) || segments_intersect2(p, q, c, a);
}

bool segment_meets_triangle3(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) noexcept {
  const int sp = sign_of(orient3d(a, b, c, p)), sq = sign_of(orient3d(a, b, c, q));
  if (sp * sq > 0) return false;  // both strictly on one side of the plane
  if (sp == 0 && sq == 0) {
    // Coplanar: a 2D question in a projection that keeps the triangle a triangle.
    const int axis = projection_axis(a, b, c);
    return segment_meets_triangle2(project(p, axis), project(q, axis), project(a, axis), project(b, axis),
                                   project(c, axis));
  }
  // The line pq crosses the plane at one point, which lies on [p, q]; it is in the closed
  // triangle iff the line passes no edge on the wrong side: the three orientations of the line
  // against the edges do not have opposite strict signs.
  const int s1 = sign_of(orient3d(p, q, a, b)), s2 = sign_of(orient3d(p, q, b, c)),
            s3 = sign_of(orient3d(p, q, c, a));
  const bool any_positive = s1 > 0 || s2 > 0 || s3 > 0;
  const bool any_negative = s1 < 0 || s2 < 0 || s3 < 0;
  return !(any_positive && any_negative);
}

}  // namespace dtlab
