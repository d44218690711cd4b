// STL files (stereolithography), ASCII and binary, into a triangle surface.
//
//   ASCII:  solid [name]                    Binary (little-endian):
//             facet normal nx ny nz           80-byte header (any content, "solid" included)
//               outer loop                    uint32 facet count n at byte 80
//                 vertex x y z   (3 times)    n facets of 50 bytes from byte 84: normal and
//               endloop                         3 vertices as float32 x y z, uint16 attribute
//             endfacet
//           endsolid [name]
//
// Encoding. A file is binary iff it has at least 84 bytes and exactly 84 + 50 n bytes, n being the
// count at byte 80; otherwise it must begin with "solid" and is read as ASCII. The "solid" prefix
// alone decides nothing, since many binary writers begin their header with it. An ASCII file
// cannot pass the size rule by chance unless it exceeds 27 GB: the bytes at 80..83 are text,
// so n >= 0x0a0a0a0a.
//
// Vertices. STL repeats every vertex in every facet that uses it. The reader merges two vertices
// only when their coordinates are bitwise identical doubles (so -0 and 0 stay apart, and nearly
// equal vertices are kept apart for the PLC check to name); vertices are numbered in order of
// first appearance. A binary file's float32 coordinates convert to doubles exactly; an ASCII
// file's decimal coordinates are read as doubles, not rounded to float.
//
// Ignored, as documented here: facet normals (binary: the 12 bytes; ASCII: the three tokens
// after "facet normal", which must be present but are not parsed, since some writers put "nan"
// there for degenerate facets) and the binary attribute byte count. Degenerate facets are kept:
// the PLC check names them. ASCII keywords are matched without regard to case; an ASCII file
// may hold several solids one after another, and triangle_refs numbers them from 0 (a binary
// file's refs are all 0). vertex_refs are 0.
//
// ParseError for everything else: in an ASCII file at its line; in a binary file the error's
// line() is the byte offset of the offending value, and the message says "byte". Refused: a
// file that is neither encoding (the message gives both rules), a missing or misplaced keyword,
// a facet with other than 3 vertices, a coordinate outside kernel/coordinate_range.hpp (float32
// subnormals, NaN and infinity included), text after the last endsolid.
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <string_view>

#include "mesh/io/mesh_data3.hpp"

namespace dtlab {

enum class StlEncoding { Ascii, Binary };

// The size rule above; the bytes are the whole file.
StlEncoding detect_stl_encoding(std::string_view bytes);

// `file_name` names the input in error messages.
MeshData3 read_stl(std::istream& in, const std::string& file_name);
MeshData3 read_stl(const std::string& path);

// Writes the triangles (with a unit normal computed in doubles, or 0 0 0 for a degenerate one),
// as one solid named "dtlab" in ASCII. Binary writes float32, so a coordinate that is not exactly
// a float is an InputError naming the vertex rather than a silent rounding. References have no
// place in STL and are not written, nor are vertices that no triangle uses. Edges or tetrahedra
// (which STL cannot hold), or a vertex number out of range, are an InputError.
void write_stl(std::ostream& out, const MeshData3& mesh, StlEncoding encoding);
void write_stl(const std::string& path, const MeshData3& mesh, StlEncoding encoding);

}  // namespace dtlab
