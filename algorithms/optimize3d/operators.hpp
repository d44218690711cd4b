// The local operators of 3D mesh optimization (book §8.3-§8.4) on the shared mesh
// (mesh/mesh3.hpp), one a file: face swap 2 -> 3 (face_swap.cpp), shell transformation
// n -> 2n - 4 with edge removal 3 -> 2 and 4 -> 4 as its first cases (shell.cpp), vertex
// relocation toward the optimal point of its ball (relocate.cpp), edge collapse (collapse.cpp),
// edge split (split.cpp). strategy.cpp (optimize3d.hpp) orders them.
//
// Every operator follows §8.6.1: it simulates its result (validity by exact orient3d on every new
// tetrahedron, quality Q_K of kernel/quality.hpp in the vertex metrics, worst over the four) and
// applies it only when the criterion holds. None crosses or changes a constrained facet or edge,
// touches a ghost or an exterior tetrahedron, or merges two regions (a facet between tetrahedra of
// different references is treated as constrained); none moves or removes a vertex flagged
// Mesh3::kFixed or Mesh3::kOnBoundary; references are kept. After each one the mesh passes
// Mesh3::check().
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "algorithms/common/unit_mesh.hpp"
#include "kernel/metric.hpp"
#include "kernel/vec.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab {

using MetricField3 = MetricField<Metric3, Vec3>;  // algorithms/common/unit_mesh.hpp

// Size operators may leave the worst Q_K of what they touch at the old worst or at this,
// whichever is larger (collapse: Q <= 3; split: Q <= 4 — tetrahedra are worse than triangles
// for the same sizes: the book's Tables 7.1-7.3 and 8.2-8.3 put most of them in [1, 3]).
inline constexpr double kCollapseQualityLimit3 = 3.0;
inline constexpr double kSplitQualityLimit3 = 4.0;
// The largest shell a transformation retriangulates (Table 8.1: Cat(n - 1) triangulations; the
// dynamic program is O(n^3) but shells beyond this are rare and never improve).
inline constexpr std::uint32_t kMaxShellSize = 12;

// --- Face swap 2 -> 3 (book §8.3.2) -------------------------------------------------------------
// Replaces the two tetrahedra beside facet h (p, q, r) by the three around the edge joining their
// apexes d, e, when all three are positive and their worst Q_K is below the pair's (margin).
// False (nothing changed) when h is locked (constrained, between regions, beside a ghost or an
// exterior tetrahedron), when de already is an edge, or when the swap is invalid or no better.
// `created` (optional) receives the new tetrahedra's slots.
bool try_face_swap(Mesh3& mesh, std::uint32_t h, double margin = kImprovementMargin,
                   std::vector<std::uint32_t>* created = nullptr);

// --- Shell transformation n -> 2n - 4 (book §8.3.3, Table 8.1) ---------------------------------
// Removes edge ab: its shell of n tetrahedra (3 <= n <= kMaxShellSize) is replaced by the best
// triangulation T of its ring (the min-max of Q_K over the 2(n - 2) tetrahedra {t + a, t + b},
// found by dynamic programming over the ring's sub-polygons, every candidate tetrahedron checked
// positive exactly). n = 3 is the edge removal 3 -> 2, n = 4 the 4 -> 4 swap. Accepted when the
// new worst is below the shell's (margin). False when ab is no free edge (constrained, a shell
// facet constrained, the shell leaving the domain or crossing regions) or no triangulation is
// valid and better.
// `hint`: a live tetrahedron with edge ab, or kNone.
bool try_shell_transformation(Mesh3& mesh, std::uint32_t a, std::uint32_t b, double margin = kImprovementMargin,
                              std::vector<std::uint32_t>* created = nullptr, std::uint32_t hint = Mesh3::kNone);

struct SwapPass3Result {
  std::uint64_t face_swaps = 0;
  std::uint64_t shell_transformations = 0;
  bool limit_reached = false;  // stopped at the bound (a safety net)
};
// Face swaps and shell transformations until none improves: the tetrahedra of `seeds` (empty:
// every domain tetrahedron whose Q_K exceeds `threshold`), worst first, each new tetrahedron
// queued again when its Q_K exceeds `threshold`. At most 20 changes per live tetrahedron + 1000.
SwapPass3Result swap_pass3(Mesh3& mesh, double margin = kImprovementMargin, std::span<const std::uint32_t> seeds = {},
                           double threshold = 0.0);

// --- Relocation (book §8.4, (8.13)-(8.17)) ------------------------------------------------------
struct Relocate3Options {
  double margin = kImprovementMargin;  // the ball's worst Q_K must improve by this, relative
  std::uint32_t tries = 6;              // relaxation w = 1, 1/2, ..., 2^-(tries-1)
};
// The optimal point P* of v's ball (book (8.17), optimal shape relocation): the mean, weighted by
// the current Q_K of each tetrahedron, of the apexes I_j that make each facet of the ball's
// boundary a regular tetrahedron in the facet's metric (the mean of its vertex metrics).
Vec3 optimal_point(const Mesh3& mesh, std::uint32_t v, std::span<const std::uint32_t> ball);
// Moves a free vertex v to P' = (1 - w) P + w P* (8.13), the first w from 1 down for which every
// tetrahedron of the ball is positive and the ball's worst Q_K improves; failing that, the same
// relaxation toward the ideal point of the ball's worst tetrahedron alone. Its metric becomes
// `field` at P' (unchanged when the field is empty). `field` is asked at every candidate P',
// before its orientations are tested: it must answer (any finite metric) for points outside the
// domain too. True when v moved.
bool try_relocate3(Mesh3& mesh, std::uint32_t v, const MetricField3& field, const Relocate3Options& options = {});
// One sweep: every free vertex once, worst ball first. Returns the number of vertices moved.
std::uint64_t relocate_sweep3(Mesh3& mesh, const MetricField3& field, const Relocate3Options& options = {});

// --- Relocation for dihedral angles (relocate_dihedral.cpp) -------------------------------------
struct RelocateDihedral3Options {
  double quality_limit = 3.0;      // the ball's worst Q_K may rise up to this (or its old worst)
  double max_dihedral_cos = -2.0;  // the ball's largest angle may rise up to this one's (cos), or its old
  double margin = 1e-9;            // the smallest angle's cosine must fall by this
  std::uint32_t tries = 6;         // w = 1, 1/2, ...
};
// Moves a free vertex v toward the optimal point of its ball (8.17), else toward the centroid of
// its link, with relaxation, when the ball's smallest dihedral angle grows, no new tetrahedron is
// inverted (exact), its largest angle stays below max(old largest, max_dihedral_cos's) and its
// worst Q_K at most max(old worst, quality_limit). True when v moved.
bool try_relocate_dihedral3(Mesh3& mesh, std::uint32_t v, const MetricField3& field,
                            const RelocateDihedral3Options& options = {});

// --- Collapse (book §8.3.5) ---------------------------------------------------------------------
struct Collapse3Options {
  double short_length = kShortEdgeLength;  // collapse_pass3: edges shorter than this, in the metric
  double long_length = kLongEdgeLength;    // no new edge may be longer than this
  double quality_limit = kCollapseQualityLimit3;
  double margin = kImprovementMargin;
};
enum class Collapse3Criterion : std::uint8_t {
  NotWorse,  // the new worst Q_K of the ball is at most max(old worst, quality_limit): a size operation
  Improve,   // the new worst Q_K is strictly below the old worst (margin): a shape operation (slivers)
};
// Collapses edge uv: the free end is removed and its tetrahedra take the other end; the shell of
// uv disappears. Both directions are tried when both ends are free, the better result kept.
// Accepted when every new tetrahedron is positive (then they tile the old ball, which is
// star-shaped from the kept end), no new edge is longer than long_length, and the criterion
// holds.
bool try_collapse3(Mesh3& mesh, std::uint32_t u, std::uint32_t v, const Collapse3Options& options = {},
                   Collapse3Criterion criterion = Collapse3Criterion::NotWorse);
// Collapses every edge shorter than short_length, shortest first. Returns the number of collapses.
std::uint64_t collapse_pass3(Mesh3& mesh, const Collapse3Options& options = {});

// --- Split (book §8.3.6) ------------------------------------------------------------------------
struct Split3Options {
  double long_length = kLongEdgeLength;    // split_pass3: edges longer than this, in the metric
  double short_length = kShortEdgeLength;  // no edge from the new vertex to the ring shorter than this
  double quality_limit = kSplitQualityLimit3;
  double margin = kImprovementMargin;         // the swaps after each split
  std::uint64_t max_vertices = 20'000'000;  // split_pass3 stops short of this many live vertices
};
// The point of edge ab where both halves have the same metric length (as optimize2d's).
Vec3 metric_midpoint3(const Vec3& a, const Metric3& ma, const Vec3& b, const Metric3& mb) noexcept;
// Splits free edge ab at its metric midpoint (metric from `field`, else interpolated from the
// ends): each tetrahedron (a, b, c, d) of its shell becomes (m, b, c, d) and (a, m, c, d).
// Refused (kNone) for an edge that is not free, when a new tetrahedron would not be positive,
// when an edge from m to the ring would be shorter than short_length, or when the new worst Q_K
// exceeds both the shell's and quality_limit. Returns the new vertex.
std::uint32_t try_split3(Mesh3& mesh, std::uint32_t a, std::uint32_t b, const MetricField3& field,
                         const Split3Options& options = {});
struct SplitPass3Result {
  std::uint64_t splits = 0;
  std::uint64_t swaps = 0;
  bool limit_reached = false;
};
// Splits every free edge longer than long_length, longest first, each followed by the swap pass
// on the new vertex's ball; halves still too long join the queue.
SplitPass3Result split_pass3(Mesh3& mesh, const MetricField3& field, const Split3Options& options = {});

}  // namespace dtlab
