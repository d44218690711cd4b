// Gmsh meshes (.msh): MSH 4.1 read and written, ASCII and binary; MSH 2.2 (and 2.0, 2.1) read,
// ASCII and binary. The layout is the one of Gmsh's reference manual ("MSH file format"):
//
//   $MeshFormat      4.1 <0 ascii | 1 binary> 8   (binary: then the int 1, telling the byte order)
//   $PhysicalNames   count, then lines   dimension tag "name"        (ASCII in both encodings)
//   $Entities        points, curves, surfaces, volumes, each with its physical tags (4.1 only)
//   $Nodes           blocks of nodes, each classified on an entity: tags, then x y z [u v w]
//   $Elements        blocks of elements of one type on one entity: tag, node tags
//   (2.2: $Nodes  n, then  id x y z;  $Elements  n, then  id type ntags physical elementary ... nodes)
//
// What MeshData3 holds, and how: nodes are the vertices (all three coordinates, bit for bit);
// elements of type 15 (point) give the vertex references, 1 (2-node line) the edges, 2 (3-node
// triangle) the triangles, 4 (4-node tetrahedron) the tetrahedra. An element's reference is the
// physical tag of its entity (4.1; the first one, with a note, if there are several) or its
// first tag (2.2); 0 without one. Nodes and the elements of each kind come in the order of their
// tags, so that a file dtlab writes reads back in the order it was written. $PhysicalNames become
// `names`. Gmsh's tetrahedra are positive (orient3d > 0), as MeshData3's: a negative or flat one
// is refused, not reordered.
//
// Refused, with a ParseError naming the line (ASCII) or the byte (binary, "at byte N"): every
// element type MeshData3 cannot hold (quadrangles, hexahedra, prisms, pyramids, second- and
// higher-order elements, ...) by its element tag and type name; a node tag used twice or missing;
// counts that do not match the entries or exceed what the rest of the file can hold; MSH 4.0 and
// 3.0, data size other than 8, partitioned meshes ($PartitionedEntities); a coordinate outside
// kernel/coordinate_range.hpp; a section that does not end with its $End line; text after the
// last section. Sections that carry no mesh ($NodeData, $ElementData, $Periodic, ...) are skipped,
// and named in `notes`, so that a caller can say what was not kept.
#pragma once

#include <istream>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "mesh/io/mesh_data3.hpp"
#include "mesh/io/physical_names.hpp"
#include "mesh/io/tetrahedron_orientation.hpp"

namespace dtlab {

struct GmshMesh {
  MeshData3 mesh;  // a 2D mesh has z = 0 (mesh/io/planar_mesh.hpp)
  std::vector<PhysicalName> names;
  std::vector<std::string> notes;  // what the file held and the mesh does not keep
};

enum class GmshEncoding : std::uint8_t { Ascii, Binary };

// Either version and encoding, told by $MeshFormat; `file_name` names the input in messages;
// `tetrahedra`: Keep reads negative and flat tetrahedra as written.
GmshMesh read_gmsh(std::istream& in, const std::string& file_name,
                   NonPositiveTetrahedra tetrahedra = NonPositiveTetrahedra::Refuse);
GmshMesh read_gmsh(const std::string& path, NonPositiveTetrahedra tetrahedra = NonPositiveTetrahedra::Refuse);

// MSH 4.1. One entity per (dimension, reference) pair, whose physical tag is the reference (none
// for 0), and one point entity per vertex with a reference other than 0, holding a point
// element; one node block on the highest-dimensional entity; element tags number the edges, then
// the triangles, then the tetrahedra, in order. InputError naming the element for a vertex number
// out of range, a refs vector neither empty nor the size of its elements, or a negative reference
// (Gmsh's physical tags are positive).
void write_gmsh(std::ostream& out, const MeshData3& mesh, std::span<const PhysicalName> names,
                GmshEncoding encoding = GmshEncoding::Ascii);
void write_gmsh(const std::string& path, const MeshData3& mesh, std::span<const PhysicalName> names,
                GmshEncoding encoding = GmshEncoding::Ascii);

}  // namespace dtlab
