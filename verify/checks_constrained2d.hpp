// Exact checkers for constrained triangulations in 2D (algorithms/constrained2d), library code
// for the tests, the fuzzer, the benchmark and `dtlab constrain --verify`.
//
// What they prove, and why it is enough (book §3.1-§3.4; ROADMAP.md "Steiner points and
// rounding"):
//  - validity in doubles: the input points are the first points, unchanged; the finite triangles
//    are strictly ccw (exact orient2d), form a triangulated disk whose boundary is the convex hull
//    of the points (checks2d.hpp: together they cover the hull exactly once), and no two used
//    points coincide; the domain's triangles are some of them, its boundary runs along
//    constrained edges (and along the hull only where the exterior is kept);
//  - constraints: every input segment AB is a CHAIN of constrained edges from A to B, each step
//    forward along AB, through vertices on it: input vertices exactly on the open segment
//    (orient2d zero) or within their rounding bound of it (a crossing rounded onto one) or, on
//    the segment's own edges, of a piece between chain vertices around them (a bent piece that
//    ran exactly through one), Steiner vertices within their rounding bound of an exact point of AB (the
//    box of half-widths rounding_bound(x), rounding_bound(y) around the vertex meets the closed
//    segment, decided in rationals); a Steiner vertex on the chains of two crossing segments must
//    moreover lie within its rounding bound of their exact intersection (within_rounding_bound),
//    and every Steiner vertex must lie on some chain;
//  - the method's property: "cdt" every interior edge that is not constrained locally Delaunay
//    by the perturbed incircle (an edge's two triangles see every point visible from them, so
//    this is the constrained Delaunay property of Definition 3.6, Chew 1989), "conforming" every
//    interior edge locally Delaunay (the Delaunay triangulation, checks2d.hpp), "swap" none.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/problems/constrained2.hpp"
#include "verify/checks2d.hpp"
#include "verify/problem_report.hpp"

namespace dtlab {

struct ConstrainedCheckReport2 : ProblemReport {  // ok, problems (each naming its item), problem_count
  std::size_t points = 0;             // input and Steiner points
  std::size_t steiner_points = 0;
  std::size_t segments = 0;           // input segments whose chain was checked
  std::size_t chain_edges = 0;        // constrained edges on the chains found
  std::size_t constrained_edges = 0;
  std::size_t triangles = 0;          // finite triangles of the whole triangulation
  std::size_t domain_triangles = 0;
  std::size_t incircle_tests = 0;
  std::size_t rounding_checks = 0;    // Steiner points checked against an exact intersection

  // Appends other's problems, marked as numbered from 0.
  void merge(const CheckReport2& other);
};

struct ConstrainedCheckOptions2 {
  // The property to check: "cdt" constrained Delaunay, "conforming" Delaunay, anything else
  // ("swap") none beyond validity and constraints.
  std::string method = "cdt";
  // As given to constrained2d: with the exterior kept, the domain may end at the convex hull
  // along edges that are not constrained.
  bool keep_exterior = false;
  // The number of the first point and segment in problem texts: 0 for the API, the file's
  // numbering (1 for Medit, 0 or 1 for .poly) in the CLI.
  std::uint32_t first_number = 0;
};

// Validity in doubles: input points first and unchanged, finite triangles ccw and covering the
// convex hull once (checks2d), used points distinct, constrained edges mesh edges once each with
// valid segment ids and the segments' markers, domain triangles among the triangles with one
// region each, the domain's boundary on constrained (or, keeping the exterior, hull) edges,
// rounding_checks_failed zero. A degenerate result (no triangles) must come from collinear input.
ConstrainedCheckReport2 check_constrained_validity2(const ConstrainedInput2& input, const Constrained2dResult& result,
                                                   const ConstrainedCheckOptions2& options = {});

// Every input segment a chain of constrained edges through vertices on it; Steiner points
// within their rounding bounds (see above), each on some chain.
ConstrainedCheckReport2 check_constrained_chains2(const ConstrainedInput2& input, const Constrained2dResult& result,
                                                 const ConstrainedCheckOptions2& options = {});

// Every interior edge locally Delaunay under the perturbed incircle; constrained edges skipped
// when `skip_constrained` (the CDT property) and tested too when not (Delaunay).
ConstrainedCheckReport2 check_locally_delaunay2(const Constrained2dResult& result, bool skip_constrained,
                                               const ConstrainedCheckOptions2& options = {});

// All of the above, the property chosen by options.method. The chain and property checks run
// only when the triangulation is valid (they read its edges).
ConstrainedCheckReport2 verify_constrained2d(const ConstrainedInput2& input, const Constrained2dResult& result,
                                            const ConstrainedCheckOptions2& options = {});

// {"ok":true,"problem_count":0,"counts":{...},"problems":[...]}
std::string to_json(const ConstrainedCheckReport2& report);
// One summary line, then one problem per line.
std::string to_text(const ConstrainedCheckReport2& report);

}  // namespace dtlab
