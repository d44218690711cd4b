// Every crossing of the input segments, found at once and snap rounded onto the grid of doubles
// (Hobby, "Practical segment intersection with finite precision output", 1999; Guibas and
// Marimont, "Rounding arrangements dynamically", 1998). The grid's cells are the boxes of reals
// that round to one double point (the rounding box of kernel/rounding.hpp): a crossing's exact
// point is rounded correctly, and the rounded point is a "hot" point; then every segment is
// routed through every hot point whose box it meets, in order along it. Rerouted this way the
// chains of two segments meet only at shared points: a chain bent at a rounded crossing cannot
// pass over a neighbouring crossing of a cluster (three or more segments a few ulps from one
// point), which segment-by-segment rounding did, crossing again and again.
//
// Candidate pairs come from the triangulation (the Delaunay triangulation of the points, before
// any insertion): each segment is walked along its pipe (book §1.7), and two segments can cross
// only inside a triangle both pipes hold, so the work follows the mesh's own density (a uniform
// grid does not: long, dense segments share cells quadratically). The walk also gives the
// vertices exactly on each segment, which become stops too.
//
// Hot points are the rounded crossings and, once some crossing is not a double point (only then
// can a chain bend), every vertex of a segment's pipe whose rounding box the segment meets. Each
// chain vertex is within its rounding bound of its segment, so the chains pass the checks of
// verify/checks_constrained2d.hpp.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "algorithms/constrained2d/constrained_mesh.hpp"
#include "kernel/rounding.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

struct SnappedCrossings {
  // A rounded crossing: its double point and, for the messages and the rounding check, the
  // first pair of segments (indices into the segment list) whose exact crossing rounds to it.
  struct Hot {
    Vec2 point;
    ExactPoint2 exact;
    bool exact_double = false;
    std::uint32_t s = 0, t = 0;
  };
  // A point a segment is routed through: an input vertex id, or kHot + index into `hot`.
  static constexpr std::uint32_t kHot = 0x8000'0000u;
  std::vector<Hot> hot;  // distinct points, ordered by coordinates
  // Segment k's stops (vertices exactly on it, hot points it meets), strictly inside it, ordered
  // from its first endpoint to its second: stops[first[k] .. first[k + 1]).
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> stops;
  bool rounded = false;  // some crossing is not a double point
};

// `mesh`: the triangulation of the input vertices, not yet changed; `segments`: endpoint ids,
// none of zero length. Segments that touch at an endpoint or overlap collinearly are not
// crossings; proper crossings only, decided by exact orient2d.
SnappedCrossings snap_crossings(const ConstrainedMesh2& mesh, std::span<const std::array<std::uint32_t, 2>> segments);

// The ids of the stops strictly inside segment ab, ordered from a to b by the exact parameter of
// their points' projections (ties by id), each id once.
std::vector<std::uint32_t> order_along_segment(const Vec2& a, const Vec2& b,
                                               std::vector<std::pair<Vec2, std::uint32_t>> stops);

}  // namespace dtlab
