// Metrics from solutions (metric_from_solution.hpp), one template for 2D and 3D.
#include "algorithms/adapt/metric_from_solution.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "kernel/error.hpp"
#include "mesh/element_edges.hpp"

namespace dtlab {

namespace {

template <int D>
struct Traits;
template <>
struct Traits<2> {
  using Point = Vec2;
  using Metric = Metric2;
  using Eigen = MetricEigen2;
  static constexpr double kLinfConstant = 2.0 / 9.0;
};
template <>
struct Traits<3> {
  using Point = Vec3;
  using Metric = Metric3;
  using Eigen = MetricEigen3;
  static constexpr double kLinfConstant = 9.0 / 32.0;
};

template <int D>
double element_measure(std::span<const typename Traits<D>::Point> points, const std::array<std::uint32_t, D + 1>& e) {
  if constexpr (D == 2) {
    return 0.5 * std::fabs(cross(points[e[1]] - points[e[0]], points[e[2]] - points[e[0]]));
  } else {
    return std::fabs(dot(cross(points[e[1]] - points[e[0]], points[e[2]] - points[e[0]]), points[e[3]] - points[e[0]])) /
           6.0;
  }
}

// ∫ q, P1: each element's measure times the mean of q at its vertices.
template <int D>
double integrate(std::span<const typename Traits<D>::Point> points,
                 std::span<const std::array<std::uint32_t, D + 1>> elements, const std::vector<double>& q) {
  double sum = 0.0;
  for (const auto& e : elements) {
    double mean = 0.0;
    for (const std::uint32_t v : e) mean += q[v];
    sum += element_measure<D>(points, e) * mean / (D + 1);
  }
  return sum;
}

template <int D>
double diagonal(std::span<const typename Traits<D>::Point> points) {
  typename Traits<D>::Point lo = points.empty() ? typename Traits<D>::Point{} : points[0], hi = lo;
  for (const auto& p : points) {
    lo.x = std::min(lo.x, p.x), hi.x = std::max(hi.x, p.x);
    lo.y = std::min(lo.y, p.y), hi.y = std::max(hi.y, p.y);
    if constexpr (D == 3) lo.z = std::min(lo.z, p.z), hi.z = std::max(hi.z, p.z);
  }
  return norm(hi - lo);
}

// Constants of the normalisation (documented in metric_from_solution.hpp).
constexpr double kDefaultMinSize = 1e-8;        // default h_min, relative to the diagonal
constexpr double kSmallestSize = 1e-9;          // the smallest h_min, relative to the diagonal
constexpr double kEigenvalueFloor = 1e-12;      // of the largest |H| eigenvalue
constexpr double kComplexityTolerance = 1e-6;   // relative, delivered (clipped) vs asked
constexpr double kSolveTolerance = 1e-9;        // relative, where the solve for the scale stops
constexpr int kSolveIterations = 100;           // bisection steps on log s (the bracket: < 2^11)
constexpr double kRoundOffHessian = 1e-12;      // |lambda| h^2 / max |u| at or below: round-off

// A double in six significant digits, for messages.
std::string format_double(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

void check_positive(const std::optional<double>& x, const char* name) {
  if (x && !(*x > 0.0 && std::isfinite(*x)))
    throw InputError(std::string("metric from solution: ") + name + " = " + format_double(*x) +
                     ": give a positive finite value");
}

// The shortest edge at each used vertex: the length over which round-off in the values is
// magnified into the recovered Hessian (noise ~ eps max|u| / h^2).
template <int D>
std::vector<double> shortest_edges(std::span<const typename Traits<D>::Point> points,
                                   std::span<const std::array<std::uint32_t, D + 1>> elements) {
  std::vector<double> shortest(points.size(), std::numeric_limits<double>::infinity());
  for (const auto& e : elements)
    for (int i = 0; i <= D; ++i)
      for (int j = i + 1; j <= D; ++j) {
        const double l = norm(points[e[j]] - points[e[i]]);
        shortest[e[i]] = std::min(shortest[e[i]], l);
        shortest[e[j]] = std::min(shortest[e[j]], l);
      }
  return shortest;
}

std::string field_name(const SolutionMetricOptions& options, std::size_t f) {
  std::string name = "field " + std::to_string(f + 1);
  if (f < options.field_names.size()) name += " (" + options.field_names[f] + ")";
  return name;
}

// The metric s M clipped to [h_min, h_max], M given by its eigen-decomposition: each eigenvalue
// s lambda clamped to [h_max^-2, h_min^-2] (an overflow of s lambda to inf clamps to h_min^-2).
template <int D>
typename Traits<D>::Metric clipped(typename Traits<D>::Eigen e, double s, double h_min, double h_max) {
  for (double& l : e.values) l = std::clamp(s * l, 1.0 / (h_max * h_max), 1.0 / (h_min * h_min));
  return from_eigen(e);
}

// The global scale s of the normalised metric M (the fields' closed forms, intersected) for which
// clip(s M) has the complexity asked (Loseille and Alauzet 2011, part II: the constant is fixed
// for the metric actually delivered, after the size bounds). C(s) = integral of sqrt(det clip(s M))
// is continuous and non-decreasing in s: each clamped eigenvalue clamp(s lambda) is, and so are
// their product, its root and the P1 sum with positive weights, in doubles too, as C is evaluated
// here from the eigenvalues of M. So C(s) = N is solved by bisection on log s, from the closed
// form s = 1 (kept as is where it holds: no clipping, or none that moves C) towards the bound that
// brackets N: s_lo, where every eigenvalue clamps to h_max^-2 (C = the all-h_max complexity), or
// s_hi, where every one clamps to h_min^-2. N outside [C(s_lo), C(s_hi)] is refused by name.
template <int D>
double clipped_scale(std::span<const typename Traits<D>::Point> points,
                     std::span<const std::array<std::uint32_t, D + 1>> elements, const std::vector<char>& used,
                     std::span<const typename Traits<D>::Metric> metrics, double asked, double h_min, double h_max) {
  const std::size_t n = points.size();
  std::vector<typename Traits<D>::Eigen> e(n);
  double smallest = std::numeric_limits<double>::infinity(), largest = 0.0;
  for (std::size_t v = 0; v < n; ++v) {
    if (!used[v]) continue;
    e[v] = eigen(metrics[v]);
    for (const double l : e[v].values) smallest = std::min(smallest, l), largest = std::max(largest, l);
  }
  const double lo = 1.0 / (h_max * h_max), hi = 1.0 / (h_min * h_min);
  std::vector<double> q(n, 0.0);
  auto complexity = [&](double s) {
    for (std::size_t v = 0; v < n; ++v) {
      if (!used[v]) continue;
      double det = 1.0;
      for (const double l : e[v].values) det *= std::clamp(s * l, lo, hi);
      q[v] = std::sqrt(det);
    }
    return integrate<D>(points, elements, q);
  };
  auto close = [&](double c) { return std::fabs(c - asked) <= kSolveTolerance * asked; };
  const double c1 = complexity(1.0);
  if (close(c1)) return 1.0;
  // The bracket's far end; its bounds are finite doubles as the eigenvalues lie in
  // [kMinMetricEigenvalue, kMaxMetricEigenvalue] and the sizes in the kernel's range.
  const double s_lo = lo / largest, s_hi = hi / smallest;
  const double c_lo = complexity(s_lo), c_hi = complexity(s_hi);
  const std::string range = "the sizes [h_min, h_max] = [" + format_double(h_min) + ", " + format_double(h_max) +
                            "] reach complexities " + format_double(c_lo) + " (every size h_max) to " +
                            format_double(c_hi) + " (every size h_min)";
  if (asked < c_lo && !close(c_lo))
    throw InputError("metric from solution: complexity " + format_double(asked) +
                     " is below the complexity of the all-h_max metric: " + range + "; ask for more or a larger h_max");
  if (asked > c_hi && !close(c_hi))
    throw InputError("metric from solution: complexity " + format_double(asked) +
                     " is above the complexity of the all-h_min metric: " + range + "; ask for less or a smaller h_min");
  if (close(c_lo)) return s_lo;
  if (close(c_hi)) return s_hi;
  // C(a) < N < C(b): halve [log a, log b] (its width is under 2^11, so 100 steps reach the
  // doubles' resolution of s long before; the stop is at kSolveTolerance of N).
  const bool up = c1 < asked;
  double a = up ? 1.0 : s_lo, b = up ? s_hi : 1.0, c_a = up ? c1 : c_lo, c_b = up ? c_hi : c1;
  for (int i = 0; i < kSolveIterations; ++i) {
    const double s = std::sqrt(a) * std::sqrt(b);  // the geometric mean, without overflow
    if (!(s > a && s < b)) break;                  // adjacent doubles: nothing left to halve
    const double c = complexity(s);
    if (close(c)) return s;
    if (c < asked) {
      a = s, c_a = c;
    } else {
      b = s, c_b = c;
    }
  }
  return asked - c_a <= c_b - asked ? a : b;
}

template <int D>
std::vector<typename Traits<D>::Metric> compute(std::span<const typename Traits<D>::Point> points,
                                                std::span<const std::array<std::uint32_t, D + 1>> elements,
                                                std::span<const std::vector<double>> fields,
                                                const SolutionMetricOptions& options, SolutionMetricStats* stats) {
  using Metric = typename Traits<D>::Metric;
  if (fields.empty()) throw InputError("metric from solution: give at least one field");
  if (options.complexity.has_value() == options.error.has_value())
    throw InputError("metric from solution: give either a target complexity or a target error, not both nor neither");
  check_positive(options.complexity, "complexity");
  check_positive(options.error, "error");
  check_positive(options.relative_cutoff, "relative cutoff");
  check_positive(options.h_min, "h_min");
  check_positive(options.h_max, "h_max");
  if (!(options.p >= 1.0)) throw InputError("metric from solution: p = " + std::to_string(options.p) + ": give p >= 1");
  const bool linf = std::isinf(options.p);
  if (options.error && !linf) throw InputError("metric from solution: a target error goes with the L-infinity norm only; give a complexity for Lp");
  if (options.gradation && !(*options.gradation >= 1.0 && std::isfinite(*options.gradation)))
    throw InputError("metric from solution: gradation = " + std::to_string(*options.gradation) + ": give beta >= 1");
  if (elements.empty()) throw InputError("metric from solution: the mesh has no element");
  const double diag = diagonal<D>(points);
  const double h_max = options.h_max.value_or(diag), h_min = options.h_min.value_or(kDefaultMinSize * diag);
  check_size(h_min, options.h_min ? "metric from solution: h_min" : "metric from solution: the default h_min (1e-8 of the diagonal)");
  check_size(h_max, options.h_max ? "metric from solution: h_max" : "metric from solution: the default h_max (the diagonal)");
  if (!(h_min >= kSmallestSize * diag))
    throw InputError("metric from solution: h_min = " + format_double(h_min) + " is below " + format_double(kSmallestSize) +
                     " of the mesh's diagonal " + format_double(diag) +
                     ": sizes that small are under the resolution of its coordinates");
  if (!(h_min <= h_max))
    throw InputError("metric from solution: h_min = " + format_double(h_min) + " exceeds h_max = " + format_double(h_max));
  const std::size_t n = points.size();
  std::vector<char> used(n, 0);
  for (const auto& e : elements)
    for (const std::uint32_t v : e)
      if (v < n) used[v] = 1;
  const std::vector<double> shortest = shortest_edges<D>(points, elements);

  std::vector<Metric> result;
  double complexity_before = 0.0;
  for (std::size_t f = 0; f < fields.size(); ++f) {
    const std::string name = field_name(options, f);
    // The field scaled by a power of two (exact) to max |u| in [0.5, 1]: the metric normalised to
    // a complexity does not depend on a factor on u (|H| scales by it, D_N det^(-1/(2p+d)) by its
    // inverse), so this loses nothing and keeps 1e300 x^2 from overflowing.
    std::vector<double> u = fields[f];
    if (u.size() == n)
      for (std::size_t v = 0; v < n; ++v)
        if (!std::isfinite(u[v]))
          throw InputError("metric from solution: " + name + ": the value at vertex " + std::to_string(v + 1) +
                               " is not finite",
                           {v});
    double u_max = 0.0;
    for (std::size_t v = 0; v < std::min(n, u.size()); ++v)
      if (used[v]) u_max = std::max(u_max, std::fabs(u[v]));
    int exponent2 = 0;
    if (u_max > 0.0) std::frexp(u_max, &exponent2);
    for (double& x : u) x = std::ldexp(x, -exponent2);
    const double u_scale = std::ldexp(1.0, exponent2);  // u = u_scale * (the scaled field)
    const double u_max_scaled = std::ldexp(u_max, -exponent2);
    const auto hessian = recover_hessian(points, elements, std::span<const double>(u), options.recovery);
    // |H| per vertex. An eigenvalue whose second-order term over the vertex's shortest edge,
    // |lambda| h^2, is within kRoundOffHessian of max |u| is round-off, not curvature: it is set
    // to 0 (the field is linear in that direction, as far as doubles can tell).
    std::vector<typename Traits<D>::Eigen> abs_h(n);
    double largest = 0.0, largest_term = 0.0;
    for (std::size_t v = 0; v < n; ++v) {
      if (!used[v]) continue;
      Metric h;
      std::copy(hessian[v].begin(), hessian[v].end(), h.m.begin());
      abs_h[v] = eigen(h);
      const double noise = kRoundOffHessian * u_max_scaled / (shortest[v] * shortest[v]);
      for (double& l : abs_h[v].values) {
        l = std::fabs(l);
        if (u_max_scaled > 0.0) largest_term = std::max(largest_term, l * shortest[v] * shortest[v] / u_max_scaled);
        if (!(l > noise)) l = 0.0;
        if (options.relative_cutoff) l /= std::max(std::fabs(u[v]), *options.relative_cutoff * u_max_scaled);
        largest = std::max(largest, l);
      }
    }
    if (!(largest > 0.0))
      throw InputError("metric from solution: " + name + " is linear to round-off on the mesh (largest |lambda| h^2 / max |u| = " +
                       format_double(largest_term) + ", at most " + format_double(kRoundOffHessian) +
                       ", over the Hessian eigenvalues lambda and each vertex's shortest edge h): its P1 interpolation "
                       "error is zero, so no metric follows from it; give a size instead (dtlab mesh --size H, or --hmax)");
    // Eigenvalues relative to the largest, floored at a tiny fraction of it (det > 0 for the
    // powers; a floored direction gets h_max from the clipping).
    std::vector<double> det(n, 0.0);
    for (std::size_t v = 0; v < n; ++v) {
      if (!used[v]) continue;
      det[v] = 1.0;
      for (double& l : abs_h[v].values) det[v] *= (l = std::max(l / largest, kEigenvalueFloor));
    }
    // The scale of each vertex's relative |H|.
    std::vector<double> scale(n, 0.0);
    if (options.error) {
      // Not scale-invariant: the error is absolute. The true |H| is largest * u_scale * (relative).
      const double s = Traits<D>::kLinfConstant / *options.error * (options.relative_cutoff ? 1.0 : u_scale) * largest;
      std::fill(scale.begin(), scale.end(), s);
    } else {
      const double exponent = linf ? 0.5 : options.p / (2.0 * options.p + D);
      std::vector<double> q(n, 0.0);
      for (std::size_t v = 0; v < n; ++v)
        if (used[v]) q[v] = std::pow(det[v], exponent);
      const double integral = integrate<D>(points, elements, q);
      const double d_n = std::pow(*options.complexity, 2.0 / D) * std::pow(integral, -2.0 / D);
      for (std::size_t v = 0; v < n; ++v)
        if (used[v]) scale[v] = linf ? d_n : d_n * std::pow(det[v], -1.0 / (2.0 * options.p + D));
    }
    std::vector<Metric> m(n, Metric::isotropic(h_max));
    for (std::size_t v = 0; v < n; ++v) {
      if (!used[v]) continue;
      typename Traits<D>::Eigen e = abs_h[v];
      for (double& l : e.values) {
        l *= scale[v];
        // An eigenvalue out of the kernel's range (kernel/metric.hpp: its determinant would
        // overflow or underflow) is refused here, before the clipping could hide it.
        if (!(l >= kMinMetricEigenvalue && l <= kMaxMetricEigenvalue))
          throw InputError("metric from solution: " + name + ": the metric at vertex " + std::to_string(v + 1) +
                               " has eigenvalue " + format_double(l) + " (size " + format_double(1.0 / std::sqrt(l)) +
                               "), out of the representable range [" + format_double(kMinMetricEigenvalue) + ", " +
                               format_double(kMaxMetricEigenvalue) + "]" +
                               (options.error ? ": the error asked is too small for the field's scale" : ""),
                           {v});
      }
      m[v] = from_eigen(e);
    }
    if (result.empty()) {
      result = std::move(m);
    } else {
      for (std::size_t v = 0; v < n; ++v)
        if (used[v]) result[v] = intersect(result[v], m[v]);
    }
  }
  complexity_before = metric_complexity(points, elements, std::span<const Metric>(result));
  double scale = 1.0;
  if (options.complexity) {
    scale = clipped_scale<D>(points, elements, used, result, *options.complexity, h_min, h_max);
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (!used[v]) {
      result[v] = Metric::isotropic(h_max);
    } else if (scale == 1.0) {
      result[v] = clip(result[v], h_min, h_max);  // the closed form held: as it always was
    } else {
      result[v] = clipped<D>(eigen(result[v]), scale, h_min, h_max);
    }
  }
  double complexity_clipped = 0.0;
  if (options.complexity || stats) complexity_clipped = metric_complexity(points, elements, std::span<const Metric>(result));
  if (options.complexity && !(std::fabs(complexity_clipped - *options.complexity) <= kComplexityTolerance * *options.complexity))
    // The solve stops within kSolveTolerance; more than kComplexityTolerance off means the doubles
    // did not hold the metric (composing it from its eigenvalues, its determinants, their sum).
    throw InputError("metric from solution: the metric clipped to [h_min, h_max] = [" + format_double(h_min) + ", " +
                     format_double(h_max) + "] has complexity " + format_double(complexity_clipped) + " where " +
                     format_double(*options.complexity) + " was asked (beyond the relative tolerance " +
                     format_double(kComplexityTolerance) + "): the fields' Hessians are out of the range the "
                     "normalisation holds in doubles");
  std::uint32_t passes = 0;
  if (options.gradation) {
    passes = apply_gradation(points, element_edges(elements), std::span<Metric>(result), *options.gradation);
  }
  if (stats) {
    stats->complexity_before_clipping = complexity_before;
    stats->complexity_before_gradation = complexity_clipped;
    stats->normalisation_scale = scale;
    stats->complexity = options.gradation ? metric_complexity(points, elements, std::span<const Metric>(result))
                                          : complexity_clipped;
    stats->gradation_passes = passes;
    stats->h_min = std::numeric_limits<double>::infinity();
    stats->h_max = 0.0;
    stats->max_anisotropy = 1.0;
    for (std::size_t v = 0; v < n; ++v) {
      if (!used[v]) continue;
      const auto s = sizes(result[v]);
      stats->h_max = std::max(stats->h_max, s.front());
      stats->h_min = std::min(stats->h_min, s.back());
      stats->max_anisotropy = std::max(stats->max_anisotropy, s.front() / s.back());
    }
  }
  return result;
}

template <int D>
double complexity_of(std::span<const typename Traits<D>::Point> points,
                     std::span<const std::array<std::uint32_t, D + 1>> elements,
                     std::span<const typename Traits<D>::Metric> metrics) {
  std::vector<double> q(points.size(), 0.0);
  for (const auto& e : elements)
    for (const std::uint32_t v : e) q[v] = std::sqrt(std::max(0.0, metrics[v].determinant()));
  return integrate<D>(points, elements, q);
}

}  // namespace

std::vector<Metric2> metric_from_solutions(std::span<const Vec2> points,
                                           std::span<const std::array<std::uint32_t, 3>> triangles,
                                           std::span<const std::vector<double>> fields,
                                           const SolutionMetricOptions& options, SolutionMetricStats* stats) {
  return compute<2>(points, triangles, fields, options, stats);
}

std::vector<Metric3> metric_from_solutions(std::span<const Vec3> points,
                                           std::span<const std::array<std::uint32_t, 4>> tetrahedra,
                                           std::span<const std::vector<double>> fields,
                                           const SolutionMetricOptions& options, SolutionMetricStats* stats) {
  return compute<3>(points, tetrahedra, fields, options, stats);
}

double metric_complexity(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 3>> triangles,
                         std::span<const Metric2> metrics) {
  return complexity_of<2>(points, triangles, metrics);
}

double metric_complexity(std::span<const Vec3> points, std::span<const std::array<std::uint32_t, 4>> tetrahedra,
                         std::span<const Metric3> metrics) {
  return complexity_of<3>(points, tetrahedra, metrics);
}

}  // namespace dtlab
