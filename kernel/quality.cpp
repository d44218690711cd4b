// Shape quality Q_K = alpha * h_max / rho_K of book §8.2: 1 for the
// equilateral triangle / regular tetrahedron, growing without bound as the element flattens.
// Written as alpha * h_max * (sum of facet measures) / |2D area or 3D volume determinant| so that
// one division carries the degeneracy; flatness itself is decided by the exact orientation test.
// In a metric M (book (8.7)) the same measures are taken of the image under S = M^1/2, without
// computing S: |S v| = sqrt(v^T M v), area and volume scale by sqrt(det M), and a face with normal
// n = u x w has |S u x S w| = sqrt(n^T adj(M) n) (adj(M) = det(M) M^-1, the adjugate).
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

namespace {

// max(edge_lengths(a, b, c, d)), bit for bit, with the norm (a three-term hypot) taken only of
// the edges whose rounded squared length is within a relative 1e-9 of the largest: the others
// are shorter beyond any rounding of either measure. Outside the range where the squares neither
// overflow nor lose their relative precision, all six.
double longest_edge(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  const std::array<Vec3, 6> e{b - a, c - a, d - a, c - b, d - b, d - c};
  std::array<double, 6> s;
  double s_max = 0.0;
  for (int i = 0; i < 6; ++i) {
    s[i] = dot(e[i], e[i]);
    s_max = std::max(s_max, s[i]);
  }
  const bool safe = s_max > 1e-280 && s_max < 1e280;
  const double floor = safe ? s_max * (1.0 - 1e-9) : 0.0;
  double h_max = 0.0;
  for (int i = 0; i < 6; ++i)
    if (!safe || s[i] >= floor) h_max = std::max(h_max, norm(e[i]));
  return h_max;
}

// Q_K from the hypot norms: the value outside the range where quality_from_squares (below) keeps
// its relative precision (very small or very large differences of coordinates).
double shape_quality_by_hypot(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  const double h_max = longest_edge(a, b, c, d);
  const Vec3 ba = b - a, ca = c - a, da = d - a;
  // rho = |det| / (sum over the faces of |cross|).
  const double twice_area = norm(cross(ba, ca)) + norm(cross(ba, da)) + norm(cross(ca, da)) +
                            norm(cross(c - b, d - b));
  const double six_volume = std::fabs(dot(ba, cross(ca, da)));
  if (six_volume == 0.0) return kInfinity;
  return kQualityAlpha3d * h_max * twice_area / six_volume;
}

constexpr double kLowSquare = 1e-200;  // above it, squared areas are normal numbers

// Q_K of the tetrahedron with edges ba, ca, da (from a) and cb, db (from b), the first facet's
// twice-area given, from the square roots of the rounded squared norms (each correctly rounded,
// about five times cheaper than hypot's scaled sums); NaN outside the range where those squares
// keep their relative precision (squared edges within [1e-140, 1e140] keep the squared areas
// below 1e280), so that every comparison with it fails.
double quality_from_squares(double s_max, double area_abc, const Vec3& ba, const Vec3& ca, const Vec3& da,
                            const Vec3& cb, const Vec3& db) noexcept {
  const Vec3 n1 = cross(ba, da), n2 = cross(ca, da), n3 = cross(cb, db);
  const double q1 = dot(n1, n1), q2 = dot(n2, n2), q3 = dot(n3, n3);
  const double six_volume = std::fabs(dot(ba, n2));  // n2 = cross(ca, da)
  if (!(s_max > 1e-140 && s_max < 1e140 && q1 > kLowSquare && q2 > kLowSquare && q3 > kLowSquare &&
        six_volume > 0.0))
    return std::numeric_limits<double>::quiet_NaN();
  const double twice_area = area_abc + std::sqrt(q1) + std::sqrt(q2) + std::sqrt(q3);
  return kQualityAlpha3d * std::sqrt(s_max) * twice_area / six_volume;
}

// The first facet's twice-area for quality_from_squares, NaN where its square is too small.
double root_area(const Vec3& ba, const Vec3& ca) noexcept {
  const Vec3 n0 = cross(ba, ca);
  const double q0 = dot(n0, n0);
  return q0 > kLowSquare ? std::sqrt(q0) : std::numeric_limits<double>::quiet_NaN();
}

// Q_K by the square roots of the squares where they keep their precision, NaN elsewhere.
double quality_by_squares(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  const Vec3 ba = b - a, ca = c - a, da = d - a, cb = c - b, db = d - b, dc = d - c;
  const double s_max = std::max({dot(ba, ba), dot(ca, ca), dot(da, da), dot(cb, cb), dot(db, db), dot(dc, dc)});
  const double area = root_area(ba, ca);
  if (std::isnan(area)) return area;
  return quality_from_squares(s_max, area, ba, ca, da, cb, db);
}

}  // namespace

double shape_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  if (orient3d(a, b, c, d) == Sign::Zero) return kInfinity;
  return shape_quality_nonflat(a, b, c, d);
}

double shape_quality_nonflat(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  const double q = quality_by_squares(a, b, c, d);
  return std::isnan(q) ? shape_quality_by_hypot(a, b, c, d) : q;
}

std::array<double, 2> dihedral_cosine_range(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  // Outward normals of the faces opposite a, b, c, d: each turned away from its vertex.
  const std::array<Vec3, 4> p{a, b, c, d};
  std::array<Vec3, 4> n;
  std::array<double, 4> length;
  for (int i = 0; i < 4; ++i) {
    const Vec3& x = p[(i + 1) & 3];
    const Vec3& y = p[(i + 2) & 3];
    const Vec3& z = p[(i + 3) & 3];
    Vec3 m = cross(y - x, z - x);
    if (dot(m, p[i] - x) > 0.0) m = -1.0 * m;
    n[i] = m;
    length[i] = norm_by_square(m);
  }
  double lo = 1.0, hi = -1.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const double c_ij = -dot(n[i], n[j]) / (length[i] * length[j]);
      lo = std::min(lo, c_ij);
      hi = std::max(hi, c_ij);
    }
  return {lo, hi};
}

FacetQuality3::FacetQuality3(const Vec3& a, const Vec3& b, const Vec3& c) noexcept
    : a_(a), b_(b), c_(c), ba_(b - a), ca_(c - a), cb_(c - b) {
  s_ba_ = dot(ba_, ba_);
  s_ca_ = dot(ca_, ca_);
  s_cb_ = dot(cb_, cb_);
  root_area_abc_ = root_area(ba_, ca_);
}

// shape_quality_nonflat above with the facet's terms read.
double FacetQuality3::with_apex(const Vec3& d) const noexcept {
  if (!std::isnan(root_area_abc_)) {
    const Vec3 da = d - a_, db = d - b_, dc = d - c_;
    const double s_max = std::max({s_ba_, s_ca_, dot(da, da), s_cb_, dot(db, db), dot(dc, dc)});
    const double q = quality_from_squares(s_max, root_area_abc_, ba_, ca_, da, cb_, db);
    if (!std::isnan(q)) return q;
  }
  return shape_quality_by_hypot(a_, b_, c_, d);
}

namespace {

// sqrt(n^T adj(M) n): the measure in M of the parallelogram whose normal is n (header above).
double face_measure(const Metric3& m, const Vec3& n) noexcept {
  const double a = m.m[0], b = m.m[1], c = m.m[2], d = m.m[3], e = m.m[4], f = m.m[5];
  const Metric3 adjugate{{c * f - e * e, d * e - b * f, a * f - d * d, b * e - c * d, b * d - a * e, a * c - b * b}};
  return adjugate.length(n);
}

double squared_length(const Metric2& m, const Vec2& v) noexcept {
  const double l = m.length(v);
  return l * l;
}

double squared_length(const Metric3& m, const Vec3& v) noexcept {
  const double l = m.length(v);
  return l * l;
}

double sign_factor(Sign s) noexcept { return s == Sign::Positive ? 1.0 : -1.0; }

// Q_K in m of a triangle known not to be flat.
double oriented_quality(const Vec2& a, const Vec2& b, const Vec2& c, const Metric2& m) noexcept {
  const Vec2 ba = b - a, ca = c - a;
  const std::array<double, 3> e = {m.length(ba), m.length(ca), m.length(c - b)};
  const double h_max = std::max({e[0], e[1], e[2]});
  const double twice_area = std::sqrt(m.determinant()) * std::fabs(cross(ba, ca));
  if (!(twice_area > 0.0)) return kInfinity;
  return kQualityAlpha2d * h_max * (e[0] + e[1] + e[2]) / twice_area;
}

// Q_K in m of a tetrahedron known not to be flat.
double oriented_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& m) noexcept {
  const Vec3 ba = b - a, ca = c - a, da = d - a, cb = c - b, db = d - b;
  const std::array<double, 6> e = {m.length(ba), m.length(ca), m.length(da),
                                   m.length(cb), m.length(db), m.length(d - c)};
  const double h_max = *std::max_element(e.begin(), e.end());
  const double twice_area = face_measure(m, cross(ba, ca)) + face_measure(m, cross(ba, da)) +
                            face_measure(m, cross(ca, da)) + face_measure(m, cross(cb, db));
  const double six_volume = std::sqrt(m.determinant()) * std::fabs(dot(ba, cross(ca, da)));
  if (!(six_volume > 0.0)) return kInfinity;
  return kQualityAlpha3d * h_max * twice_area / six_volume;
}

}  // namespace

double shape_quality(const Vec2& a, const Vec2& b, const Vec2& c, const Metric2& m) noexcept {
  if (orient2d(a, b, c) == Sign::Zero) return kInfinity;
  return oriented_quality(a, b, c, m);
}

double shape_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& m) noexcept {
  if (orient3d(a, b, c, d) == Sign::Zero) return kInfinity;
  return oriented_quality(a, b, c, d, m);
}

double shape_quality_nonflat(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& m) noexcept {
  return oriented_quality(a, b, c, d, m);
}

// One orientation test, and a vertex metric equal to an earlier one measured once (the
// isotropic uniform case: one measure instead of three or four); the same value as the maximum
// of the one-metric measures.
double shape_quality(const Vec2& a, const Vec2& b, const Vec2& c, const Metric2& ma, const Metric2& mb,
                     const Metric2& mc) noexcept {
  if (orient2d(a, b, c) == Sign::Zero) return kInfinity;
  double q = oriented_quality(a, b, c, ma);
  if (!(mb == ma)) q = std::max(q, oriented_quality(a, b, c, mb));
  if (!(mc == ma) && !(mc == mb)) q = std::max(q, oriented_quality(a, b, c, mc));
  return q;
}

double shape_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& ma,
                     const Metric3& mb, const Metric3& mc, const Metric3& md) noexcept {
  if (orient3d(a, b, c, d) == Sign::Zero) return kInfinity;
  return shape_quality_nonflat(a, b, c, d, ma, mb, mc, md);
}

double shape_quality_nonflat(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& ma,
                             const Metric3& mb, const Metric3& mc, const Metric3& md) noexcept {
  double q = oriented_quality(a, b, c, d, ma);
  if (!(mb == ma)) q = std::max(q, oriented_quality(a, b, c, d, mb));
  if (!(mc == ma) && !(mc == mb)) q = std::max(q, oriented_quality(a, b, c, d, mc));
  if (!(md == ma) && !(md == mb) && !(md == mc)) q = std::max(q, oriented_quality(a, b, c, d, md));
  return q;
}

// The sign comes from the exact orientation, the magnitude from the rounded measures.
double mean_ratio(const Vec2& a, const Vec2& b, const Vec2& c, const Metric2& m) noexcept {
  const Sign s = orient2d(a, b, c);
  if (s == Sign::Zero) return 0.0;
  const Vec2 ba = b - a, ca = c - a;
  const double sum = squared_length(m, ba) + squared_length(m, ca) + squared_length(m, c - b);
  if (!(sum > 0.0)) return 0.0;
  const double area = 0.5 * std::sqrt(m.determinant()) * std::fabs(cross(ba, ca));
  return sign_factor(s) * 4.0 * std::sqrt(3.0) * area / sum;
}

double mean_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& m) noexcept {
  const Sign s = orient3d(a, b, c, d);
  if (s == Sign::Zero) return 0.0;
  const Vec3 ba = b - a, ca = c - a, da = d - a;
  const double sum = squared_length(m, ba) + squared_length(m, ca) + squared_length(m, da) +
                     squared_length(m, c - b) + squared_length(m, d - b) + squared_length(m, d - c);
  if (!(sum > 0.0)) return 0.0;
  const double volume = std::sqrt(m.determinant()) * std::fabs(dot(ba, cross(ca, da))) / 6.0;
  const double r = std::cbrt(3.0 * volume);
  return sign_factor(s) * 12.0 * r * r / sum;
}

}  // namespace dtlab
