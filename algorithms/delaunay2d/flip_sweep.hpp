// A triangulation of a point set built with orientation tests only, the starting point of
// Lawson's flip algorithm (George & Borouchaki §2, Theorem 2.2): the points are taken in
// lexicographic order, and each one, a vertex of the hull of those before it, is joined to the
// hull edges it sees, which turns their ghosts into triangles (a "fan" sweep).
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernel/vec.hpp"

namespace dtlab {

// points[0 .. m-1]: distinct, sorted lexicographically (x, then y), not all collinear. Writes
// the 2m - 2 triangles (ghosts included, see mesh/triangulation2.hpp for the numbering) into
// vertices[0 .. 6m-7] and neighbours[0 .. 6m-7], vertex ids being indices into points. Points on
// the hull's edges are hull vertices. Exact orient2d only; throws InternalError on a broken
// invariant.
void sweep_triangulate2(const Vec2* points, std::size_t m, std::uint32_t* vertices, std::uint32_t* neighbours);

}  // namespace dtlab
