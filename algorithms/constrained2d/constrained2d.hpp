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
#include "mesh/problems/constrained2.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

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

// Throws InputError (items 0-based, texts numbered from options.first_number) for: an unknown
// method; a point out of range (as delaunay2d); a segment endpoint out of range, a zero-length segment (equal indices or equal coordinates), a marker
// list of the wrong length; naming the segment. Duplicate segments are reported and one kept.
Constrained2dResult constrained2d(const ConstrainedInput2& input, const Constrained2dOptions& options = {});

}  // namespace dtlab
