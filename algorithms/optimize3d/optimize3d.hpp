// 3D mesh optimization (book §8): the strategy of §8.6 over the local operators of
// operators.hpp, on the shared mesh (mesh/mesh3.hpp), in the metric of its vertices.
//
//   Optimize3dStats s = optimize3d(mesh, {}, [&](const Vec3& p) { return control.metric_at(p); });
//
// Each round: the tetrahedra are classified by Q_K and the bad ones (Q_K > bad_quality) treated
// worst first with the operators that fit their pathology (face swaps, shell transformations of
// their edges, relocation of their free vertices, collapse of their shortest edge: a sliver with
// four vertices near one plane is undone by a swap or a move, a needle or a cap by the collapse);
// then the whole mesh: collapses of short edges and splits of long ones (toward unit edges in the
// metric), the swap pass, relocation sweeps. Rounds repeat while the worst or the mean Q_K
// improves by `round_improvement` (relative) or sizes still change (more than one collapse or
// split per thousand vertices), at most max_rounds.
// Deterministic: the same mesh, options and field give the same result, bit for bit.
#pragma once

#include <cstdint>
#include <string>

#include "algorithms/common/optimize_strategy.hpp"
#include "algorithms/optimize3d/operators.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab {

template <class Entry>
class Registry;  // algorithms/common/registry.hpp
struct Optimize3dOperator;  // registry.hpp

// The rounds' options (algorithms/common/optimize_strategy.hpp: at most 6 rounds, tetrahedra
// with Q_K > 3 treated one by one) and the 3D operators'.
struct Optimize3dRoundDefaults {
  static constexpr std::uint32_t kMaxRounds = 6;
  static constexpr double kBadQuality = 3.0;
};
struct Optimize3dOptions : OptimizeRoundOptions<Optimize3dRoundDefaults> {
  // Where the names of `sequence` are looked up (null: optimize3d_operators(), registry.hpp).
  const Registry<Optimize3dOperator>* operators = nullptr;
  // A goal (0: not asked): the rounds stop after the first one whose mesh has no Q_K above
  // goal_worst_quality, no dihedral angle below goal_min_dihedral_deg and none above
  // goal_max_dihedral_deg (Euclidean, degrees), whatever the improvement.
  double goal_worst_quality = 0.0;
  double goal_min_dihedral_deg = 0.0;
  double goal_max_dihedral_deg = 0.0;
  // And at least this share of the tetrahedra with Q_K in [1, 2] (0: not asked).
  double goal_share_1_2 = 0.0;
  // Stop at the first round that meets the goal (else the rounds run until no gain). Either way,
  // a dihedral goal still missed after the rounds gets a last step: the vertices of the
  // tetrahedra below goal_min_dihedral_deg moved for their dihedral angles
  // (try_relocate_dihedral3, a few passes).
  bool stop_at_goal = true;
  bool dihedral_step = true;  // off: no last step (to compare)
  // With a goal, rounds after the first work only on the vertices within this many rings of
  // the tetrahedra that miss it (0: every round on the whole mesh).
  std::uint32_t goal_rings = 0;
  // The swap pass starts from the tetrahedra worse than this (the others are reached as
  // neighbours of changed ones): a pass over all of them costs much and changes little.
  double swap_threshold = 1.5;
  // The same in the rounds restricted to the goal region (goal_rings): a small region affords
  // more seeds. 0: swap_threshold.
  double region_swap_threshold = 0.0;
  // Bad tetrahedra on four boundary vertices that no other operator cures get an interior
  // vertex (an edge split and the new vertex relocated, judged as one move; strategy.cpp).
  bool interior_vertices = true;
  double margin = kImprovementMargin;
  // Skip the shell transformations and relocations known to fail again (their piece of mesh
  // unchanged since they failed: Mesh3's change epochs). The same result either way, bit for
  // bit; off only to check that.
  bool remember_failures = true;
  Relocate3Options relocate{};
  Collapse3Options collapse{};
  Split3Options split{};
};

// The rounds' report (algorithms/common/optimize_strategy.hpp) and the operators' counts.
struct Optimize3dStats : OptimizeRoundStats {
  std::uint64_t face_swaps = 0;
  std::uint64_t shell_transformations = 0;  // n -> 2n - 4, 3 -> 2 and 4 -> 4 included
  std::uint64_t relocations = 0;
  std::uint64_t collapses = 0;
  std::uint64_t splits = 0;
  std::uint64_t tetrahedra_before = 0, tetrahedra_after = 0;  // in the domain
};

struct QualitySummary3 {
  double worst = 0.0;
  double mean = 0.0;  // over the finite values
  std::uint64_t tetrahedra = 0;
  double min_dihedral_deg = 180.0, max_dihedral_deg = 0.0;  // Euclidean
  double share_1_2 = 0.0;  // of the tetrahedra, those with Q_K <= 2
};
QualitySummary3 summarize_quality(const Mesh3& mesh);

// The effort levels of `dtlab mesh --optimize LEVEL` (throws InputError on another name):
//   light     one round, one relocation sweep;
//   standard  one relocation sweep a round, the swap pass seeded with Q_K > 2 (1.5 in the
//             rounds restricted to the goal's region), rounds until
//             the goal is met — Q_K <= 3 (the book's bad-element threshold, §8.6), dihedral
//             angles in [20, 150] degrees, 97 % of Q_K in [1, 2] — or until they no longer
//             improve (at most 6); rounds after the first only within 3 rings of the tetrahedra
//             that miss the goal (with those of Q_K > 2 while the share is short);
//   thorough  two relocation sweeps a round, rounds until the worst and the mean Q_K no longer
//             improve (at most 6: the former defaults), then the dihedral step toward
//             angles in [25, 150] degrees.
Optimize3dOptions optimize3d_effort(const std::string& level);

// Optimizes `mesh` in place; `field` is the control space (empty: vertices keep their metrics,
// new vertices interpolate them). The mesh passes Mesh3::check() afterwards; no constrained facet
// or edge, kFixed or kOnBoundary vertex or reference changes.
Optimize3dStats optimize3d(Mesh3& mesh, const Optimize3dOptions& options = {}, const MetricField3& field = {});

}  // namespace dtlab
