// The table of the 2D optimization operators (registry.hpp), each entry point the pass of its
// file's operator (operators.hpp) with the strategy's options and counts.
#include "algorithms/optimize2d/registry.hpp"

namespace dtlab {

namespace {

OperatorResult collapse(Mesh2& mesh, const Optimize2dOptions& options, const MetricField2&, Optimize2dStats& stats) {
  return size_operator(options.collapses, stats.collapses, [&] { return collapse_pass(mesh, options.collapse); });
}

OperatorResult boundary_collapse(Mesh2& mesh, const Optimize2dOptions& options, const MetricField2&,
                                 Optimize2dStats& stats) {
  return size_operator(options.boundary_collapses, stats.boundary_collapses,
                       [&] { return boundary_collapse_pass(mesh, options.collapse); });
}

OperatorResult split(Mesh2& mesh, const Optimize2dOptions& options, const MetricField2& field, Optimize2dStats& stats) {
  if (!options.splits) return {};
  const SplitPassResult r = split_pass(mesh, field, options.split);
  stats.splits += r.splits;
  stats.boundary_support_fallbacks += r.support_fallbacks;
  stats.swaps += r.swaps;
  if (r.limit_reached) stats.stopped_by = "vertex_limit";
  return {r.splits, r.limit_reached};
}

OperatorResult swap(Mesh2& mesh, const Optimize2dOptions& options, const MetricField2&, Optimize2dStats& stats) {
  if (!options.swaps) return {};
  const SwapPassResult r = swap_pass(mesh, options.swap_margin);
  stats.swaps += r.swaps;
  if (r.limit_reached) stats.stopped_by = "swap_limit";
  return {0, r.limit_reached};
}

OperatorResult relocate(Mesh2& mesh, const Optimize2dOptions& options, const MetricField2& field,
                        Optimize2dStats& stats) {
  RelocationSweeps sweeps(mesh, field, options.relocate);
  return relocation_sweeps(options, stats, [&] { return sweeps.sweep(); });
}

OperatorResult valence(Mesh2& mesh, const Optimize2dOptions& options, const MetricField2& field,
                       Optimize2dStats& stats) {
  if (!options.valence) return {};
  stats.valence_swaps += valence_pass(mesh);
  return swap(mesh, options, field, stats);
}

}  // namespace

const Registry<Optimize2dOperator>& optimize2d_operators() {
  static const Registry<Optimize2dOperator> entries{
      "optimization operator",
      {Optimize2dOperator{"bad",
                          "the triangles with Q_K > bad_quality, worst first: swap, relocation, swap with "
                          "relocation or collapse of the shortest edge, the first that helps (§8.6.3; strategy.cpp)",
                          &optimize2d_detail::treat_bad_triangles},
       Optimize2dOperator{"collapse", kCollapseDescription, &collapse},
       Optimize2dOperator{"boundary_collapse",
                          "with boundary_collapses: collapses of short boundary edges along the boundary (§9.3.1; "
                          "boundary_collapse.cpp)", &boundary_collapse},
       Optimize2dOperator{"split", kSplitDescription, &split},
       Optimize2dOperator{"swap", "edge swaps until no pair's worst Q_K improves (§8.3.1; swap.cpp)", &swap},
       Optimize2dOperator{"relocate", "relocation_sweeps sweeps moving the free vertices toward the optimal point "
                                      "of their ball (§8.4.1; relocate.cpp)", &relocate},
       Optimize2dOperator{"valence", "with valence: swaps toward degree 6, then the swap pass (§8.3.7; valence.cpp)",
                          &valence}}};
  return entries;
}

}  // namespace dtlab
