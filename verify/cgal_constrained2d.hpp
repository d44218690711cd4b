// CGAL's constrained Delaunay triangulation (Constrained_Delaunay_triangulation_2) on dtlab's
// points and segments, the peer that tests compare dtlab's "cdt" method with. The CGAL code lives
// in cgal_constrained2d.cpp only, so that including this header does not pull CGAL's headers in.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec.hpp"
#include "verify/checks2d.hpp"

namespace dtlab {

enum class CgalCdtKernel {
  // Exact_predicates_inexact_constructions_kernel with CGAL's default intersection tag
  // (No_constraint_intersection_requiring_constructions_tag): the fast set-up for segments
  // that do not cross; a crossing throws InputError.
  Epick,
  // Exact_predicates_exact_constructions_kernel with Exact_intersections_tag: crossings are
  // inserted at their exact intersection points.
  EpeckExactIntersections,
};

struct CgalConstrained2d {
  // The input points, then the vertices CGAL created (crossings) in CGAL's vertex order, each
  // exact coordinate correctly rounded to double (kernel/rounding.hpp): what a user of CGAL who
  // writes its output in doubles gets.
  std::vector<Vec2> points;
  // Finite faces (the whole convex hull), counter-clockwise in CGAL's exact geometry, as ids
  // into points. Coincident input points make one vertex, carrying the smallest index.
  std::vector<TriangleIds> triangles;
  std::vector<std::array<std::uint32_t, 2>> constrained_edges;  // {a, b}, a < b, sorted
  std::size_t created_points = 0;
  double seconds = 0.0;  // converting the input, inserting the points and the constraints
};

// Points are inserted with their indices as vertex info by CGAL's range insertion (spatial
// sort), then each segment by insert_constraint between the two vertex handles.
CgalConstrained2d cgal_constrained2d(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 2>> segments,
                                     CgalCdtKernel kernel = CgalCdtKernel::Epick);

}  // namespace dtlab
