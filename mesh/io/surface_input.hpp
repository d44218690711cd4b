// The surface readers behind one call: a piecewise linear complex (mesh/io/tetgen_poly.hpp: facets
// made of polygons, with volume holes and regions where the format has them), chosen by the
// file's extension (matched without regard to case):
//
//   .off           Geomview OFF (mesh/io/off_format.hpp, read_off_surface): each face a facet of
//                  one polygon (3 or more corners), markers 0
//   .obj           Wavefront OBJ (mesh/io/obj_format.hpp): each face (3 or more corners) a facet of
//                  one polygon, each polyline piece a facet of one segment, markers 0; named
//                  "facet N" in file order from 1 (faces and polyline pieces together)
//   .stl           STL, ASCII or binary (mesh/io/stl_format.hpp): each triangle a facet, marker =
//                  solid number
//   .poly, .smesh  TetGen (mesh/io/tetgen_poly.hpp): facets as the file gives them (several
//                  polygons, segments, isolated vertices, facet holes), markers; holes and regions
//   .mesh          Medit 3D (mesh/io/medit3.hpp, read_medit3_surface): Vertices, Triangles,
//                  Quadrilaterals and Edges with their refs (an edge a facet of one 2-corner
//                  polygon); a file with Tetrahedra is refused (a volume mesh, not a surface)
//
// The readers carry polygons; they do not triangulate them. Planarity and simplicity of a facet,
// its triangulation in its plane (algorithms/constrained3d/plc/facet_triangulation.hpp), duplicate
// vertices, intersecting facets and open surfaces (algorithms/constrained3d/plc/plc_checks.hpp) are
// decided later, exactly, and named. Another extension is an InputError listing the supported
// ones; a malformed file is the reader's ParseError.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/io/tetgen_poly.hpp"

namespace dtlab {

// Facets from `begin` on (up to the next section) are named "<noun> <number>", the first one
// `first_number`: how the file itself numbers them ("face 0" in OFF, "quadrilateral 1" in Medit).
struct FacetSection {
  std::size_t begin = 0;
  std::string noun = "facet";
  std::uint32_t first_number = 1;

  friend bool operator==(const FacetSection&, const FacetSection&) = default;
};

struct SurfaceInput {
  Plc3 plc;
  std::vector<FacetSection> sections;  // sorted by begin; empty: "facet 1", "facet 2", ...
  std::uint32_t first_vertex_number = 1;  // how the file numbers its vertices (OFF: 0)

  // Facet f (0-based) as the file names it.
  std::string facet_name(std::size_t f) const;
};

// ".off", ".obj", ".stl", ".poly", ".smesh", ".mesh".
std::span<const std::string_view> surface_extensions();

// The surface of `path` by its extension; an InputError naming the file for an unknown
// extension or a surface with no facets.
SurfaceInput read_surface(const std::string& path);

// A triangle surface (MeshData3, as read_stl gives it) as a PLC: each triangle a facet of one
// polygon with its reference as marker, then each edge a facet of one 2-corner polygon;
// vertex_markers = vertex_refs. Tetrahedra are not a surface: InputError.
Plc3 plc_from_triangles(const MeshData3& mesh);

}  // namespace dtlab
