// The CGAL side of constrained2d_bench (constrained2d_cgal.cpp, built only when CGAL is found):
// CGAL's Constrained_Delaunay_triangulation_2 on the same points and segments as dtlab's
// methods. No CGAL header here, so that constrained2d_bench.cpp compiles as a dtlab user's code.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "kernel/vec.hpp"

namespace dtlab::bench {

// CGAL's version string, for the benchmark's context.
const char* cgal_cdt_version();

// Builds CGAL's constrained Delaunay triangulation the way its manual recommends for speed
// (Exact_predicates_inexact_constructions_kernel, the default intersection tag: segments must
// not cross; the input index as vertex info, one range insertion of the points with spatial
// sort, then insert_constraint between vertex handles), frees it, and returns its finite
// triangle count (the whole convex hull, as dtlab's triangulation).
std::size_t cgal_cdt_triangles(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 2>> segments);

}  // namespace dtlab::bench
