// Riemannian metrics of book §4.2 and §9.5: eigen-decomposition, powers, interpolation (on sizes,
// Borouchaki et al. 1997, or log-Euclidean, Arsigny et al. 2006), intersection by simultaneous
// reduction, clipping, edge lengths and gradation (Borouchaki, Hecht, Frey 1998).
// Every construction goes through one cyclic Jacobi eigensolver (2x2: one rotation): deterministic,
// and as accurate on the small eigenvalues of a stretched tensor as its rounded components allow
// (ulps relative for an axis-aligned one; ~eps * lambda_max absolute for a rotated one).
#include "kernel/metric.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "kernel/error.hpp"

namespace dtlab {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Cyclic Jacobi converges quadratically: a 3x3 needs about 4 sweeps; this bound only stops a
// pathological input (NaN components) from looping.
constexpr int kMaxSweeps = 32;
// apply_gradation stops once no metric moves by more than this, relative (header).
constexpr double kGradationTolerance = 1e-3;

template <int N>
using Mat = std::array<std::array<double, N>, N>;

template <int N>
struct Eig {
  std::array<double, N> values{};
  Mat<N> vectors{};  // columns: vectors[r][k] is component r of eigenvector k
};

Mat<2> full(const Metric2& m) { return {{{m.m[0], m.m[1]}, {m.m[1], m.m[2]}}}; }
Mat<3> full(const Metric3& m) {
  return {{{m.m[0], m.m[1], m.m[3]}, {m.m[1], m.m[2], m.m[4]}, {m.m[3], m.m[4], m.m[5]}}};
}

// Packs a matrix that is symmetric up to rounding, averaging the two off-diagonal halves.
Metric2 pack(const Mat<2>& a) { return Metric2{{a[0][0], 0.5 * (a[0][1] + a[1][0]), a[1][1]}}; }
Metric3 pack(const Mat<3>& a) {
  return Metric3{{a[0][0], 0.5 * (a[0][1] + a[1][0]), a[1][1], 0.5 * (a[0][2] + a[2][0]), 0.5 * (a[1][2] + a[2][1]),
                  a[2][2]}};
}

template <int N>
Mat<N> multiply(const Mat<N>& a, const Mat<N>& b) {
  Mat<N> c{};
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      double s = 0.0;
      for (int k = 0; k < N; ++k) s += a[i][k] * b[k][j];
      c[i][j] = s;
    }
  }
  return c;
}

// Cyclic Jacobi on a symmetric matrix (definite or not: logarithms are indefinite). Each rotation
// zeroes one off-diagonal entry, with the rotation angle taken in its stable form (the smaller
// root of t^2 + 2 theta t - 1 = 0); a pair is skipped once its entry is below eps times the
// geometric mean of its diagonal, which perturbs each eigenvalue by under an ulp relative.
// Eigenvalues come back ascending, ties in their diagonal order.
template <int N>
Eig<N> jacobi(Mat<N> a) {
  Mat<N> v{};
  for (int i = 0; i < N; ++i) v[i][i] = 1.0;
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    bool rotated = false;
    for (int p = 0; p < N - 1; ++p) {
      for (int q = p + 1; q < N; ++q) {
        const double apq = a[p][q];
        if (!(std::fabs(apq) > kEps * std::sqrt(std::fabs(a[p][p]) * std::fabs(a[q][q])))) continue;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * apq);
        const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::fabs(theta) + std::hypot(theta, 1.0));
        const double c = 1.0 / std::hypot(t, 1.0);
        const double s = t * c;
        for (int r = 0; r < N; ++r) {
          if (r == p || r == q) continue;
          const double arp = a[r][p], arq = a[r][q];
          a[r][p] = a[p][r] = c * arp - s * arq;
          a[r][q] = a[q][r] = s * arp + c * arq;
        }
        a[p][p] -= t * apq;
        a[q][q] += t * apq;
        a[p][q] = a[q][p] = 0.0;
        for (int r = 0; r < N; ++r) {
          const double vrp = v[r][p], vrq = v[r][q];
          v[r][p] = c * vrp - s * vrq;
          v[r][q] = s * vrp + c * vrq;
        }
        rotated = true;
      }
    }
    if (!rotated) break;
  }
  // Insertion sort of the pairs: stable, so equal eigenvalues keep their order.
  std::array<int, N> order{};
  for (int i = 0; i < N; ++i) order[i] = i;
  for (int i = 1; i < N; ++i) {
    for (int j = i; j > 0 && a[order[j]][order[j]] < a[order[j - 1]][order[j - 1]]; --j) {
      std::swap(order[j], order[j - 1]);
    }
  }
  Eig<N> e;
  for (int k = 0; k < N; ++k) {
    e.values[k] = a[order[k]][order[k]];
    for (int r = 0; r < N; ++r) e.vectors[r][k] = v[r][order[k]];
  }
  return e;
}

// V diag(f(lambda)) V^T.
template <int N, class F>
Mat<N> compose(const Eig<N>& e, F f) {
  std::array<double, N> d{};
  for (int k = 0; k < N; ++k) d[k] = f(e.values[k]);
  Mat<N> m{};
  for (int i = 0; i < N; ++i) {
    for (int j = i; j < N; ++j) {
      double s = 0.0;
      for (int k = 0; k < N; ++k) s += e.vectors[i][k] * d[k] * e.vectors[j][k];
      m[i][j] = m[j][i] = s;
    }
  }
  return m;
}

template <int N, class F>
Mat<N> apply_function(const Mat<N>& a, F f) {
  return compose<N>(jacobi<N>(a), f);
}

template <int N>
Mat<N> combine(const Mat<N>& x, double wx, const Mat<N>& y, double wy) {
  Mat<N> z{};
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) z[i][j] = wx * x[i][j] + wy * y[i][j];
  }
  return z;
}

// The two interpolation modes as a map to a linear space (sizes M^-1/2 or log M) and back.
template <int N>
Mat<N> to_linear(const Mat<N>& m, MetricInterpolation mode) {
  if (mode == MetricInterpolation::LogEuclidean) return apply_function<N>(m, [](double l) { return std::log(l); });
  return apply_function<N>(m, [](double l) { return 1.0 / std::sqrt(l); });
}

template <int N>
Mat<N> from_linear(const Mat<N>& s, MetricInterpolation mode) {
  if (mode == MetricInterpolation::LogEuclidean) return apply_function<N>(s, [](double l) { return std::exp(l); });
  return apply_function<N>(s, [](double h) { return 1.0 / (h * h); });
}

template <class M, int N>
M interpolate_two(const M& a, const M& b, double t, MetricInterpolation mode) {
  // The endpoints and a constant field come back bit for bit, not through two decompositions.
  if (t == 0.0 || a == b) return a;
  if (t == 1.0) return b;
  return pack(from_linear<N>(combine<N>(to_linear<N>(full(a), mode), 1.0 - t, to_linear<N>(full(b), mode), t), mode));
}

template <class M, int N>
M interpolate_many(std::span<const M> metrics, std::span<const double> weights, MetricInterpolation mode) {
  const std::size_t n = std::min(metrics.size(), weights.size());
  if (n == 0) return M{};
  if (std::all_of(metrics.begin(), metrics.begin() + static_cast<std::ptrdiff_t>(n),
                  [&](const M& m) { return m == metrics[0]; })) {
    return metrics[0];
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (weights[i] == 1.0) return metrics[i];  // at a vertex of the simplex
  }
  Mat<N> sum{};
  for (std::size_t i = 0; i < n; ++i) {
    if (weights[i] == 0.0) continue;
    sum = combine<N>(sum, 1.0, to_linear<N>(full(metrics[i]), mode), weights[i]);
  }
  return pack(from_linear<N>(sum, mode));
}

// Simultaneous reduction (book §9.5), in the stable form: with A = the better-conditioned of
// the two, C = A^-1/2 B A^-1/2 is symmetric, C = Q diag(mu) Q^T, and P = A^-1/2 Q reduces both
// (P^T A P = I, P^T B P = diag(mu)); keeping the larger eigenvalue in each direction gives
// A^1/2 Q diag(max(1, mu)) Q^T A^1/2. A proportional pair is no special case: C = mu I and any Q
// serves. Choosing A by conditioning, ties by components, makes the result symmetric in a, b
// bit for bit; when one metric dominates in every direction it is returned as it is.
template <class M, int N>
M intersect_impl(const M& a, const M& b) {
  if (a == b) return a;
  const Eig<N> ea = jacobi<N>(full(a));
  const Eig<N> eb = jacobi<N>(full(b));
  const double ka = ea.values[N - 1] / ea.values[0];
  const double kb = eb.values[N - 1] / eb.values[0];
  const bool a_first = ka < kb || (ka == kb && a.m < b.m);
  const M& base = a_first ? a : b;
  const M& other = a_first ? b : a;
  const Eig<N>& e = a_first ? ea : eb;
  const Mat<N> inv_sqrt = compose<N>(e, [](double l) { return 1.0 / std::sqrt(l); });
  const Mat<N> root = compose<N>(e, [](double l) { return std::sqrt(l); });
  Mat<N> c = multiply<N>(multiply<N>(inv_sqrt, full(other)), inv_sqrt);
  for (int i = 0; i < N; ++i) {
    for (int j = i + 1; j < N; ++j) c[i][j] = c[j][i] = 0.5 * (c[i][j] + c[j][i]);
  }
  const Eig<N> ec = jacobi<N>(c);
  if (ec.values[N - 1] <= 1.0) return base;
  if (ec.values[0] >= 1.0) return other;
  const Mat<N> kept = compose<N>(ec, [](double mu) { return std::max(1.0, mu); });
  return pack(multiply<N>(multiply<N>(root, kept), root));
}

template <class M, int N>
M clip_impl(const M& m, double h_min, double h_max) {
  const double lo = 1.0 / (h_max * h_max);
  const double hi = 1.0 / (h_min * h_min);
  const Eig<N> e = jacobi<N>(full(m));
  if (e.values[0] >= lo && e.values[N - 1] <= hi) return m;
  return pack(compose<N>(e, [&](double l) { return std::clamp(l, lo, hi); }));
}

template <class M>
M scaled(const M& m, double s) {
  M r = m;
  for (double& c : r.m) c *= s;
  return r;
}

// Frobenius norm of a packed tensor, the off-diagonal entries counted twice.
template <class M>
double frobenius(const M& m) {
  double s = 0.0;
  for (std::size_t k = 0; k < m.m.size(); ++k) {
    const bool diagonal = m.m.size() == 3 ? k != 1 : (k == 0 || k == 2 || k == 5);
    s += (diagonal ? 1.0 : 2.0) * m.m[k] * m.m[k];
  }
  return std::sqrt(s);
}

template <class M>
double relative_change(const M& before, const M& after) {
  M d = after;
  for (std::size_t k = 0; k < d.m.size(); ++k) d.m[k] -= before.m[k];
  return frobenius(d) / frobenius(before);
}

template <class P, class M>
std::uint32_t gradation_impl(std::span<const P> points, std::span<const std::array<std::uint32_t, 2>> edges,
                             std::span<M> metrics, double beta, std::uint32_t max_passes) {
  if (!(beta >= 1.0) || !std::isfinite(beta)) {
    throw InputError("gradation: h-grad " + std::to_string(beta) + " is not a finite number >= 1");
  }
  if (points.size() != metrics.size()) {
    throw InputError("gradation: " + std::to_string(metrics.size()) + " metrics for " +
                     std::to_string(points.size()) + " points");
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    for (std::uint32_t v : edges[e]) {
      if (v >= points.size()) {
        throw InputError("gradation: edge " + std::to_string(e) + " has vertex " + std::to_string(v) +
                             " out of range (" + std::to_string(points.size()) + " points)",
                         {e});
      }
    }
  }
  // One side of an edge: M_to := M_to ∩ grow(M_from, l_from(pq), beta); true if it moved.
  auto relax = [&](std::uint32_t from, std::uint32_t to) {
    const M grown = grow(metrics[from], metrics[from].length(points[to] - points[from]), beta);
    const M next = intersect(metrics[to], grown);
    const bool moved = relative_change(metrics[to], next) > kGradationTolerance;
    metrics[to] = next;
    return moved;
  };
  std::uint32_t passes = 0;
  while (passes < max_passes) {
    ++passes;
    bool moved = false;
    for (const auto& e : edges) {
      if (e[0] == e[1]) continue;
      moved = relax(e[0], e[1]) || moved;
      moved = relax(e[1], e[0]) || moved;
    }
    if (!moved) break;
  }
  return passes;
}

// (la - lb) / ln(la / lb), with the logarithm as log1p(d / lb): near la == lb the difference d is
// exact (Sterbenz) and the same d on both sides makes the quotient smooth, where ln(la / lb)
// would carry the ratio's rounding divided by d.
double edge_length_from(double la, double lb) {
  const double big = std::max(la, lb);
  const double d = la - lb;
  if (std::fabs(d) <= 1e-12 * big) return la;
  return d / std::log1p(d / lb);
}

Vec2 column2(const Mat<2>& v, int k) { return {v[0][k], v[1][k]}; }
Vec3 column3(const Mat<3>& v, int k) { return {v[0][k], v[1][k], v[2][k]}; }

}  // namespace

// --- Sizes -------------------------------------------------------------------------------------

bool is_representable_size(double h) noexcept { return h >= kMinMetricSize && h <= kMaxMetricSize; }

void check_size(double h, const std::string& what) {
  if (is_representable_size(h)) return;
  char text[160];
  std::snprintf(text, sizeof text, " = %.6g: %s; a size must lie in [%.6g, %.6g] (h^-2 and the metric's determinant normal doubles)",
                h, !(h > 0.0) ? "not a positive size" : "out of the representable range", kMinMetricSize, kMaxMetricSize);
  throw InputError(what + text);
}

// --- Metric2 -----------------------------------------------------------------------------------

Metric2 Metric2::isotropic(double h) noexcept {
  const double l = 1.0 / (h * h);
  return Metric2{{l, 0.0, l}};
}

Metric2 Metric2::from_sizes(const Vec2& e1, double h1, double h2) noexcept {
  const Vec2 e2{-e1.y, e1.x};
  const double l1 = 1.0 / (h1 * h1), l2 = 1.0 / (h2 * h2);
  return Metric2{{l1 * e1.x * e1.x + l2 * e2.x * e2.x, l1 * e1.x * e1.y + l2 * e2.x * e2.y,
                  l1 * e1.y * e1.y + l2 * e2.y * e2.y}};
}

bool Metric2::is_positive_definite() const noexcept {
  for (double c : m) {
    if (!std::isfinite(c)) return false;
  }
  return m[0] > 0.0 && determinant() > 0.0;
}

// --- Metric3 -----------------------------------------------------------------------------------

Metric3 Metric3::isotropic(double h) noexcept {
  const double l = 1.0 / (h * h);
  return Metric3{{l, 0.0, l, 0.0, 0.0, l}};
}

Metric3 Metric3::from_sizes(const Vec3& e1, const Vec3& e2, double h1, double h2, double h3) noexcept {
  const Vec3 e3 = cross(e1, e2);
  MetricEigen3 e;
  e.values = {1.0 / (h1 * h1), 1.0 / (h2 * h2), 1.0 / (h3 * h3)};
  e.vectors = {e1, e2, e3};
  return from_eigen(e);
}

bool Metric3::is_positive_definite() const noexcept {
  for (double c : m) {
    if (!std::isfinite(c)) return false;
  }
  // Sylvester's criterion: the leading principal minors are positive.
  return m[0] > 0.0 && m[0] * m[2] - m[1] * m[1] > 0.0 && determinant() > 0.0;
}

// --- Decomposition -----------------------------------------------------------------------------

MetricEigen2 eigen(const Metric2& m) noexcept {
  const Eig<2> e = jacobi<2>(full(m));
  MetricEigen2 r;
  r.values = e.values;
  for (int k = 0; k < 2; ++k) r.vectors[static_cast<std::size_t>(k)] = column2(e.vectors, k);
  return r;
}

MetricEigen3 eigen(const Metric3& m) noexcept {
  const Eig<3> e = jacobi<3>(full(m));
  MetricEigen3 r;
  r.values = e.values;
  for (int k = 0; k < 3; ++k) r.vectors[static_cast<std::size_t>(k)] = column3(e.vectors, k);
  return r;
}

Metric2 from_eigen(const MetricEigen2& e) noexcept {
  Eig<2> d;
  d.values = e.values;
  for (int k = 0; k < 2; ++k) {
    d.vectors[0][k] = e.vectors[static_cast<std::size_t>(k)].x;
    d.vectors[1][k] = e.vectors[static_cast<std::size_t>(k)].y;
  }
  return pack(compose<2>(d, [](double l) { return l; }));
}

Metric3 from_eigen(const MetricEigen3& e) noexcept {
  Eig<3> d;
  d.values = e.values;
  for (int k = 0; k < 3; ++k) {
    d.vectors[0][k] = e.vectors[static_cast<std::size_t>(k)].x;
    d.vectors[1][k] = e.vectors[static_cast<std::size_t>(k)].y;
    d.vectors[2][k] = e.vectors[static_cast<std::size_t>(k)].z;
  }
  return pack(compose<3>(d, [](double l) { return l; }));
}

std::array<double, 2> sizes(const Metric2& m) noexcept {
  const Eig<2> e = jacobi<2>(full(m));
  return {1.0 / std::sqrt(e.values[0]), 1.0 / std::sqrt(e.values[1])};
}

std::array<double, 3> sizes(const Metric3& m) noexcept {
  const Eig<3> e = jacobi<3>(full(m));
  return {1.0 / std::sqrt(e.values[0]), 1.0 / std::sqrt(e.values[1]), 1.0 / std::sqrt(e.values[2])};
}

Metric2 power(const Metric2& m, double p) noexcept {
  if (p == 1.0) return m;
  return pack(apply_function<2>(full(m), [p](double l) { return std::pow(l, p); }));
}

Metric3 power(const Metric3& m, double p) noexcept {
  if (p == 1.0) return m;
  return pack(apply_function<3>(full(m), [p](double l) { return std::pow(l, p); }));
}

Vec2 transform(const Metric2& s, const Vec2& v) noexcept {
  return {s.m[0] * v.x + s.m[1] * v.y, s.m[1] * v.x + s.m[2] * v.y};
}

Vec3 transform(const Metric3& s, const Vec3& v) noexcept {
  return {s.m[0] * v.x + s.m[1] * v.y + s.m[3] * v.z, s.m[1] * v.x + s.m[2] * v.y + s.m[4] * v.z,
          s.m[3] * v.x + s.m[4] * v.y + s.m[5] * v.z};
}

// --- Interpolation, intersection, clipping -----------------------------------------------------

Metric2 interpolate(const Metric2& a, const Metric2& b, double t, MetricInterpolation mode) noexcept {
  return interpolate_two<Metric2, 2>(a, b, t, mode);
}

Metric3 interpolate(const Metric3& a, const Metric3& b, double t, MetricInterpolation mode) noexcept {
  return interpolate_two<Metric3, 3>(a, b, t, mode);
}

Metric2 interpolate(std::span<const Metric2> metrics, std::span<const double> weights,
                    MetricInterpolation mode) noexcept {
  return interpolate_many<Metric2, 2>(metrics, weights, mode);
}

Metric3 interpolate(std::span<const Metric3> metrics, std::span<const double> weights,
                    MetricInterpolation mode) noexcept {
  return interpolate_many<Metric3, 3>(metrics, weights, mode);
}

Metric2 intersect(const Metric2& a, const Metric2& b) noexcept { return intersect_impl<Metric2, 2>(a, b); }
Metric3 intersect(const Metric3& a, const Metric3& b) noexcept { return intersect_impl<Metric3, 3>(a, b); }

Metric2 clip(const Metric2& m, double h_min, double h_max) noexcept { return clip_impl<Metric2, 2>(m, h_min, h_max); }
Metric3 clip(const Metric3& m, double h_min, double h_max) noexcept { return clip_impl<Metric3, 3>(m, h_min, h_max); }

// --- Lengths and gradation ---------------------------------------------------------------------

double edge_length(const Vec2& p, const Metric2& mp, const Vec2& q, const Metric2& mq) noexcept {
  const Vec2 v = q - p;
  return edge_length_from(mp.length(v), mq.length(v));
}

double edge_length(const Vec3& p, const Metric3& mp, const Vec3& q, const Metric3& mq) noexcept {
  const Vec3 v = q - p;
  return edge_length_from(mp.length(v), mq.length(v));
}

Metric2 grow(const Metric2& m, double length, double beta) noexcept {
  const double f = 1.0 + length * std::log(beta);
  return scaled(m, 1.0 / (f * f));
}

Metric3 grow(const Metric3& m, double length, double beta) noexcept {
  const double f = 1.0 + length * std::log(beta);
  return scaled(m, 1.0 / (f * f));
}

std::uint32_t apply_gradation(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 2>> edges,
                              std::span<Metric2> metrics, double beta, std::uint32_t max_passes) {
  return gradation_impl<Vec2, Metric2>(points, edges, metrics, beta, max_passes);
}

std::uint32_t apply_gradation(std::span<const Vec3> points, std::span<const std::array<std::uint32_t, 2>> edges,
                              std::span<Metric3> metrics, double beta, std::uint32_t max_passes) {
  return gradation_impl<Vec3, Metric3>(points, edges, metrics, beta, max_passes);
}

}  // namespace dtlab
