// The surface readers behind one call: a piecewise linear complex given as a triangulated
// surface (plus internal faces and edges), with volume holes and regions where the format has
// them, chosen by the file's extension (matched without regard to case):
//
//   .off           Geomview OFF (mesh/io/off_format.hpp): triangles only, refs 0
//   .stl           STL, ASCII or binary (mesh/io/stl_format.hpp): refs = solid number
//   .poly, .smesh  TetGen (mesh/io/tetgen_poly.hpp): facets triangulated by
//                  triangulate_plc_facets, refs = facet markers; holes and regions kept
//   .mesh          Medit 3D (mesh/io/medit3.hpp): Vertices, Triangles and Edges with their refs;
//                  a file with Tetrahedra is refused (it is a volume mesh, not a surface)
//
// Nothing is repaired or checked beyond what each reader checks: duplicate vertices, degenerate
// or intersecting faces and open surfaces are the PLC check's business. Another extension is an
// InputError listing the supported ones; a malformed file is the reader's ParseError.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/vec.hpp"
#include "mesh/io/mesh_data3.hpp"
#include "mesh/io/tetgen_poly.hpp"

namespace dtlab {

struct SurfaceInput {
  MeshData3 surface;                // vertices, triangles and edges with refs; no tetrahedra
  std::vector<Vec3> holes;          // volume holes (.poly, .smesh)
  std::vector<PlcRegion3> regions;  // region points with attribute and maximum volume (.poly, .smesh)
};

// ".off", ".stl", ".poly", ".smesh", ".mesh".
std::span<const std::string_view> surface_extensions();

SurfaceInput read_surface(const std::string& path);

}  // namespace dtlab
