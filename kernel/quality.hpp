// Shape quality of book §8.2: Q_K = alpha * h_max / rho_K, h_max the longest edge, rho_K the
// inradius, alpha chosen so that the equilateral triangle (regular tetrahedron) has Q = 1:
// alpha = sqrt(3)/6 in 2D, sqrt(6)/12 in 3D. Q >= 1 (up to rounding: a few ulps below 1 for a
// rounded equilateral element); a flat element (exact orient2d / orient3d zero) has
// Q = +infinity, and so has a non-flat one whose area or volume computes to zero.
#pragma once

#include "kernel/vec.hpp"

namespace dtlab {

inline constexpr double kQualityAlpha2d = 0.28867513459481288225;  // sqrt(3) / 6
inline constexpr double kQualityAlpha3d = 0.20412414523193150818;  // sqrt(6) / 12

double shape_quality(const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
double shape_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept;

}  // namespace dtlab
