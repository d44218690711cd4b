// TetGen's .node, .ele and .face files (the formats of the TetGen mesher, as its documentation
// describes them; no code of TetGen is used).
//
//   .node: <#points> [<dimension = 3> [<#attributes> [<#boundary markers: 0 or 1>]]]
//          <point #> <x> <y> <z> [attributes...] [marker]
//   .ele:  <#tetrahedra> [<nodes per tetrahedron: 4 or 10> [<#region attributes>]]
//          <tetrahedron #> <n1> <n2> <n3> <n4> [<n5> ... <n10>] [attributes...]
//   .face: <#faces> [<#boundary markers: 0 or 1>]
//          <face #> <n1> <n2> <n3> [marker]
//
// Omitted header fields take TetGen's defaults (3, 0, 0; 4, 0; 0). Numbering starts at 0 or 1,
// as the first entry says, and then runs consecutively; node numbers refer to the .node's
// numbering. TetGen writes 0 or 1 region attributes; any count is read. The columns that -o2
// and -nn add to a .face without announcing them in its header are refused (trailing text).
//
// Orientation. TetGen's documentation of the .ele format does not state one in words (only a
// figure of the node numbering). TetGen itself keeps every tetrahedron (a, b, c, d) with
// the opposite-sign orient3d convention (orient3d(a, b, c, d) < 0), i.e. det(b-a, c-a, d-a) > 0, and writes the corners in
// that order; its -R switch writes them reversed. So a .ele from TetGen is positive in dtlab's
// sense (kernel/predicates.hpp, Medit's convention), and one written with -R is negative. The
// reader therefore decides each tetrahedron's orientation exactly and requires one sign for the
// whole file: TetGenElements::orientation records it, and to_mesh_data3 swaps n3 and n4 of every
// tetrahedron of a negative file, so that MeshData3 is always positive. A flat tetrahedron, or
// one whose sign differs from the first's, is a ParseError at its line.
//
// Any other deviation is also a ParseError naming the file and line: counts that do not match
// the entries, field counts other than the header announces, node numbers out of range,
// coordinates outside kernel/coordinate_range.hpp.
#pragma once

#include <array>
#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "kernel/sign.hpp"
#include "kernel/vec.hpp"
#include "mesh/io/mesh_data3.hpp"

namespace dtlab {

struct TetGenNodes {
  std::vector<Vec3> points;
  std::size_t attribute_count = 0;
  std::vector<double> attributes;  // attribute_count per point, point after point
  bool has_markers = false;
  std::vector<int> markers;  // one per point if has_markers, else empty
  int first_index = 1;       // 0 or 1: the number of the first point in the file
};

struct TetGenElements {
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;  // corners n1..n4, 0-based, file order
  std::vector<std::array<std::uint32_t, 6>> midside;     // n5..n10 of 10-node tetrahedra, 0-based
  std::size_t attribute_count = 0;
  std::vector<double> attributes;       // attribute_count per tetrahedron
  Sign orientation = Sign::Positive;    // orient3d(n1, n2, n3, n4) of every tetrahedron
  int first_index = 1;                  // numbering of the tetrahedra in the file
  int vertex_first_index = 1;           // numbering of the points they refer to
};

struct TetGenFaces {
  std::vector<std::array<std::uint32_t, 3>> triangles;  // 0-based
  bool has_markers = false;
  std::vector<int> markers;  // one per face if has_markers, else empty
  int first_index = 1;
  int vertex_first_index = 1;
};

// `file_name` names the input in error messages; node numbers are checked against `nodes`.
TetGenNodes read_tetgen_node(std::istream& in, const std::string& file_name);
TetGenNodes read_tetgen_node(const std::string& path);
TetGenElements read_tetgen_ele(std::istream& in, const std::string& file_name, const TetGenNodes& nodes);
TetGenElements read_tetgen_ele(const std::string& path, const TetGenNodes& nodes);
TetGenFaces read_tetgen_face(std::istream& in, const std::string& file_name, const TetGenNodes& nodes);
TetGenFaces read_tetgen_face(const std::string& path, const TetGenNodes& nodes);

// Writers number from first_index / vertex_first_index and write the corners as stored; sizes
// that do not match, node numbers out of range or a first index other than 0 or 1 are an
// InputError.
void write_tetgen_node(std::ostream& out, const TetGenNodes& nodes);
void write_tetgen_node(const std::string& path, const TetGenNodes& nodes);
void write_tetgen_ele(std::ostream& out, const TetGenElements& elements, std::size_t vertex_count);
void write_tetgen_ele(const std::string& path, const TetGenElements& elements, std::size_t vertex_count);
void write_tetgen_face(std::ostream& out, const TetGenFaces& faces, std::size_t vertex_count);
void write_tetgen_face(const std::string& path, const TetGenFaces& faces, std::size_t vertex_count);

// To and from the neutral container. Point markers become vertex_refs, face markers
// triangle_refs (0 without markers). The first region attribute becomes tetrahedron_refs when
// every tetrahedron's first attribute is an integer that fits an int (TetGen's region
// attributes are); otherwise tetrahedron_refs is all 0. Tetrahedra come out positive (see
// above). A 10-node mesh has midside nodes that MeshData3 cannot hold: an InputError. MeshData3
// edges have no place in these files and are not written.
MeshData3 to_mesh_data3(const TetGenNodes& nodes, const TetGenElements& elements, const TetGenFaces* faces = nullptr);
TetGenNodes to_tetgen_nodes(const MeshData3& mesh);        // markers = vertex_refs if any
TetGenElements to_tetgen_elements(const MeshData3& mesh);  // one attribute = tetrahedron_refs if any
TetGenFaces to_tetgen_faces(const MeshData3& mesh);        // markers = triangle_refs if any

// base + ".node", ".ele" and, if it exists, ".face"; the writer writes all three.
MeshData3 read_tetgen_mesh(const std::string& base);
void write_tetgen_mesh(const std::string& base, const MeshData3& mesh);

}  // namespace dtlab
