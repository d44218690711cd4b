// CGAL's remove() for removal_bench: the benchmark's only translation unit that compiles CGAL's
// headers. Vertex handles are found by the input index kept as vertex info.
#include "bench/removal_cgal.hpp"

#include <CGAL/version.h>

#include <chrono>
#include <vector>

#include "bench/delaunay2d_cgal_impl.hpp"
#include "bench/delaunay3d_cgal_impl.hpp"

namespace dtlab::bench {
namespace {

template <class Delaunay>
CgalRemoval remove_all(Delaunay& dt, std::size_t n, std::span<const std::uint32_t> order) {
  std::vector<typename Delaunay::Vertex_handle> handle(n);
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) handle[v->info()] = v;
  const auto t0 = std::chrono::steady_clock::now();
  for (const std::uint32_t i : order) dt.remove(handle[i]);
  CgalRemoval out;
  out.remove_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace

const char* cgal_removal_version() { return CGAL_VERSION_STR; }

CgalRemoval cgal_remove2d(std::span<const Vec2> points, std::span<const std::uint32_t> order) {
  cgal2d::Delaunay dt;
  cgal2d::build(points, dt);
  CgalRemoval out = remove_all(dt, points.size(), order);
  out.finite_elements = dt.number_of_faces();
  return out;
}

CgalRemoval cgal_remove3d(std::span<const Vec3> points, std::span<const std::uint32_t> order) {
  cgal3d::Delaunay dt;
  cgal3d::build(points, dt);
  CgalRemoval out = remove_all(dt, points.size(), order);
  out.finite_elements = dt.number_of_finite_cells();
  return out;
}

}  // namespace dtlab::bench
