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
#include <string>

#include "algorithms/optimize2d/operators.hpp"
#include "kernel/interrupt.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab {

struct Optimize2dOptions {
  std::uint32_t max_rounds = 8;
  // Another round while the worst or the mean Q_K drops by more than this, relative.
  double round_improvement = 1e-3;
  // Triangles worse than this are treated one by one, worst first, at the start of each round.
  double bad_quality = 1.4;
  bool swaps = true;
  bool relocation = true;
  std::uint32_t relocation_sweeps = 2;  // per round
  bool collapses = true;                // short edges (size) and needles (shape)
  bool splits = true;                   // long edges
  // Boundary vertices that are neither kFixed nor corners collapsed along the boundary
  // (boundary_collapse_pass, after collapse_pass): adaptation's coarsening of the boundary.
  bool boundary_collapses = false;
  bool valence = false;                 // valence relaxation (§8.3.7) after the swaps
  double swap_margin = kImprovementMargin;  // try_swap's relative margin
  RelocateOptions relocate{};
  CollapseOptions collapse{};
  SplitOptions split{};
  // Asked before each round and each pass of a round (kernel/interrupt.hpp); yes: Interrupted.
  InterruptCheck interrupt{};
};

struct Optimize2dStats {
  std::uint64_t swaps = 0;  // quality swaps, including those after splits
  std::uint64_t relocations = 0;
  std::uint64_t swap_relocations = 0;  // try_swap_relocate moves kept (bad triangles only)
  std::uint64_t collapses = 0;
  std::uint64_t boundary_collapses = 0;
  std::uint64_t splits = 0;
  std::uint64_t boundary_support_fallbacks = 0;  // boundary splits put on the chord (support point refused)
  std::uint64_t valence_swaps = 0;
  std::uint32_t rounds = 0;
  // Q_K over the domain's triangles (kernel/quality.hpp, in the vertex metrics); the mean over
  // the finite values.
  double worst_before = 0.0, mean_before = 0.0;
  double worst_after = 0.0, mean_after = 0.0;
  std::uint64_t triangles_before = 0, triangles_after = 0;  // in the domain
  std::uint64_t vertices_before = 0, vertices_after = 0;    // live
  // Why the rounds ended: "converged" (no further improvement), "max_rounds", "swap_limit" or
  // "vertex_limit" (a pass stopped at its bound; the mesh is valid all the same).
  std::string stopped_by;
  double seconds = 0.0;
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
