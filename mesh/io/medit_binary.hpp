// Medit binary meshes (.meshb, libMeshb's GMF binary encoding), the 2D and 3D subsets that
// mesh/io/medit.hpp and medit3.hpp read in ASCII:
//
//   int 1 (tells the byte order), int version 1-4; then keywords, each an int code, the file
//   offset of the next keyword (32 bits in versions 1-2, 64 bits in 3-4), and its data:
//     Dimension (3)   int 2 or 3
//     Vertices (4)    count, then per vertex: dimension reals, int ref
//     Edges (5)       count, then per edge: 2 ints (vertex numbers from 1), int ref
//     Triangles (6)   count, then 3 ints, int ref
//     Tetrahedra (8)  count, then 4 ints, int ref (3D only; positive, as in the ASCII files)
//     End (54)        offset 0, nothing after it
//   Reals are floats in version 1, doubles from 2; ints and counts are 32 bits up to version 3
//   and 64 bits in version 4. The binary reader of medit_sol.cpp shares this layout
//   (mesh/io/binary_input.hpp).
//
// The rules are the ASCII readers': Dimension before Vertices, Vertices before the elements, one
// section of each, End last, nothing after it. Anything else is a ParseError whose line() is
// the byte offset and whose message says "at byte": another keyword (Corners, Quadrilaterals,
// ... named by code and name), the other dimension, a count larger than the rest of the file can
// hold (refused before anything is allocated), a next-keyword offset that is not where the next
// keyword begins, a vertex number out of range, a coordinate outside kernel/coordinate_range.hpp,
// a tetrahedron that is negative or flat (decided exactly), a reference that does not fit an int.
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <string_view>

#include "mesh/io/mesh_data.hpp"
#include "mesh/io/mesh_data3.hpp"
#include "mesh/io/tetrahedron_orientation.hpp"

namespace dtlab {

// True iff the first word is 1 in either byte order (a binary Medit file).
bool is_medit_binary(std::string_view bytes) noexcept;

// The Dimension of a binary Medit file (2 or 3): a ParseError if the file has none before its
// first section, or is not a binary Medit file.
int medit_binary_dimension(std::string_view bytes, const std::string& file_name);
int medit_binary_dimension(const std::string& path);

// `file_name` names the input in error messages.
MeshData2 read_meshb2(std::istream& in, const std::string& file_name);
MeshData2 read_meshb2(const std::string& path);
// `tetrahedra`: Keep reads negative and flat tetrahedra as written.
MeshData3 read_meshb3(std::istream& in, const std::string& file_name,
                      NonPositiveTetrahedra tetrahedra = NonPositiveTetrahedra::Refuse);
MeshData3 read_meshb3(const std::string& path, NonPositiveTetrahedra tetrahedra = NonPositiveTetrahedra::Refuse);

// Writes `version` 2, 3 or 4 (doubles, little-endian), so that a write/read cycle keeps every
// bit. InputError naming the element if a vertex number is out of range, a refs vector is neither
// empty nor the size of its elements, or the file would need a larger version (version 2 has
// 32-bit offsets: 2 GiB at most; versions 2 and 3 count in 32 bits).
void write_meshb2(std::ostream& out, const MeshData2& mesh, int version = 2);
void write_meshb2(const std::string& path, const MeshData2& mesh, int version = 2);
void write_meshb3(std::ostream& out, const MeshData3& mesh, int version = 2);
void write_meshb3(const std::string& path, const MeshData3& mesh, int version = 2);

}  // namespace dtlab
