// Medit ASCII meshes (.mesh, the format of INRIA's Medit viewer and libMeshb), 2D subset:
//
//   MeshVersionFormatted 2
//   Dimension 2
//   Vertices    n   then n lines  x y ref
//   Edges       n   then n lines  v1 v2 ref         (vertex numbers from 1)
//   Triangles   n   then n lines  v1 v2 v3 ref
//   End
//
// The reader takes a keyword's value on the keyword's line or on the next line, '#' comments
// and blank lines anywhere; each entry must sit on a line of its own. MeshVersionFormatted must
// come first, Dimension before Vertices, Vertices before Edges and Triangles, and End last.
// Anything else is a ParseError naming the line: Dimension 3 (a 3D mesh), another Medit
// keyword this 2D reader does not keep (Corners, Quadrilaterals, ...), an unknown keyword, a
// count that does not match the entries, a vertex number out of range, a coordinate outside
// kernel/coordinate_range.hpp, text after End, or a file that ends before End.
#pragma once

#include <istream>
#include <ostream>
#include <string>

#include "mesh/io/mesh_data.hpp"

namespace dtlab {

// `file_name` names the input in error messages.
MeshData2 read_medit2(std::istream& in, const std::string& file_name);
MeshData2 read_medit2(const std::string& path);

// Throws InputError naming the element if a vertex number is out of range or a refs vector is
// neither empty nor the size of its elements.
void write_medit2(std::ostream& out, const MeshData2& mesh);
void write_medit2(const std::string& path, const MeshData2& mesh);

}  // namespace dtlab
