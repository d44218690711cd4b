// CGAL's Constrained_Delaunay_triangulation_2 for constrained2d_bench: the benchmark's only
// translation unit that compiles CGAL's headers (constrained2d_cgal.hpp says how it is set up).
#include "bench/constrained2d_cgal.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/version.h>

#include <utility>
#include <vector>

namespace dtlab::bench {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, DataStructure>;

}  // namespace

const char* cgal_cdt_version() { return CGAL_VERSION_STR; }

std::size_t cgal_cdt_triangles(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 2>> segments) {
  // The conversion of the input belongs to the measured work: dtlab copies its input too.
  std::vector<std::pair<Kernel::Point_2, std::uint32_t>> input;
  input.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    input.emplace_back(Kernel::Point_2(points[i].x, points[i].y), static_cast<std::uint32_t>(i));
  Cdt cdt;
  cdt.insert(input.begin(), input.end());
  std::vector<Cdt::Vertex_handle> handle(points.size());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) handle[v->info()] = v;
  for (const auto& [a, b] : segments) cdt.insert_constraint(handle[a], handle[b]);
  return cdt.number_of_faces();
}

}  // namespace dtlab::bench
