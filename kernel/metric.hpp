// Riemannian metrics (book §4.2, §9.5): symmetric positive definite tensors M that measure a
// vector v as sqrt(v^T M v). A unit mesh in M has every edge of length ~1; the metric of a size
// h is h^-2 I (isotropic), and an anisotropic one is R diag(h1^-2, h2^-2) R^T. The algorithms
// never special-case the isotropic metric: it is a Metric2 like any other.
//
// Conventions:
//  - Components are stored in Medit's SolAtVertices order for a symmetric tensor:
//    2D (m11, m12, m22), 3D (m11, m12, m22, m13, m23, m33).
//  - Interpolation works on the sizes M^-1/2 by default (Borouchaki, George, Hecht, Laug, Saltel
//    1997, part I: a metric that varies linearly in size), log-Euclidean on request (Arsigny,
//    Fillard, Pennec, Ayache 2006: exp of the weighted mean of the logarithms).
//  - Intersection is the simultaneous reduction of book §9.5: in the basis that diagonalises
//    both, keep the larger eigenvalue (smaller size) in each direction: the largest ellipse
//    (ellipsoid) contained in both unit balls.
//  - Edge length between two vertex metrics is the geometric interpolation of the two lengths,
//    l = (la - lb) / ln(la / lb) (la when la == lb), as the UGAWG benchmarks measure it (Alauzet,
//    Loseille: "A decade of progress on anisotropic mesh adaptation", 2016).
//  - Gradation follows Borouchaki, Hecht, Frey 1998 ("Mesh gradation control"): the metric at p
//    seen from q at length l_p(pq) is grown to (1 + l_p(pq) ln(beta))^-2 M_p, and M_q is
//    intersected with it; beta = h-grad >= 1 bounds the size ratio along a unit edge.
// These are measures and constructions: no combinatorial decision depends on them.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>

#include "kernel/vec.hpp"

namespace dtlab {

// The sizes a metric holds: h with h^-2 in [2^-340, 2^340], so that every eigenvalue and every
// product of up to three of them (the determinant in 3D) is a normal double, neither overflowing
// to inf nor underflowing to 0. That is h in [2^-170, 2^170], about [6.7e-52, 1.5e51].
inline constexpr double kMinMetricSize = 0x1p-170;
inline constexpr double kMaxMetricSize = 0x1p170;
inline constexpr double kMinMetricEigenvalue = 0x1p-340;  // kMaxMetricSize^-2
inline constexpr double kMaxMetricEigenvalue = 0x1p340;   // kMinMetricSize^-2
// Whether h lies in [kMinMetricSize, kMaxMetricSize] (false for NaN).
bool is_representable_size(double h) noexcept;
// Throws InputError "WHAT = h: ..." naming the range when h is not a representable size (or not
// positive): the check to make before isotropic(h), from_sizes(..., h, ...) or clip(.., h, ..).
void check_size(double h, const std::string& what);

struct Metric2 {
  std::array<double, 3> m{1.0, 0.0, 1.0};  // m11, m12, m22

  // h^-2 I: size h in every direction (h a representable size, check_size above; outside it the
  // components overflow or the determinant underflows).
  static Metric2 isotropic(double h) noexcept;
  // Size h1 along the unit direction e1, h2 along its normal.
  static Metric2 from_sizes(const Vec2& e1, double h1, double h2) noexcept;

  // sqrt(v^T M v); inline: the optimizers evaluate it millions of times (same -ffp-contract=off
  // everywhere, so the value does not depend on the caller).
  double length(const Vec2& v) const noexcept {
    const double q = m[0] * v.x * v.x + 2.0 * m[1] * v.x * v.y + m[2] * v.y * v.y;
    return std::sqrt(std::max(0.0, q));  // q >= 0 up to rounding for a positive definite m
  }
  double determinant() const noexcept { return m[0] * m[2] - m[1] * m[1]; }
  // m = lambda I exactly (isotropic): lengths in m are a scaling of Euclidean ones.
  bool is_scalar() const noexcept { return m[1] == 0.0 && m[0] == m[2]; }
  // Strictly positive definite with finite components (m11 > 0, det > 0, checked in doubles).
  bool is_positive_definite() const noexcept;

  friend bool operator==(const Metric2&, const Metric2&) = default;
};

struct Metric3 {
  std::array<double, 6> m{1.0, 0.0, 1.0, 0.0, 0.0, 1.0};  // m11, m12, m22, m13, m23, m33

  static Metric3 isotropic(double h) noexcept;
  // Sizes along the orthonormal directions e1, e2, e3 = e1 x e2.
  static Metric3 from_sizes(const Vec3& e1, const Vec3& e2, double h1, double h2, double h3) noexcept;

  double length(const Vec3& v) const noexcept {
    const double q = m[0] * v.x * v.x + m[2] * v.y * v.y + m[5] * v.z * v.z +
                     2.0 * (m[1] * v.x * v.y + m[3] * v.x * v.z + m[4] * v.y * v.z);
    return std::sqrt(std::max(0.0, q));
  }
  double determinant() const noexcept {
    const double a = m[0], b = m[1], c = m[2], d = m[3], e = m[4], f = m[5];
    // | a b d |
    // | b c e |
    // | d e f |
    return a * (c * f - e * e) - b * (b * f - e * d) + d * (b * e - c * d);
  }
  // m = lambda I exactly (isotropic): lengths in m are a scaling of Euclidean ones.
  bool is_scalar() const noexcept {
    return m[1] == 0.0 && m[3] == 0.0 && m[4] == 0.0 && m[0] == m[2] && m[0] == m[5];
  }
  bool is_positive_definite() const noexcept;

  friend bool operator==(const Metric3&, const Metric3&) = default;
};

// Eigen-decomposition: eigenvalues ascending, unit eigenvectors (columns) in the same order.
struct MetricEigen2 {
  std::array<double, 2> values{};
  std::array<Vec2, 2> vectors{};
};
struct MetricEigen3 {
  std::array<double, 3> values{};
  std::array<Vec3, 3> vectors{};
};
MetricEigen2 eigen(const Metric2& m) noexcept;
MetricEigen3 eigen(const Metric3& m) noexcept;
Metric2 from_eigen(const MetricEigen2& e) noexcept;
Metric3 from_eigen(const MetricEigen3& e) noexcept;

// The sizes h_i = lambda_i^-1/2, largest first (so sizes[0] / sizes[1] is the stretching).
std::array<double, 2> sizes(const Metric2& m) noexcept;
std::array<double, 3> sizes(const Metric3& m) noexcept;

// M^p for any real p (M^-1/2: the size tensor; M^1/2: the map to the unit space).
Metric2 power(const Metric2& m, double p) noexcept;
Metric3 power(const Metric3& m, double p) noexcept;
// M^1/2 v: the image of v in the space where M is the identity.
Vec2 transform(const Metric2& sqrt_m, const Vec2& v) noexcept;
Vec3 transform(const Metric3& sqrt_m, const Vec3& v) noexcept;

enum class MetricInterpolation : std::uint8_t { Sizes, LogEuclidean };

// Along an edge: t = 0 gives a, t = 1 gives b.
Metric2 interpolate(const Metric2& a, const Metric2& b, double t,
                    MetricInterpolation mode = MetricInterpolation::Sizes) noexcept;
Metric3 interpolate(const Metric3& a, const Metric3& b, double t,
                    MetricInterpolation mode = MetricInterpolation::Sizes) noexcept;
// In a simplex, with barycentric weights (non-negative, summing to 1): one per metric.
Metric2 interpolate(std::span<const Metric2> metrics, std::span<const double> weights,
                    MetricInterpolation mode = MetricInterpolation::Sizes) noexcept;
Metric3 interpolate(std::span<const Metric3> metrics, std::span<const double> weights,
                    MetricInterpolation mode = MetricInterpolation::Sizes) noexcept;

// Simultaneous reduction (book §9.5): the largest ellipse inside both unit balls.
Metric2 intersect(const Metric2& a, const Metric2& b) noexcept;
Metric3 intersect(const Metric3& a, const Metric3& b) noexcept;

// Eigenvalues clipped to [1/h_max^2, 1/h_min^2] (0 < h_min <= h_max), directions kept.
Metric2 clip(const Metric2& m, double h_min, double h_max) noexcept;
Metric3 clip(const Metric3& m, double h_min, double h_max) noexcept;

// Length of the edge pq between the vertex metrics mp and mq (geometric interpolation above).
double edge_length(const Vec2& p, const Metric2& mp, const Vec2& q, const Metric2& mq) noexcept;
double edge_length(const Vec3& p, const Metric3& mp, const Vec3& q, const Metric3& mq) noexcept;

// The metric m at p, grown for a point at metric length l from p with h-grad beta:
// (1 + l ln beta)^-2 m.
Metric2 grow(const Metric2& m, double length, double beta) noexcept;
Metric3 grow(const Metric3& m, double length, double beta) noexcept;

// Gradation over a mesh's edges: repeats M_q := M_q ∩ grow(M_p, l_p(pq), beta) (both ways) over
// every edge until no metric changes by more than a relative 1e-3, or `max_passes` passes.
// Returns the number of passes made. Edges are pairs of indices into points / metrics.
std::uint32_t apply_gradation(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 2>> edges,
                              std::span<Metric2> metrics, double beta, std::uint32_t max_passes = 100);
std::uint32_t apply_gradation(std::span<const Vec3> points, std::span<const std::array<std::uint32_t, 2>> edges,
                              std::span<Metric3> metrics, double beta, std::uint32_t max_passes = 100);

}  // namespace dtlab
