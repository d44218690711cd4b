// Shape quality of book §8.2: Q_K = alpha * h_max / rho_K, h_max the longest edge, rho_K the
// inradius, alpha chosen so that the equilateral triangle (regular tetrahedron) has Q = 1:
// alpha = sqrt(3)/6 in 2D, sqrt(6)/12 in 3D. Q >= 1 (up to rounding: a few ulps below 1 for a
// rounded equilateral element); a flat element (exact orient2d / orient3d zero) has
// Q = +infinity, and so has a non-flat one whose area or volume computes to zero.
#pragma once

#include <array>

#include "kernel/metric.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

inline constexpr double kQualityAlpha2d = 0.28867513459481288225;  // sqrt(3) / 6
inline constexpr double kQualityAlpha3d = 0.20412414523193150818;  // sqrt(6) / 12

double shape_quality(const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
double shape_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept;

// Q_K in a metric (book §8.2, (8.7)): Q_K of the element's image under M^1/2 (the space where M
// is the identity). With the vertex metrics, the worst (largest) of the values in each of them.
double shape_quality(const Vec2& a, const Vec2& b, const Vec2& c, const Metric2& m) noexcept;
double shape_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& m) noexcept;
double shape_quality(const Vec2& a, const Vec2& b, const Vec2& c, const Metric2& ma, const Metric2& mb,
                     const Metric2& mc) noexcept;
double shape_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& ma,
                     const Metric3& mb, const Metric3& mc, const Metric3& md) noexcept;

// The 3D values above for a tetrahedron already known not to be flat (orient3d(a, b, c, d) is not
// Zero, as an operator that tested it exactly knows): the same values, without the second test.
// Whatever the orientation (the measure of |det|); of a flat tetrahedron, +inf or a meaningless
// large value, so a caller that compares it with a bound before the exact test must still make it.
double shape_quality_nonflat(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept;
double shape_quality_nonflat(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& m) noexcept;
double shape_quality_nonflat(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& ma,
                             const Metric3& mb, const Metric3& mc, const Metric3& md) noexcept;

// shape_quality_nonflat(a, b, c, d) (Euclidean) for many apexes d over one facet (a, b, c), as
// vertex relocation asks it: what depends only on the facet (its three edges, its area) is
// computed once. The same value, bit for bit, as shape_quality_nonflat(a, b, c, d).
class FacetQuality3 {
 public:
  FacetQuality3() = default;
  FacetQuality3(const Vec3& a, const Vec3& b, const Vec3& c) noexcept;
  double with_apex(const Vec3& d) const noexcept;

 private:
  Vec3 a_{}, b_{}, c_{}, ba_{}, ca_{}, cb_{};
  double s_ba_ = 0.0, s_ca_ = 0.0, s_cb_ = 0.0;  // squared lengths
  double root_area_abc_ = 0.0;                   // |ba x ca| from its square, NaN when too small
};

// The cosines of the largest and the smallest of the six interior dihedral angles of a
// non-flat tetrahedron (Euclidean): {cos of the largest angle, cos of the smallest}. The angle
// along an edge is pi minus the angle between the outward normals of the two faces at it.
std::array<double, 2> dihedral_cosine_range(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept;

// Mean-ratio quality in a metric, as the UGAWG benchmarks measure it (1 = equilateral in M, 0 =
// flat): 2D 4 sqrt(3) area_M / sum of squared edge lengths in M; 3D 12 (3 vol_M)^(2/3) / sum of
// squared edge lengths in M; area_M = sqrt(det M) area. Signed: negative for an inverted element.
double mean_ratio(const Vec2& a, const Vec2& b, const Vec2& c, const Metric2& m) noexcept;
double mean_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& m) noexcept;

}  // namespace dtlab
