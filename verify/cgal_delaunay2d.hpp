// CGAL's 2D Delaunay triangulation (Delaunay_triangulation_2 over
// Exact_predicates_inexact_constructions_kernel) on dtlab's points, as the peer that tests and
// benchmarks compare every dtlab variant with. The CGAL code lives in cgal_delaunay2d.cpp only,
// so that including this header does not pull CGAL's headers into the caller.
#pragma once

#include <span>
#include <vector>

#include "kernel/vec.hpp"
#include "verify/checks2d.hpp"

namespace dtlab {

// The finite triangles of CGAL's Delaunay triangulation of `points`, counter-clockwise, as
// 0-based indices into `points`. Points are inserted with their indices as vertex info through
// CGAL's range insertion (which sorts them spatially). Coincident points make one vertex, which
// carries the smallest index among them (dtlab's convention for duplicates); if all points are
// collinear, or fewer than three are distinct, the result is empty. On cocircular input CGAL
// resolves ties by its own symbolic perturbation, which need not agree with dtlab's.
std::vector<TriangleIds> cgal_delaunay2d(std::span<const Vec2> points);

struct CgalDelaunay2dRun {
  std::vector<TriangleIds> triangles;  // as cgal_delaunay2d returns them
  double insert_seconds = 0.0;         // wall time of converting the points and inserting them
  double total_seconds = 0.0;          // the same plus reading the triangles out
};

// cgal_delaunay2d with the wall time of the construction measured apart from the read-out.
CgalDelaunay2dRun cgal_delaunay2d_timed(std::span<const Vec2> points);

}  // namespace dtlab
