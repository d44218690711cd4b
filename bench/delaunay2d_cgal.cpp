// CGAL's Delaunay_triangulation_2 for delaunay2d_bench: the benchmark's only translation unit
// that compiles CGAL's headers (delaunay2d_cgal_impl.hpp says how CGAL is set up).
#include "bench/delaunay2d_cgal.hpp"

#include <CGAL/version.h>

#include "bench/delaunay2d_cgal_impl.hpp"

namespace dtlab::bench {

const char* cgal_version() { return CGAL_VERSION_STR; }

std::size_t cgal_delaunay2d_triangles(std::span<const Vec2> points, FaceCount count) {
  cgal2d::Delaunay dt;
  cgal2d::build(points, dt);
  return count == FaceCount::finite ? dt.number_of_faces() : dt.tds().number_of_faces();
}

}  // namespace dtlab::bench
