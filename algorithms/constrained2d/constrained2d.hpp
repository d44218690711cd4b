// Constrained triangulation in 2D (book §3.1-§3.4) and the empty mesh of a domain (§5.2): the
// public entry point. One call, any registered method (registry.hpp), one result for all.
//
//   dtlab::ConstrainedInput2 in{.points = pts, .segments = segs};
//   dtlab::Constrained2dResult r = dtlab::constrained2d(in, {.method = "cdt"});
//   for (auto [a, b, c] : r.triangles) ...          // the domain's triangles, ccw
//   for (auto e : r.constrained_edges) ...          // e.a, e.b, e.marker
//
// Input segments are resolved before any method runs its own step (enforce.cpp): a segment
// through an input vertex is split there (exact orient2d); collinear overlapping segments become
// the pieces of their union, each piece keeping the marker of the LOWEST-NUMBERED input segment
// that covers it; crossing segments are split at their exact intersection, correctly rounded to
// double (kernel/rounding.hpp), which becomes a Steiner vertex both segments pass through.
//
// Straightness under rounding (ROADMAP.md, "Steiner points and rounding"): the rounded point is
// the truth. A segment is represented by the CHAIN of straight mesh edges through its vertices;
// a chain may bend at a vertex by at most that vertex's rounding bound (checked exactly with
// within_rounding_bound against the exact intersection of the two input segments' lines, and
// counted in rounding_checks_failed, which must stay 0). The crossings are snap rounded
// (crossings.hpp, Hobby 1999): once some crossing is not a double point, every segment also
// passes through each rounded crossing and each nearby segment endpoint whose rounding box it
// meets, so that bent chains meet only at shared vertices, even in clusters of crossings a few
// ulps apart. Every triangle is built by the exact predicates on the rounded coordinates, so the
// output is a valid mesh in doubles whatever the bend; a crossing of chains that snapping did not
// prevent is split where met, within a bound (enforce.cpp).
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

struct Constrained2dOptions {
  std::string method = "cdt";  // a name from constrained2d_methods(): "cdt", "swap", "conforming"
  bool keep_exterior = false;  // keep the triangles outside every constrained boundary
  std::uint64_t seed = 0x5EED'D71A'B000'0001ull;  // for the initial Delaunay triangulation
  // The order in which the edges crossing a missing piece are swapped (book §3.3.3): false, a
  // queue (Sloan 1993: the crossed edges in pipe order, each swapped when its quadrilateral is
  // convex, requeued while it still crosses); true, a random crossed edge each time (drawn from
  // a generator seeded with `seed`, so a run is reproducible).
  bool random_swaps = false;
  // Conforming only: the most Steiner points its splitting may add, as a multiple of
  // (points + segments); past it constrained2d throws InputError naming the segment.
  std::uint32_t conforming_steiner_factor = 64;
  // The number of the first point, segment, hole and region in messages and error texts: 0 for
  // the API (as InputError::items), the input file's numbering in the CLI (Medit 1, .poly 0 or 1).
  std::uint32_t first_number = 0;
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

// Throws InputError (items 0-based, texts numbered from options.first_number) for: an unknown
// method; a point out of range (as delaunay2d); a segment endpoint out of range, a zero-length segment (equal indices or equal coordinates), a marker
// list of the wrong length; naming the segment. Duplicate segments are reported and one kept.
Constrained2dResult constrained2d(const ConstrainedInput2& input, const Constrained2dOptions& options = {});

}  // namespace dtlab
