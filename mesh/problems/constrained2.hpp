// The problem types of constrained triangulation in 2D (book §3): what a planar straight line
// graph is as input and what a constrained triangulation is as a result. They sit below
// algorithms/ so that verify/ checks results without depending on the algorithms that make them;
// algorithms/constrained2d/constrained2d.hpp makes them, algorithms/mesh2d reads them.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/stats.hpp"
#include "kernel/vec.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

struct RegionSeed2 {
  Vec2 point;
  int attribute = 0;
};

struct ConstrainedInput2 {
  std::span<const Vec2> points;
  std::span<const std::array<std::uint32_t, 2>> segments;  // indices into points
  std::span<const int> segment_markers;                    // empty, or one per segment
  std::span<const Vec2> holes;                             // each eats the region holding it
  std::span<const RegionSeed2> regions;                    // each gives its region an attribute
};

struct ConstrainedEdge2 {
  std::uint32_t a = 0, b = 0;  // vertex ids, a < b
  std::uint32_t segment = 0;   // the input segment it comes from (the lowest-numbered one)
  int marker = 0;              // that segment's marker (0 if no markers were given)
  // One half-edge of it in Constrained2dResult::triangulation (kNone in shared_edges).
  std::uint32_t half_edge = Triangulation2::kNone;
};

// A crossing Steiner point made where two constrained chains, bent by earlier rounding, cross
// although their input segments do not cross there (the fallback of enforcement, which snap
// rounding leaves rare): the correctly rounded intersection of the lines through the two pieces
// (a0, a1) of segment `segments[0]` and (b0, b1) of `segments[1]`, as they were then.
struct BentCrossing2 {
  std::uint32_t vertex = 0;
  std::array<std::uint32_t, 2> segments{};
  std::array<std::uint32_t, 4> pieces{};  // a0, a1, b0, b1
};

struct Constrained2dResult {
  // Points: the input, in input order, then the Steiner points. Triangles: the whole convex hull
  // (closed by ghosts, the contract of mesh/triangulation2.hpp), exterior and holes included.
  Triangulation2 triangulation;
  // The domain: the finite triangles kept (ccw, vertex ids), and each one's region attribute
  // (0 outside every region seed).
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<int> triangle_region;
  // The same per stored triangle of `triangulation`, as Mesh2 takes it: the region, or
  // Mesh2::kExterior for ghosts and triangles outside the domain.
  std::vector<int> slot_regions;
  // Every constrained edge once: the input segments split at vertices, crossings and (for
  // "conforming") split points.
  std::vector<ConstrainedEdge2> constrained_edges;
  // The edges covered by more than one segment (collinear overlaps, chains sharing pieces after
  // rounding, the dropped duplicates of a segment): one entry per further segment, with its
  // marker, sorted; each such edge is in constrained_edges with its lowest-numbered segment.
  std::vector<ConstrainedEdge2> shared_edges;
  std::uint32_t input_point_count = 0;
  std::uint32_t crossing_steiner_points = 0;  // from segment crossings
  std::uint32_t split_steiner_points = 0;     // from conforming splits
  std::vector<BentCrossing2> bent_crossings;  // the crossing points made from pieces' lines
  // Steiner points on a crossing not within their rounding bound of the exact intersection
  // (must be 0; kept as a count so that tests and the CLI can check it).
  std::uint32_t rounding_checks_failed = 0;
  std::uint32_t flips = 0;  // edge swaps of enforcement and Delaunay restoration
  // What was found and done: duplicates, overlaps, crossings, ignored holes ... (at most
  // kMaxMessages kept; message_count counts all).
  static constexpr std::size_t kMaxMessages = 200;
  std::vector<std::string> messages;
  std::size_t message_count = 0;
  // Empty, or why there are no triangles (fewer than 3 distinct points, all collinear).
  std::string degenerate_message;
  PredicateStats predicate_stats;
  double seconds = 0.0;
};

}  // namespace dtlab
