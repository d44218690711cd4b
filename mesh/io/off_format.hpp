// Geomview's OFF files (Object File Format), the ASCII subset that surface meshes use:
//
//   [ST][C][N]OFF          header keyword; the counts may follow on the same line
//   <#vertices> <#faces> <#edges>      (#edges is read and ignored, as Geomview does)
//   x y z [nx ny nz] [r g b [a]] [s t]  one vertex per line, numbered from 0 in file order
//   n v1 ... vn [colour]                one face per line; colour: 1, 3 or 4 numbers
//
// The prefixes add per-vertex data in that order (N: a normal, C: a colour of 3 or 4 numbers,
// ST: texture coordinates); it is read as numbers and not kept. Face colours are read and not
// kept either. '#' comments and blank lines may appear anywhere. Messages name vertices and
// faces by their 0-based number, as OFF itself does.
//
// read_off fills a MeshData3, which holds triangles, so there every face must have exactly 3
// vertices: a face with more is a polygon, refused by name with a ParseError. read_off_surface
// reads every face of 3 or more vertices as a PLC facet of one polygon (mesh/io/tetgen_poly.hpp:
// facet i is face i, corners in file order, marker 0); whether a polygon is planar and simple is
// not the reader's business (algorithms/constrained3d/plc/facet_triangulation.hpp decides it
// exactly). Refused by name in both: the
// 4OFF (4D) and nOFF (n-dimensional) variants, binary OFF ("OFF BINARY"), an unknown header.
// Every other deviation is a ParseError naming the file and line: counts that do not match the
// entries, a vertex number out of range, a coordinate outside kernel/coordinate_range.hpp, a
// face with fewer than 3 vertices, text after the last face. Nothing is repaired: repeated
// vertices, degenerate faces and open or non-manifold surfaces are the PLC check's business.
//
// The readers fill vertex_refs and triangle_refs (vertex_markers) with 0 (OFF has no references).
#pragma once

#include <istream>
#include <ostream>
#include <string>

#include "mesh/io/mesh_data3.hpp"
#include "mesh/io/tetgen_poly.hpp"

namespace dtlab {

// `file_name` names the input in error messages.
MeshData3 read_off(std::istream& in, const std::string& file_name);
MeshData3 read_off(const std::string& path);
Plc3 read_off_surface(std::istream& in, const std::string& file_name);
Plc3 read_off_surface(const std::string& path);

// Writes "OFF", the counts (0 edges), the vertices and the triangles. References have no place in
// OFF and are not written. Edges or tetrahedra (which OFF cannot hold), or a vertex number out of
// range, are an InputError.
void write_off(std::ostream& out, const MeshData3& mesh);
void write_off(const std::string& path, const MeshData3& mesh);

}  // namespace dtlab
