// The metric that equidistributes the P1 interpolation error of a solution (book §12.2, whose
// text the reference lost; the formulas are those of Frey and Alauzet 2005, "Anisotropic mesh
// adaptation for CFD computations", CMAME 194, and of the continuous mesh framework, Loseille
// and Alauzet 2011, SINUM 49):
//  1. the Hessian H at the vertices (hessian.hpp), then |H| = R |Λ| R^T;
//  2. relative error (optional, Frey–Alauzet §4.3): |H| / max(|u|, cutoff · max |u|);
//  3. the norm:
//     - L∞ with a target error ε: M = c_d / ε |H| (c_2 = 2/9, c_3 = 9/32: the constant of the
//       interpolation error bound on a unit element);
//     - Lp (p ≥ 1) with a target complexity N, the user's one knob (about the number of vertices):
//       M = D_N det(|H|)^(-1/(2p+d)) |H|, D_N = N^(2/d) (∫ det(|H|)^(p/(2p+d)))^(-2/d), so that the
//       continuous complexity ∫ sqrt(det M) is N; L∞ with a complexity is the limit p → ∞
//       (D_N = N^(2/d) (∫ sqrt(det |H|))^(-2/d));
//  4. the intersection of the metrics of several fields (book §9.5, §12.2.5: each field's metric
//     by the same rule, then simultaneous reduction);
//  5. the sizes clipped to [h_min, h_max] (an eigenvalue 0 of |H|, a direction where the field is
//     linear, gets h_max). With a complexity the global constant is fixed for the clipped metric
//     (Loseille and Alauzet 2011, part II): the metric is clip(s M), s solved by bisection on
//     log s so that ∫ sqrt(det clip(s M)) is N within a relative 1e-9 (checked at 1e-6); s = 1,
//     the closed form, where no clipping moves the complexity. Only the global constant is
//     solved: the per-vertex det^(-1/(2p+d)) of the Lp norm stays as in 3. With several fields
//     the constant is that of the intersection (scaling commutes with it), so the metric written
//     has complexity N whatever the number of fields. An N outside the complexities of the
//     all-h_max and all-h_min metrics is refused, naming the bound and the reachable range;
//  6. the gradation (kernel/metric.hpp apply_gradation, h-grad β), after 5: it only grows the
//     metric, so the complexity after it is N or more (stats: complexity_before_gradation, N,
//     and complexity, after).
// Integrals are P1 over the mesh: ∫ q = Σ_K |K| · (mean of q at K's vertices).
// Bounded work and values in doubles (issue 42):
//  - each field is scaled by a power of two (exact) to max |u| in [0.5, 1] before the recovery:
//    with a complexity the metric does not depend on a factor on u (|H| scales by it, D_N
//    det(|H|)^(-1/(2p+d)) by its inverse), and 1e300 x² neither overflows nor underflows;
//  - round-off: an eigenvalue λ of the recovered Hessian with |λ| h² ≤ 1e-12 max |u| (h the
//    vertex's shortest edge) is 0. The round-off of a linear field measures at most 1.3 ulps of
//    max |u| in |λ| h² (2D and 3D, both recoveries, graded meshes); 1e-12 is about 4500 ulps. A
//    field with every eigenvalue 0 is linear to round-off and refused;
//  - the eigenvalues of each field's metric must lie in [kMinMetricEigenvalue,
//    kMaxMetricEigenvalue] (kernel/metric.hpp), and with a complexity the clipped metric's
//    ∫ sqrt(det M) must be N within a relative 1e-6 (the solve stops at 1e-9; the rest is the
//    round-off of composing the metrics and summing their determinants); h_min, h_max must be
//    representable sizes, h_min at least 1e-9 of the diagonal.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algorithms/adapt/hessian.hpp"
#include "kernel/metric.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

struct SolutionMetricOptions {
  HessianRecovery recovery = HessianRecovery::LeastSquares;
  // p of the Lp norm; infinity (the default) is the L∞ norm.
  double p = std::numeric_limits<double>::infinity();
  // Exactly one of the two: the target complexity N (> 0) or the target error ε (> 0, L∞ only).
  std::optional<double> complexity;
  std::optional<double> error;
  // Relative error with this cutoff (> 0): |H| / max(|u|, cutoff · max |u|).
  std::optional<double> relative_cutoff;
  // Size bounds (0 < h_min <= h_max); absent: h_min = 1e-8 · diagonal, h_max = the diagonal.
  std::optional<double> h_min, h_max;
  // Gradation β >= 1 over the mesh's edges; absent: none.
  std::optional<double> gradation;
  // The fields' names for messages (e.g. their files), in the order of `fields`; may be empty.
  std::vector<std::string> field_names;
};

struct SolutionMetricStats {
  double complexity_before_clipping = 0.0;   // ∫ sqrt(det M) of the normalised metric, closed form
                                             // (N for one field with a complexity)
  double complexity_before_gradation = 0.0;  // the same, scaled and clipped (N when asked)
  double complexity = 0.0;                   // the same of the final metric (after the gradation)
  double normalisation_scale = 1.0;          // s: the final metric is clip(s M) (before gradation)
  double h_min = 0.0, h_max = 0.0;          // the smallest and largest size of the final metric
  double max_anisotropy = 0.0;              // largest ratio of sizes at one vertex
  std::uint32_t gradation_passes = 0;
};

// One field per entry of `fields` (each one value per point); the metric at every point (unused
// points get h_max^-2 I). Throws InputError for bad options (naming them and the value), for
// fields as recover_hessian does, for a field linear to round-off (no Hessian to distribute), for
// a metric out of the doubles' range (the bounds above), naming the field, and for a complexity
// the size bounds cannot reach (naming the bound and the reachable range).
std::vector<Metric2> metric_from_solutions(std::span<const Vec2> points,
                                           std::span<const std::array<std::uint32_t, 3>> triangles,
                                           std::span<const std::vector<double>> fields,
                                           const SolutionMetricOptions& options, SolutionMetricStats* stats = nullptr);
std::vector<Metric3> metric_from_solutions(std::span<const Vec3> points,
                                           std::span<const std::array<std::uint32_t, 4>> tetrahedra,
                                           std::span<const std::vector<double>> fields,
                                           const SolutionMetricOptions& options, SolutionMetricStats* stats = nullptr);

// ∫ sqrt(det M) over the mesh, P1: the continuous complexity (about the vertex count of a unit
// mesh in M).
double metric_complexity(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 3>> triangles,
                         std::span<const Metric2> metrics);
double metric_complexity(std::span<const Vec3> points, std::span<const std::array<std::uint32_t, 4>> tetrahedra,
                         std::span<const Metric3> metrics);

}  // namespace dtlab
