#include "verify/cgal_delaunay3d.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <tuple>
#include <utility>

namespace dtlab {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_3<VertexBase, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, DataStructure>;

// The finite cells of `dt` as tetrahedra of input ids; where points were merged, each id is the
// smallest index with the vertex's coordinates.
std::vector<TetrahedronIds> read_tetrahedra(const Delaunay& dt, std::span<const Vec3> points) {
  std::vector<TetrahedronIds> tetrahedra;
  if (dt.dimension() < 3) return tetrahedra;
  tetrahedra.reserve(dt.number_of_finite_cells());
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    tetrahedra.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
  }
  if (dt.number_of_vertices() == points.size()) return tetrahedra;
  // Some points coincided: CGAL kept whichever copy it inserted first, dtlab keeps the smallest
  // index. Map each used vertex to the smallest index at its coordinates.
  std::map<std::tuple<double, double, double>, std::uint32_t> first;
  for (std::uint32_t i = 0; i < points.size(); ++i) first.emplace(std::tuple{points[i].x, points[i].y, points[i].z}, i);
  for (TetrahedronIds& t : tetrahedra) {
    for (std::uint32_t& v : t) v = first.at({points[v].x, points[v].y, points[v].z});
  }
  return tetrahedra;
}

Delaunay build(std::span<const Vec3> points) {
  std::vector<std::pair<Kernel::Point_3, std::uint32_t>> input;
  input.reserve(points.size());
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    input.emplace_back(Kernel::Point_3(points[i].x, points[i].y, points[i].z), i);
  }
  Delaunay dt;
  dt.insert(input.begin(), input.end());
  return dt;
}

}  // namespace

std::vector<TetrahedronIds> cgal_delaunay3d(std::span<const Vec3> points) {
  const Delaunay dt = build(points);
  return read_tetrahedra(dt, points);
}

CgalDelaunay3dRun cgal_delaunay3d_timed(std::span<const Vec3> points) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const Delaunay dt = build(points);
  const auto built = Clock::now();
  CgalDelaunay3dRun run;
  run.tetrahedra = read_tetrahedra(dt, points);
  run.insert_seconds = std::chrono::duration<double>(built - start).count();
  run.total_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return run;
}

}  // namespace dtlab
