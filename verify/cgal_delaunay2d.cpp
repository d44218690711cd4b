#include "verify/cgal_delaunay2d.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <utility>

namespace dtlab {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, DataStructure>;

// The finite faces of `dt` as triangles of input ids; where points were merged, each id is the
// smallest index with the vertex's coordinates.
std::vector<TriangleIds> read_triangles(const Delaunay& dt, std::span<const Vec2> points) {
  std::vector<TriangleIds> triangles;
  if (dt.dimension() < 2) return triangles;
  triangles.reserve(dt.number_of_faces());
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    // CGAL's faces are counter-clockwise, as dtlab's.
    triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  }
  if (dt.number_of_vertices() == points.size()) return triangles;
  // Some points coincided: CGAL kept whichever copy it inserted first, dtlab keeps the smallest
  // index. Map each used vertex to the smallest index at its coordinates.
  std::map<std::pair<double, double>, std::uint32_t> first;
  for (std::uint32_t i = 0; i < points.size(); ++i) first.emplace(std::pair{points[i].x, points[i].y}, i);
  for (TriangleIds& t : triangles) {
    for (std::uint32_t& v : t) v = first.at({points[v].x, points[v].y});
  }
  return triangles;
}

Delaunay build(std::span<const Vec2> points) {
  std::vector<std::pair<Kernel::Point_2, std::uint32_t>> input;
  input.reserve(points.size());
  for (std::uint32_t i = 0; i < points.size(); ++i) input.emplace_back(Kernel::Point_2(points[i].x, points[i].y), i);
  Delaunay dt;
  dt.insert(input.begin(), input.end());
  return dt;
}

}  // namespace

std::vector<TriangleIds> cgal_delaunay2d(std::span<const Vec2> points) {
  const Delaunay dt = build(points);
  return read_triangles(dt, points);
}

CgalDelaunay2dRun cgal_delaunay2d_timed(std::span<const Vec2> points) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const Delaunay dt = build(points);
  const auto built = Clock::now();
  CgalDelaunay2dRun run;
  run.triangles = read_triangles(dt, points);
  run.insert_seconds = std::chrono::duration<double>(built - start).count();
  run.total_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return run;
}

}  // namespace dtlab
