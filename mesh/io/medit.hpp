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
// Sections of feature and attribute data (Corners, Ridges, RequiredVertices, RequiredEdges,
// RequiredTriangles, Normals, NormalAtVertices, Tangents, TangentAtVertices, Identifier,
// Geometry; layouts in text_input.hpp's MeditSkippedSections) are read, checked and dropped,
// each with a note that names it and its count. Anything else is a ParseError naming the line:
// Dimension 3 (a 3D mesh), an element section this 2D reader does not keep (Quadrilaterals,
// EdgesP2, ...), a skipped section's count or number out of range, an unknown keyword, a
// count that does not match the entries, a vertex number out of range, a coordinate outside
// kernel/coordinate_range.hpp, text after End, or a file that ends before End.
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "mesh/io/mesh_data.hpp"

namespace dtlab {

// `file_name` names the input in error messages. `notes` receives one line per skipped section
// ("section Corners skipped (4 entries from line 12: corner vertices)"); when it is null, each
// note is written to std::cerr as "warning: <file>: <note>" (io::deliver_notes).
MeshData2 read_medit2(std::istream& in, const std::string& file_name, std::vector<std::string>* notes = nullptr);
MeshData2 read_medit2(const std::string& path, std::vector<std::string>* notes = nullptr);

// Throws InputError naming the element if a vertex number is out of range or a refs vector is
// neither empty nor the size of its elements.
void write_medit2(std::ostream& out, const MeshData2& mesh);
void write_medit2(const std::string& path, const MeshData2& mesh);

}  // namespace dtlab
