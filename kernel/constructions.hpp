// Constructions and measures of book §1 and §8.2, in doubles: areas and volumes, circumcentres
// and radii, inradii, edge lengths. These are measures, not decisions: no combinatorial choice
// in dtlab depends on them (the predicates decide); where a constructed point must be exact or
// correctly rounded, rounding.hpp does it.
#pragma once

#include <array>

#include "kernel/vec.hpp"

namespace dtlab {

// Signed area of triangle abc: positive iff counter-clockwise. Measures in doubles: on a nearly
// flat element the sign may differ from orient2d / orient3d, which alone decide orientation.
double signed_area(const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
// Signed volume of tetrahedron abcd: det(b-a, c-a, d-a) / 6, positive iff orient3d > 0.
double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept;

// Circumcentre and circumradius; for a degenerate (flat) element the centre has infinite or
// NaN coordinates and the radius is +infinity. Flat means the exact orient2d / orient3d is zero
// (then the centre is NaN); a non-flat element whose computed centre overflows also gets an
// infinite radius.
Vec2 circumcenter(const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
Vec3 circumcenter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept;
double circumradius(const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
double circumradius(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept;

// Inradius: 2 * area / perimeter in 2D, 3 * volume / total face area in 3D; 0 when flat (exact
// orient2d / orient3d zero).
double inradius(const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
double inradius(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept;

// Edge lengths, in the local edge order of the element: triangle (bc, ca, ab), i.e. edge i is
// opposite vertex i; tetrahedron (ab, ac, ad, bc, bd, cd).
std::array<double, 3> edge_lengths(const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
std::array<double, 6> edge_lengths(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept;

}  // namespace dtlab
