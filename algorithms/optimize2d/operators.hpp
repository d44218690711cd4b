// The local operators of 2D mesh optimization (book §8.3-§8.4) on the shared mesh
// (mesh/mesh2.hpp), one a file: edge swap (swap.cpp), vertex relocation toward the optimal
// point of its ball (relocate.cpp), edge collapse (collapse.cpp), edge split (split.cpp),
// valence relaxation (valence.cpp). strategy.cpp (optimize2d.hpp) orders them.
//
// Every operator follows §8.6.1: it simulates its result (validity by exact orient2d on every
// new triangle, quality Q_K of kernel/quality.hpp in the vertex metrics) and applies it only when
// the criterion holds. None crosses a constrained edge, touches a ghost or an exterior triangle,
// or merges two regions (an edge between triangles of different references is treated as
// constrained); none moves or removes a vertex flagged Mesh2::kFixed or Mesh2::kOnBoundary.
// After each one the mesh passes Mesh2::check().
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "algorithms/common/unit_mesh.hpp"
#include "kernel/metric.hpp"
#include "kernel/vec.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab {

using MetricField2 = MetricField<Metric2, Vec2>;  // algorithms/common/unit_mesh.hpp

// A collapse may leave the ball's worst Q_K at the old worst or at this, whichever is larger
// (Q <= 2: the book's first quality class, §8.2.2 and Tables 7.1-7.3).
inline constexpr double kCollapseQualityLimit = 2.0;
// A split may leave the new triangles' worst Q_K at the old worst or at this, whichever is
// larger (Q <= 3: the book's second quality class).
inline constexpr double kSplitQualityLimit = 3.0;

// --- Edge swap (book §8.3.1) ---------------------------------------------------------------------
// Swaps the diagonal of half-edge h's quadrilateral when the worst Q_K of the pair strictly
// improves (by the relative `margin`) and both new triangles are positive. False (nothing
// changed) when h is constrained, between regions, beside a ghost or an exterior triangle, or
// when the swap is invalid or does not improve.
bool try_swap(Mesh2& mesh, std::uint32_t h, double margin = kImprovementMargin);

struct SwapPassResult {
  std::uint64_t swaps = 0;
  bool limit_reached = false;  // stopped at the swap bound (a safety net: never reached in tests)
};
// Swaps with a work queue until no edge improves: the edges of `seeds` (half-edges; empty: every
// edge of the domain, worst pair first), and the four outer edges of each swapped pair. At most
// 20 swaps per live triangle + 1000.
SwapPassResult swap_pass(Mesh2& mesh, double margin = kImprovementMargin, std::span<const std::uint32_t> seeds = {});

// --- Relocation (book §8.4.1, (8.13)-(8.17)) ---------------------------------------------------
struct RelocateOptions {
  double margin = kImprovementMargin;  // the ball's worst Q_K must improve by this, relative
  std::uint32_t tries = 6;             // relaxation w = 1, 1/2, ..., 2^-(tries-1)
};
// Moves a free vertex v (no kFixed / kOnBoundary flag, every triangle around it in one region
// of the domain, no constrained edge at it) to P' = (1 - w) P + w P*, P* the optimal point of its
// ball: the mean, weighted by the triangles' Q_K, of the points I_j that make each ring edge an
// equilateral triangle in the edge's metric (§8.4.1 "optimal shape relocation", Brière de l'Isle
// and George 1995, weights a_j = Q_Kj). The first w, from 1 down, for which every triangle of the
// ball is positive and the ball's worst Q_K improves is kept; the vertex's metric is `field` at
// P' (unchanged when the field is empty). True when v moved.
bool try_relocate(Mesh2& mesh, std::uint32_t v, const MetricField2& field, const RelocateOptions& options = {});
// One sweep: every free vertex once, worst ball first. Returns the number of vertices moved.
std::uint64_t relocate_sweep(Mesh2& mesh, const MetricField2& field, const RelocateOptions& options = {});
// Consecutive sweeps with nothing but relocation between them (a round's relocation_sweeps): the
// same moves as relocate_sweep each time, without repeating what cannot change. Each ball's
// qualities are measured once and again only after a vertex of the ball moved (they serve the
// order and the attempt). The mesh may change between two sweeps only by relocations made here.
class RelocationSweeps {
 public:
  RelocationSweeps(Mesh2& mesh, const MetricField2& field, const RelocateOptions& options);
  std::uint64_t sweep();  // relocate_sweep's: the number of vertices moved

 private:
  void measure();  // the free vertices and their balls' qualities, before the first sweep
  // v's ring (Mesh2::ball's half-edges, as is_free found them: the topology stays during the
  // sweeps) and its triangles' qualities, measured again if a vertex of the ball moved.
  struct Ball {
    std::span<const std::uint32_t> ring;
    std::span<double> q;
  };
  Ball ball(std::uint32_t v);

  Mesh2& mesh_;
  const MetricField2& field_;
  RelocateOptions options_;
  std::vector<std::uint32_t> free_;     // the free vertices (optimize2d_detail::is_free), by id
  std::vector<std::uint32_t> start_;    // v's ball: rings_ and q_ in [start_[v], start_[v + 1])
  std::vector<std::uint32_t> rings_;    // the free vertices' rings, one after the other
  std::vector<double> q_;               // quality(v, origin, destination) of each ring half-edge
  std::vector<std::uint8_t> stale_;     // a vertex of v's ball moved since q_ was measured
};

// --- Collapse (book §8.3.5, edge suppression by reduction) -------------------------------------
struct CollapseOptions {
  double short_length = kShortEdgeLength;  // collapse_pass: edges shorter than this, in the metric
  double long_length = kLongEdgeLength;    // no new edge may be longer than this
  double quality_limit = kCollapseQualityLimit;
  double margin = kImprovementMargin;
  // try_boundary_collapse: how far the removed vertex may lie from the boundary edge that
  // replaces its two (an absolute distance; 0: exactly on it, by orient2d).
  double boundary_deviation = 0.0;
};
enum class CollapseCriterion : std::uint8_t {
  // The new worst Q_K of the ball is at most max(old worst, quality_limit): a size operation.
  NotWorse,
  // The new worst Q_K is strictly below the old worst (margin): a shape operation.
  Improve,
};
// Collapses the edge of h onto one of its ends: the other end (which must be free as in
// try_relocate) is removed and its triangles reconnected to the kept end; the two triangles of
// the edge disappear. Both directions are tried when both ends are free, the better result kept.
// Accepted when the link condition holds (the ends share exactly the two opposite vertices), every
// new triangle is positive, no new edge is longer than long_length, and the criterion holds.
bool try_collapse(Mesh2& mesh, std::uint32_t h, const CollapseOptions& options = {},
                  CollapseCriterion criterion = CollapseCriterion::NotWorse);
// Collapses every edge shorter than short_length, shortest first (edges made short by a collapse
// join the queue). Returns the number of collapses.
std::uint64_t collapse_pass(Mesh2& mesh, const CollapseOptions& options = {});

// --- Boundary collapse (book §9.3.1; boundary_collapse.cpp) --------------------------------------
// Removes boundary vertex v (kOnBoundary, not kFixed, exactly two constrained edges vu and vw of
// one reference) onto w or u along the boundary, whichever leaves the better domain triangles:
// every triangle around v (ghosts and exterior triangles included) takes the kept end, the two
// boundary edges become one with their reference. Accepted when v lies within
// options.boundary_deviation of the new boundary edge (0: on it, exactly), the link condition
// holds, every new finite triangle is positive, no new domain edge is longer than long_length and
// the domain triangles' worst Q_K stays at most max(old worst, quality_limit). True when done.
bool try_boundary_collapse(Mesh2& mesh, std::uint32_t v, const CollapseOptions& options = {});
// Collapses boundary edges shorter than short_length, shortest first. Returns the number done.
std::uint64_t boundary_collapse_pass(Mesh2& mesh, const CollapseOptions& options = {});

// --- Split (book §8.3.6) -----------------------------------------------------------------------
struct SplitOptions {
  double long_length = kLongEdgeLength;  // split_pass: edges longer than this, in the metric
  // No split makes an edge from the new vertex to an opposite vertex shorter than this: without
  // it, triangles beside an edge that may not be split (a long boundary edge) would be split
  // without end, ever flatter.
  double short_length = kShortEdgeLength;
  // A split that makes the pair's worst Q_K exceed both the old worst and quality_limit is taken
  // only if every new triangle keeps an altitude of at least min_height in the metric (thick:
  // the swaps after it improve it); otherwise, beside an edge that may not be split, splits
  // would flatten triangles without end.
  double quality_limit = kSplitQualityLimit;
  double min_height = 0.5 * kShortEdgeLength;
  // An edge longer than this is split without that guard (the default: never). Adaptation sets
  // 3 (adapt2d.cpp): beside a curved wall in a strongly anisotropic metric the wall's edges must be short
  // (a chord's sagitta is bounded by the small size), the first layer's triangles are thin in
  // the metric, and the splits of their long edges thin them further before the swaps improve
  // them. The flattening stays bounded: with a value above 2 sqrt2 the halves of an edge are split
  // unguarded only while they are still more than twice too long, at most log2(length) times.
  double unguarded_length = std::numeric_limits<double>::infinity();
  // Split constrained edges (and edges between regions) too: 1 -> 2 in each triangle beside the
  // edge (ghosts included), the constraint and its reference carried to both halves, the new
  // vertex kOnBoundary. Off by default: the boundary discretisation is the input's.
  bool boundary = false;
  // Where a boundary split puts its point (with `boundary`): given the constrained half-edge h
  // (in a domain triangle) and the chord point a + s (b - a), a point of the boundary's smooth
  // support (algorithms/adapt/boundary_curve2.hpp); empty: the chord point. A support point
  // that would make a new triangle non-positive is replaced by the chord point.
  std::function<Vec2(const Mesh2& mesh, std::uint32_t h, double s)> boundary_point;
  double swap_margin = kImprovementMargin;  // the swaps around each new vertex
  std::uint64_t max_vertices = 20'000'000;  // split_pass stops short of this many live vertices
};
// The point of edge ab where both halves have the same metric length, with the length varying
// geometrically along the edge (the interpolation of kernel/metric.hpp edge_length): a + s (b - a),
// s = ln((1 + r) / 2) / ln r, r = l_b / l_a (s = 1/2 when r = 1).
Vec2 metric_midpoint(const Vec2& a, const Metric2& ma, const Vec2& b, const Metric2& mb) noexcept;
// Splits the edge of h at its metric midpoint (metric from `field`, else interpolated from the
// ends): 2 -> 4. Refused (kNone) for a constrained edge or an edge between regions unless
// options.boundary, for an edge beside no domain triangle, when a new finite triangle would not
// be positive, when an edge from the new vertex to an opposite vertex would be shorter than
// options.short_length, or when the new domain triangles would be both worse (above the old
// pair's worst and options.quality_limit) and thin (an altitude below options.min_height in the
// metric). Returns the new vertex. No swaps here (split_pass does them).
// With options.boundary_point, a boundary split's point is the support's when valid; `fell_back`
// (optional) tells whether the chord point had to be taken instead.
std::uint32_t try_split(Mesh2& mesh, std::uint32_t h, const MetricField2& field, const SplitOptions& options = {},
                        bool* fell_back = nullptr);
struct SplitPassResult {
  std::uint64_t splits = 0;
  std::uint64_t swaps = 0;
  std::uint64_t support_fallbacks = 0;  // boundary splits on the chord: the support point was refused
  bool limit_reached = false;  // stopped at options.max_vertices
};
// Splits every edge longer than long_length, longest first, each followed by swaps on the edges
// around the new vertex; halves still too long join the queue.
SplitPassResult split_pass(Mesh2& mesh, const MetricField2& field, const SplitOptions& options = {});

// --- Swap with relocation (book §8.6.3, combined operators) -------------------------------------
// Swaps h's diagonal, then relocates the quadrilateral's free vertices (try_relocate), and keeps
// the result only when the worst Q_K over the balls of the four vertices strictly improves (by
// `margin`); otherwise restores the mesh exactly. For the bad triangles that neither a swap nor a
// relocation alone improves (a boundary vertex with too few triangles). True when kept.
bool try_swap_relocate(Mesh2& mesh, std::uint32_t h, const MetricField2& field, const RelocateOptions& options = {},
                       double margin = kImprovementMargin);

// --- Valence relaxation (book §8.3.7; Frey and Field 1991) ---------------------------------------
// Swaps the edges whose swap brings the degrees of the four vertices involved closer to their
// targets (6 inside; on the boundary 1 + the number of 60-degree sectors of the domain angle, at
// least 3), decided on the sum of squared deviations, when the swap is valid and does not make
// the pair's worst Q_K worse. One pass over the edges in storage order; returns the swaps.
std::uint64_t valence_pass(Mesh2& mesh);

}  // namespace dtlab
