// The CGAL side of delaunay2d_bench (delaunay2d_cgal.cpp, built only when CGAL is found): CGAL's
// Delaunay_triangulation_2 on the same points as dtlab's variants. No CGAL header here, so that
// delaunay2d_bench.cpp compiles as a dtlab user's code does.
#pragma once

#include <cstddef>
#include <span>

#include "kernel/vec.hpp"

namespace dtlab::bench {

// CGAL's version string, for the benchmark's context.
const char* cgal_version();

// What cgal_delaunay2d_triangles returns: all stored faces (O(1), for the timed loop) or the
// finite ones (a walk around the hull: O(hull), which on circle input is every point).
enum class FaceCount { stored, finite };

// Builds CGAL's Delaunay triangulation of `points` (delaunay2d_cgal_impl.hpp: Epick, input index
// as vertex info, range insertion with spatial sort), frees it, and returns its face count.
std::size_t cgal_delaunay2d_triangles(std::span<const Vec2> points, FaceCount count);

}  // namespace dtlab::bench
