// Medit ASCII meshes (.mesh, the format of INRIA's Medit viewer and libMeshb), 3D subset:
//
//   MeshVersionFormatted 2
//   Dimension 3
//   Vertices    n   then n lines  x y z ref
//   Edges       n   then n lines  v1 v2 ref          (vertex numbers from 1)
//   Triangles   n   then n lines  v1 v2 v3 ref
//   Tetrahedra  n   then n lines  v1 v2 v3 v4 ref    (positive: orient3d(v1, v2, v3, v4) > 0)
//   Quadrilaterals n then n lines v1 v2 v3 v4 ref    (read_medit3_surface only)
//   End
//
// The layout rules are the 2D reader's (medit.hpp): a keyword's value on its line or the next,
// '#' comments and blank lines anywhere, one entry per line, MeshVersionFormatted first,
// Dimension before Vertices, Vertices before the elements, End last. The sections of feature
// and attribute data (Corners, Ridges, Required*, Normals, NormalAtVertices, Tangents,
// TangentAtVertices, Identifier, Geometry, as TetGen's -g output and MMG's carry) are read,
// checked and dropped with a note each, as in medit.hpp. Anything else is a ParseError naming
// the line: Dimension 2 (a 2D mesh), an element section the mesh cannot hold (Hexahedra, Prisms,
// TetrahedraP2, ...), a skipped section's count or number out of range (a Ridges entry naming an
// edge past Edges' count, ...), an unknown keyword, a count that does not match the entries, a
// vertex number out of range, a coordinate outside kernel/coordinate_range.hpp, a tetrahedron that is not
// positive (negative or flat, decided exactly), text after End, or a file that ends before End.
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "mesh/io/mesh_data3.hpp"
#include "mesh/io/tetrahedron_orientation.hpp"
#include "mesh/io/tetgen_poly.hpp"

namespace dtlab {

// `file_name` names the input in error messages; `notes` as in read_medit2 (null: warnings on
// std::cerr); `tetrahedra`: Keep reads negative and flat tetrahedra as written.
MeshData3 read_medit3(std::istream& in, const std::string& file_name, std::vector<std::string>* notes = nullptr,
                      NonPositiveTetrahedra tetrahedra = NonPositiveTetrahedra::Refuse);
MeshData3 read_medit3(const std::string& path, std::vector<std::string>* notes = nullptr,
                      NonPositiveTetrahedra tetrahedra = NonPositiveTetrahedra::Refuse);

// A surface as a PLC (mesh/io/tetgen_poly.hpp): the same layout, with Quadrilaterals read too;
// one facet of one polygon per element, triangles first, then quadrilaterals, then edges (2-corner
// polygons), each with its reference as marker; vertex_markers = the vertex references. Planarity
// and simplicity of a quadrilateral are decided later, exactly
// (algorithms/constrained3d/plc/facet_triangulation.hpp). A file with Tetrahedra is an InputError (a
// volume mesh, not a surface).
Plc3 read_medit3_surface(std::istream& in, const std::string& file_name, std::vector<std::string>* notes = nullptr);
Plc3 read_medit3_surface(const std::string& path, std::vector<std::string>* notes = nullptr);

// Throws InputError naming the element if a vertex number is out of range or a refs vector is
// neither empty nor the size of its elements. Orientation is not checked here (the reader does).
void write_medit3(std::ostream& out, const MeshData3& mesh);
void write_medit3(const std::string& path, const MeshData3& mesh);

}  // namespace dtlab
