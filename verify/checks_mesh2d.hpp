// Exact checks of a 2D mesher's output (algorithms/mesh2d), library code for the tests, the
// fuzzer, the benchmark and `dtlab mesh --verify`. Independent of the generator: it reads the
// output arrays and recomputes the constrained triangulation of the input.
//  - validity in doubles: every triangle strictly ccw (exact orient2d), no two vertices equal,
//    conformity (each edge in at most two triangles, with opposite orientations), the boundary
//    (edges in one triangle) made of output Edges only;
//  - constraints: every piece of an input segment in the input's constrained triangulation (split
//    at vertices and crossings) that has the domain on a side is a chain of output Edges, each step
//    forward, through vertices exactly on it (orient2d zero; preferred) or, for a resampled
//    boundary's rounded cut points, within a few ulps of its line; each Edge with the marker of a
//    segment along it;
//  - regions: each output triangle lies in the domain of the input's constrained Delaunay
//    triangulation, in a triangle of the same region: the one its interior meets next to its
//    first vertex, found by exact orient2d alone (so slivers between crossings that round within
//    ulps are placed right), or, for a triangle with a resampled boundary's rounded cut point,
//    the one holding its centroid;
//  - coverage: the output's area equals the domain's (relative 1e-9: both are sums in doubles).
#pragma once

#include <string>

#include "mesh/io/mesh_data.hpp"
#include "mesh/problems/constrained2.hpp"
#include "verify/problem_report.hpp"

namespace dtlab {

struct MeshCheckReport2 : ProblemReport {
  std::size_t vertices = 0, triangles = 0, edges = 0, segments = 0, chain_edges = 0, region_checks = 0;
  std::size_t exterior_segments = 0;  // input segments with no piece beside the domain (not meshed)
  double area = 0.0, domain_area = 0.0;
};

// `cdt`: the input's constrained Delaunay triangulation (constrained2d(input), method "cdt"): the
// reference of the regions, the coverage and the constraints.
MeshCheckReport2 check_mesh2d(const ConstrainedInput2& input, const Constrained2dResult& cdt, const MeshData2& output,
                              std::uint32_t first_number = 0);

std::string to_json(const MeshCheckReport2& report);
std::string to_text(const MeshCheckReport2& report);

}  // namespace dtlab
