// CGAL's Delaunay_triangulation_3 for delaunay3d_bench: the benchmark's only translation unit
// that compiles CGAL's headers (delaunay3d_cgal_impl.hpp says how CGAL is set up).
#include "bench/delaunay3d_cgal.hpp"

#include <CGAL/version.h>

#include "bench/delaunay3d_cgal_impl.hpp"

namespace dtlab::bench {

const char* cgal_version() { return CGAL_VERSION_STR; }

std::size_t cgal_delaunay3d_tetrahedra(std::span<const Vec3> points, CellCount count) {
  cgal3d::Delaunay dt;
  cgal3d::build(points, dt);
  return count == CellCount::finite ? dt.number_of_finite_cells() : dt.tds().number_of_cells();
}

}  // namespace dtlab::bench
