// The CGAL side of delaunay3d_bench (delaunay3d_cgal.cpp, built only when CGAL is found): CGAL's
// Delaunay_triangulation_3 on the same points as dtlab's variants. No CGAL header here, so that
// delaunay3d_bench.cpp compiles as a dtlab user's code does.
#pragma once

#include <cstddef>
#include <span>

#include "kernel/vec.hpp"

namespace dtlab::bench {

// CGAL's version string, for the benchmark's context.
const char* cgal_version();

// What cgal_delaunay3d_tetrahedra returns: all stored cells (O(1), for the timed loop) or the
// finite ones (CGAL counts them by iterating over the cells).
enum class CellCount { stored, finite };

// Builds CGAL's Delaunay triangulation of `points` (delaunay3d_cgal_impl.hpp: Epick, input index
// as vertex info, range insertion with spatial sort), frees it, and returns its cell count.
std::size_t cgal_delaunay3d_tetrahedra(std::span<const Vec3> points, CellCount count);

}  // namespace dtlab::bench
