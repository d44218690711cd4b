// Triangle's .node and .ele files (the formats of Shewchuk's Triangle, as its documentation
// describes them; no code of Triangle is used).
//
//   .node: header  <#vertices> [<dimension = 2> [<#attributes> [<#boundary markers: 0 or 1>]]]
//          lines   <vertex #> <x> <y> [attributes...] [marker]
//   .ele:  header  <#triangles> [<nodes per triangle: 3 or 6> [<#attributes>]]
//          lines   <triangle #> <n1> <n2> <n3> [<n4> <n5> <n6>] [attributes...]
//
// Omitted header fields take Triangle's defaults (2, 0, 0 and 3, 0). Numbering starts at 0 or 1,
// as the first entry's number says (Triangle's rule), and must then run consecutively. Node
// numbers in a .ele refer to the .node's numbering. Blank lines and '#' comments may appear
// anywhere; each entry sits on one line with exactly the fields its header announces. Any
// deviation is a ParseError naming the file and line.
#pragma once

#include <array>
#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "mesh/io/mesh_data.hpp"

namespace dtlab {

struct TriangleNodes {
  std::vector<Vec2> points;
  std::size_t attribute_count = 0;
  std::vector<double> attributes;  // attribute_count per point, point after point
  bool has_markers = false;
  std::vector<int> markers;  // one per point if has_markers, else empty
  int first_index = 1;       // 0 or 1: the number of the first vertex in the file
};

struct TriangleElements {
  std::vector<std::array<std::uint32_t, 3>> triangles;  // corners, 0-based
  std::vector<std::array<std::uint32_t, 3>> midside;    // nodes 4-6 of 6-node triangles, 0-based
  std::size_t attribute_count = 0;
  std::vector<double> attributes;  // attribute_count per triangle
  int first_index = 1;             // numbering of the triangles in the file
  int vertex_first_index = 1;      // numbering of the vertices they refer to
};

// `file_name` names the input in error messages.
TriangleNodes read_triangle_node(std::istream& in, const std::string& file_name);
TriangleNodes read_triangle_node(const std::string& path);
// Node numbers are checked against `nodes` (count and numbering).
TriangleElements read_triangle_ele(std::istream& in, const std::string& file_name, const TriangleNodes& nodes);
TriangleElements read_triangle_ele(const std::string& path, const TriangleNodes& nodes);

// Writers number from first_index / vertex_first_index; malformed data is an InputError.
void write_triangle_node(std::ostream& out, const TriangleNodes& nodes);
void write_triangle_node(const std::string& path, const TriangleNodes& nodes);
void write_triangle_ele(std::ostream& out, const TriangleElements& elements, std::size_t vertex_count);
void write_triangle_ele(const std::string& path, const TriangleElements& elements, std::size_t vertex_count);

// To and from the neutral container. Markers become vertex_refs (0 without markers). The first
// element attribute becomes triangle_refs when every triangle's first attribute is an integer
// that fits an int (Triangle's regional attributes are written so); otherwise triangle_refs is
// all 0 and the attributes stay in TriangleElements. Midside nodes have no place in MeshData2:
// converting a 6-node mesh is an InputError. Edges are not part of .node/.ele.
MeshData2 to_mesh_data(const TriangleNodes& nodes, const TriangleElements& elements);
TriangleNodes to_triangle_nodes(const MeshData2& mesh);         // markers = vertex_refs if any
TriangleElements to_triangle_elements(const MeshData2& mesh);   // one attribute = triangle_refs if any

// base + ".node" and base + ".ele".
MeshData2 read_triangle_mesh(const std::string& base);
void write_triangle_mesh(const std::string& base, const MeshData2& mesh);

}  // namespace dtlab
