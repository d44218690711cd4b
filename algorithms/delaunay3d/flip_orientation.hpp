// Orientation with the infinite vertex, for variant "flip" (flip.cpp), which flips ghost
// tetrahedra like finite ones and so needs to know whether a tetrahedron through kInfinite is
// positive.
//
// Why this rule. Lift the points to the paraboloid and add the vertical point at infinity w:
// finite tetrahedra are the lower facets of the convex hull, ghosts its vertical facets
// (w, a, b, c). Seen from a centre O high above a point c0 strictly inside the hull, every facet
// projects to a non-degenerate cell, and the orientation of (w, a, b, c) from O is the 3D
// orientation of (c0, a, b, c) with the opposite sign: kInfinite acts as a point inside the
// hull whose orientations are negated. A ghost is then positive exactly when c0 lies on the inner
// side of its hull facet, i.e. when q beyond the facet makes (q, a, b, c) positive, as
// tetrahedralization3.hpp defines it; ghosts fill the cones from c0 over the hull facets, beyond
// them, so every point of space lies in one tetrahedron, finite or ghost.
//
// c0 is symbolic: v0 + e (v1 - v0) + e^2 (v2 - v0) + e^3 (v3 - v0) for the first tetrahedron
// (v0, v1, v2, v3) and e infinitely small, strictly inside it and so inside every later hull.
// orient3d(c0, a, b, c) is affine in c0, so its sign is that of the first non-zero among
// orient3d(v0, a, b, c), orient3d(v1, ...), orient3d(v2, ...), orient3d(v3, ...), zero only when
// a, b, c are collinear.
#pragma once

#include <array>
#include <cstdint>

#include "kernel/sign.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

class FlipOrientation {
 public:
  // points: indexed by vertex id; first: the first tetrahedron, whose vertices span space.
  FlipOrientation(const Vec3* points, std::array<std::uint32_t, 4> first) noexcept;

  // Orientation of (a, b, c, d), at most one of them kInfinite: orient3d for finite points,
  // the rule above otherwise.
  Sign orient(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const noexcept;

 private:
  // Sign of orient3d(c0, a, b, c).
  Sign from_interior(std::uint32_t a, std::uint32_t b, std::uint32_t c) const noexcept;

  const Vec3* p_;
  std::array<Vec3, 4> first_;
};

}  // namespace dtlab
