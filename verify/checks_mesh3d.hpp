// Exact checks of a 3D mesher's output (algorithms/mesh3d), library code for the tests, the
// benchmark and `dtlab mesh --verify`. Independent of the generator: it reads the output arrays
// and recomputes the input's recovered tetrahedralization.
//  - validity: every vertex distinct, every tetrahedron positive (exact orient3d);
//  - conformity: every facet in one or two tetrahedra, two with opposite orientations; every
//    facet in one tetrahedron (the domain's boundary) and every facet between two references is
//    an output triangle, and every output triangle is a facet of the tetrahedra;
//  - the boundary: the input's recovered tetrahedralization (the empty mesh) is recomputed and
//    checked exactly (verify/checks_constrained3d.hpp: its pieces triangulate the input triangles
//    exactly, its Steiner points within their rounding bounds); every output triangle is one of
//    its pieces (the same three points: the input triangle itself, or a piece where recovery put
//    Steiner points) with its reference, or a tile of one (the surface cut in the size: its
//    vertices on the piece's plane within the rounding of its cut points, surface_tiles3.hpp, its
//    centroid inside it) with its reference; every piece beside the domain is an output
//    triangle or covered by its tiles (their areas sum to its area, relative 1e-9);
//  - regions: the volume of each reference equals that region's volume in the input's recovered
//    tetrahedralization (relative 1e-9 of the whole volume: sums in doubles; exact coverage
//    follows from conformity with the boundary identical), the same set of references;
//  - statistics recomputed from the output (mesh/mesh_quality.hpp).
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "mesh/problems/constrained3.hpp"
#include "mesh/mesh_quality.hpp"
#include "verify/problem_report.hpp"

namespace dtlab {

struct MeshCheckReport3 : ProblemReport {
  std::size_t vertices = 0, tetrahedra = 0, triangles = 0, interior_facets = 0, boundary_facets = 0;
  std::size_t identical_triangles = 0;  // output triangles equal to an input triangle
  std::size_t piece_triangles = 0;      // output triangles strictly inside one (Steiner points)
  std::size_t tile_triangles = 0;       // output triangles inside a piece (the surface cut in the size)
  std::size_t regions = 0;
  double volume = 0.0, domain_volume = 0.0;
  QualityReport quality;  // recomputed from the output (with `metrics` when given)
};

struct MeshCheckOptions3 {
  bool remove_cavities = false;   // as the mesher was told (Mesh3dOptions::remove_cavities)
  std::uint32_t first_number = 1;  // how messages number items (Medit: 1)
};

// `recovered`: the input's boundary recovery (constrained3d with method "recover", as
// recover_domain in algorithms/mesh3d/mesh3d.hpp makes it), itself checked exactly here and the
// reference of the output's boundary. `metrics`: empty, or one per output vertex (the quality is
// then measured in them).
MeshCheckReport3 check_mesh3d(const ConstrainedInput3& input, const Constrained3dResult& recovered,
                              const MeshData3& output, std::span<const Metric3> metrics = {},
                              const MeshCheckOptions3& options = {});

std::string to_json(const MeshCheckReport3& report);
std::string to_text(const MeshCheckReport3& report);

}  // namespace dtlab
