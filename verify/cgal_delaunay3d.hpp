// CGAL's 3D Delaunay triangulation (Delaunay_triangulation_3 over
// Exact_predicates_inexact_constructions_kernel) on dtlab's points, as the peer that tests and
// benchmarks compare every dtlab 3D variant with. The CGAL code lives in cgal_delaunay3d.cpp
// only, so that including this header does not pull CGAL's headers into the caller.
#pragma once

#include <span>
#include <vector>

#include "kernel/vec.hpp"
#include "verify/checks3d.hpp"

namespace dtlab {

// The finite cells of CGAL's Delaunay triangulation of `points` as 0-based indices into
// `points`, in CGAL's vertex order (positive: orient3d(v0, v1, v2, v3) > 0, dtlab's convention
// too). Points are inserted with their indices as vertex info through CGAL's range insertion
// (which sorts them spatially). Coincident points make one vertex, which carries the smallest
// index among them (dtlab's convention for duplicates); if all points are coplanar, or fewer than
// four are distinct, the result is empty. On cospherical input CGAL breaks ties by its own
// symbolic perturbation (Devillers and Teillaud 2011); cgal_delaunay3d_test.cpp records where
// it agrees with dtlab's.
std::vector<TetrahedronIds> cgal_delaunay3d(std::span<const Vec3> points);

struct CgalDelaunay3dRun {
  std::vector<TetrahedronIds> tetrahedra;  // as cgal_delaunay3d returns them
  double insert_seconds = 0.0;             // wall time of converting the points and inserting them
  double total_seconds = 0.0;              // the same plus reading the cells out
};

// cgal_delaunay3d with the wall time of the construction measured apart from the read-out.
CgalDelaunay3dRun cgal_delaunay3d_timed(std::span<const Vec3> points);

}  // namespace dtlab
