// Lawson's edge flipping (Lawson 1977; George & Borouchaki §2, Theorem 2.2): flipping every
// interior edge that is not locally Delaunay, until none is left, turns any triangulation of a
// point set into its Delaunay triangulation. Here "locally Delaunay" is decided by
// incircle_perturbed, so the result is the perturbed Delaunay triangulation every dtlab variant
// produces, degenerate inputs included.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernel/vec.hpp"

namespace dtlab {

struct LawsonFlipStats {
  std::uint64_t flips = 0;
  std::uint64_t edge_tests = 0;  // incircle_perturbed calls
};

// vertices / neighbours: `triangles` triangles (ghosts included, numbering and contract of
// mesh/triangulation2.hpp, closed) over points[0 .. m-1], m distinct vertices, with a convex
// hull made of ghosts. Flips in place until every edge between two finite triangles is locally
// Delaunay. Storage stays where it is: triangle and half-edge slots are reused, nothing is
// allocated per flip. Throws InternalError past m(m-1)/2 flips (an edge flipped away never
// comes back, so more would mean a broken invariant).
LawsonFlipStats lawson_flip2(const Vec2* points, std::size_t m, std::uint32_t* vertices,
                             std::uint32_t* neighbours, std::size_t triangles);

// The statistics of this thread's last lawson_flip2 call (for tests and measurements).
LawsonFlipStats last_lawson_flip2_stats() noexcept;

}  // namespace dtlab
