// CGAL's 3D Delaunay triangulation as dtlab's benchmarks run it, shared by the two translation
// units that compile CGAL's headers (delaunay3d_cgal.cpp inside delaunay3d_bench, and the
// one-run process cgal_delaunay3d_run_bench.cpp). Include it from nowhere else.
//
// The set-up CGAL's manual recommends for speed: Exact_predicates_inexact_constructions_kernel,
// the input index as vertex info, the sequential data structure, and one range insertion of
// (point, index) pairs, which spatially sorts the points (BRIO with Hilbert order) first.
#pragma once

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab::bench::cgal3d {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_3<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, DataStructure>;

// The conversion of the input belongs to the measured work: dtlab's variants copy their input
// too. Duplicate points become one vertex (CGAL keeps the first one inserted).
inline void build(std::span<const Vec3> points, Delaunay& out) {
  std::vector<std::pair<Kernel::Point_3, std::uint32_t>> input;
  input.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    input.emplace_back(Kernel::Point_3(points[i].x, points[i].y, points[i].z), static_cast<std::uint32_t>(i));
  }
  out.insert(input.begin(), input.end());
}

}  // namespace dtlab::bench::cgal3d
