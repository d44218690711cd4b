// Shape quality Q_K = alpha * h_max / rho_K of book §8.2: 1 for the
// equilateral triangle / regular tetrahedron, growing without bound as the element flattens.
// Written as alpha * h_max * (sum of facet measures) / |2D area or 3D volume determinant| so that
// one division carries the degeneracy; flatness itself is decided by the exact orientation test.
#include "kernel/quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernel/constructions.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}  // namespace

double shape_quality(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  if (orient2d(a, b, c) == Sign::Zero) return kInfinity;
  const std::array<double, 3> e = edge_lengths(a, b, c);
  const double h_max = std::max({e[0], e[1], e[2]});
  // rho = |cross| / perimeter.
  const double twice_area = std::fabs(cross(b - a, c - a));
  if (twice_area == 0.0) return kInfinity;
  return kQualityAlpha2d * h_max * (e[0] + e[1] + e[2]) / twice_area;
}

double shape_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  if (orient3d(a, b, c, d) == Sign::Zero) return kInfinity;
  const std::array<double, 6> e = edge_lengths(a, b, c, d);
  const double h_max = *std::max_element(e.begin(), e.end());
  const Vec3 ba = b - a, ca = c - a, da = d - a;
  // rho = |det| / (sum over the faces of |cross|).
  const double twice_area = norm(cross(ba, ca)) + norm(cross(ba, da)) + norm(cross(ca, da)) +
                            norm(cross(c - b, d - b));
  const double six_volume = std::fabs(dot(ba, cross(ca, da)));
  if (six_volume == 0.0) return kInfinity;
  return kQualityAlpha3d * h_max * twice_area / six_volume;
}

}  // namespace dtlab
