// 2D mesh optimization (book §8): the strategy of §8.6.3 over the local operators of
// operators.hpp, on the shared mesh (mesh/mesh2.hpp), in the metric of its vertices (the
// isotropic metric h^-2 I is a metric like any other).
//
//   Optimize2dStats s = optimize2d(mesh, {}, [&](const Vec2& p) { return control.metric_at(p, hint); });
//
// Each round: the triangles are classified by Q_K and the bad ones (Q_K > bad_quality) treated
// worst first with the operators that fit their pathology (swap, relocation, collapse of their
// shortest edge when that improves them); then the whole mesh: collapses of short edges and
// splits of long ones (the aim is a unit mesh, edges in [1/sqrt2, sqrt2] in the metric), swaps,
// relocation sweeps, optionally valence relaxation. Rounds repeat while the worst or the mean Q_K
// improves by `round_improvement` (relative) or the sizes still change, at most max_rounds.
// Deterministic: the same mesh, options and field give the same result, bit for bit.
#pragma once

#include <cstdint>

#include "algorithms/common/optimize_strategy.hpp"
#include "algorithms/optimize2d/operators.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab {

template <class Entry>
class Registry;  // algorithms/common/registry.hpp
struct Optimize2dOperator;  // registry.hpp

// The rounds' options (algorithms/common/optimize_strategy.hpp: at most 8 rounds, triangles with
// Q_K > 1.4 treated one by one) and the 2D operators'.
struct Optimize2dRoundDefaults {
  static constexpr std::uint32_t kMaxRounds = 8;
  static constexpr double kBadQuality = 1.4;
};
struct Optimize2dOptions : OptimizeRoundOptions<Optimize2dRoundDefaults> {
  // Where the names of `sequence` are looked up (null: optimize2d_operators(), registry.hpp).
  const Registry<Optimize2dOperator>* operators = nullptr;
  // Boundary vertices that are neither kFixed nor corners collapsed along the boundary
  // (boundary_collapse_pass, after collapse_pass): adaptation's coarsening of the boundary.
  bool boundary_collapses = false;
  bool valence = false;                 // valence relaxation (§8.3.7) after the swaps
  double swap_margin = kImprovementMargin;  // try_swap's relative margin
  RelocateOptions relocate{};
  CollapseOptions collapse{};
  SplitOptions split{};
};

// The rounds' report (algorithms/common/optimize_strategy.hpp) and the operators' counts.
struct Optimize2dStats : OptimizeRoundStats {
  std::uint64_t swaps = 0;  // quality swaps, including those after splits
  std::uint64_t relocations = 0;
  std::uint64_t swap_relocations = 0;  // try_swap_relocate moves kept (bad triangles only)
  std::uint64_t collapses = 0;
  std::uint64_t boundary_collapses = 0;
  std::uint64_t splits = 0;
  std::uint64_t boundary_support_fallbacks = 0;  // boundary splits put on the chord (support point refused)
  std::uint64_t valence_swaps = 0;
  std::uint64_t triangles_before = 0, triangles_after = 0;  // in the domain
};

// The worst and mean Q_K over the domain's triangles (the mean over the finite values; both 0
// without triangles).
struct QualitySummary2 {
  double worst = 0.0;
  double mean = 0.0;
  std::uint64_t triangles = 0;
};
QualitySummary2 summarize_quality(const Mesh2& mesh);

// Optimizes `mesh` in place; `field` is the control space (operators.hpp MetricField2; empty:
// the vertices keep their metrics, new vertices interpolate them). The mesh passes Mesh2::check()
// afterwards; no constrained edge, kFixed or kOnBoundary vertex changes (boundary splits only
// with options.split.boundary).
Optimize2dStats optimize2d(Mesh2& mesh, const Optimize2dOptions& options = {}, const MetricField2& field = {});

}  // namespace dtlab
