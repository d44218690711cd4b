// Exact intersection tests of closed simplices (points, segments, triangles), decided by the
// filtered exact orient2d / orient3d only: no tolerance, so a segment that touches a triangle at
// one endpoint or along an edge intersects it, and one a single ulp away does not.
//
// Closed sets throughout: a segment includes its endpoints, a triangle its edges and vertices.
// Degenerate operands (a segment of two equal points, a triangle of collinear points) are a
// precondition violation the callers check first (PLC input checks name them).
#pragma once

#include "kernel/vec.hpp"

namespace dtlab {

// p on the closed segment [a, b] (a != b), for p, a, b in the plane.
bool on_segment2(const Vec2& p, const Vec2& a, const Vec2& b) noexcept;
// Closed segments [a, b] and [c, d] share a point (collinear overlaps included).
bool segments_intersect2(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept;
// p in the closed triangle (a, b, c), a, b, c not collinear, either orientation.
bool in_triangle2(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
// The closed segment [p, q] and the closed triangle (a, b, c) (not collinear) share a point.
bool segment_meets_triangle2(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b, const Vec2& c) noexcept;

// 3D: the closed segment [p, q] (p != q) and the closed triangle (a, b, c) (not collinear) share
// a point. Coplanar operands are decided in a coordinate plane onto which the triangle projects
// without degenerating.
bool segment_meets_triangle3(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) noexcept;

// a, b, c on one line (exactly).
bool collinear3(const Vec3& a, const Vec3& b, const Vec3& c) noexcept;

// Which coordinate to drop so that the non-collinear 3D points a, b, c stay non-collinear: 0 (x),
// 1 (y) or 2 (z); and the projection of p that drops it.
int projection_axis(const Vec3& a, const Vec3& b, const Vec3& c) noexcept;
Vec2 project(const Vec3& p, int drop_axis) noexcept;

}  // namespace dtlab
