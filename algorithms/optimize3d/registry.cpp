// The table of the 3D optimization operators (registry.hpp), each entry point the pass of its
// file's operator (operators.hpp, local.hpp) with the strategy's options and counts.
#include "algorithms/optimize3d/registry.hpp"

#include "algorithms/optimize3d/local.hpp"

namespace dtlab {

namespace {

OperatorResult collapse(Mesh3& mesh, const Optimize3dOptions& options, const MetricField3&, Optimize3dStats& stats,
                        const OperatorScope3& scope) {
  return size_operator(options.collapses, stats.collapses,
                       [&] { return optimize3d_detail::collapse_pass(mesh, options.collapse, scope.region); });
}

OperatorResult split(Mesh3& mesh, const Optimize3dOptions& options, const MetricField3& field, Optimize3dStats& stats,
                     const OperatorScope3& scope) {
  if (!options.splits) return {};
  Split3Options split = options.split;
  split.margin = options.margin;
  const SplitPass3Result r = optimize3d_detail::split_pass(mesh, field, split, scope.region);
  stats.splits += r.splits;
  stats.face_swaps += r.swaps;  // counted together: split_pass3 does not tell them apart
  if (r.limit_reached) stats.stopped_by = "vertex_limit";
  return {r.splits, r.limit_reached};
}

OperatorResult swap(Mesh3& mesh, const Optimize3dOptions& options, const MetricField3&, Optimize3dStats& stats,
                    const OperatorScope3& scope) {
  if (!options.swaps) return {};
  optimize3d_detail::QualityCache cache;
  const double threshold = !scope.region.empty() && options.region_swap_threshold > 0.0 ? options.region_swap_threshold
                                                                                        : options.swap_threshold;
  const optimize3d_detail::SwapPassResult r =
      optimize3d_detail::swap_pass(mesh, options.margin, scope.seeds, threshold, cache, scope.memo);
  stats.face_swaps += r.face_swaps;
  stats.shell_transformations += r.shell_transformations;
  if (r.limit_reached) stats.stopped_by = "swap_limit";
  return {0, r.limit_reached};
}

OperatorResult relocate(Mesh3& mesh, const Optimize3dOptions& options, const MetricField3& field,
                        Optimize3dStats& stats, const OperatorScope3& scope) {
  return relocation_sweeps(options, stats, [&] {
    return optimize3d_detail::relocate_sweep(mesh, field, options.relocate, scope.memo, scope.region);
  });
}

}  // namespace

const Registry<Optimize3dOperator>& optimize3d_operators() {
  static const Registry<Optimize3dOperator> entries{
      "optimization operator",
      {Optimize3dOperator{"bad",
                          "the tetrahedra with Q_K > bad_quality, worst first: face swap or shell transformation, "
                          "relocation, collapse of the shortest edge, an interior vertex (§8.6; strategy.cpp)",
                          &optimize3d_detail::treat_bad_tetrahedra},
       Optimize3dOperator{"collapse", kCollapseDescription, &collapse},
       Optimize3dOperator{"split", kSplitDescription, &split},
       Optimize3dOperator{"swap", "face swaps 2 -> 3 and shell transformations n -> 2n - 4 from the tetrahedra "
                                  "worse than swap_threshold (§8.3.2-§8.3.3; swap_pass.cpp)", &swap},
       Optimize3dOperator{"relocate", "relocation_sweeps sweeps moving the free vertices toward the optimal point "
                                      "of their ball (§8.4; relocate.cpp)", &relocate}}};
  return entries;
}

}  // namespace dtlab
