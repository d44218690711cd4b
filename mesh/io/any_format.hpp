// Reading and writing points and meshes of either dimension by file extension: the one facade
// that the command line (apps/), Python (python/) and the tests use, so that a format is added
// in one place (docs/architecture.md, "Where a new X goes").
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "kernel/vec.hpp"
#include "mesh/io/mesh_data.hpp"
#include "mesh/io/mesh_data3.hpp"
#include "mesh/io/tetrahedron_orientation.hpp"

namespace dtlab {

// Lower-case extension of a path, without the dot ("" if none).
std::string extension_of(std::string_view path);

// Medit binary .meshb and Gmsh .msh (a 2D mesh: no tetrahedra, every z = 0) are read and written
// beside the formats below, for 2D and 3D alike.
//
// 2 or 3: the dimension of a point or mesh input: a .mesh file's Dimension keyword, a .node or
// .poly file's header (Triangle's 2 or TetGen's 3; for a .ele, the .node's beside it), the
// numbers per line of a plain point file.
int input_dimension(const std::string& path);

// Whether `path` holds a 3D piecewise linear complex (a closed surface: .off .obj .stl .smesh, a
// TetGen .poly or a Medit .mesh of dimension 3) rather than a planar graph or a point set.
bool is_surface_input(const std::string& path);

// Points of a 2D input: Triangle .node, Medit .mesh (its Vertices), or a plain point file.
std::vector<Vec2> read_points2(const std::string& path);

// A 2D mesh: Medit .mesh, or Triangle .ele (with the .node beside it).
MeshData2 read_mesh2(const std::string& path);

// Writes Medit .mesh, or Triangle .node + .ele for OUT.ele / OUT.node; other extensions are an
// InputError naming the supported ones.
void write_mesh2(const std::string& path, const MeshData2& mesh);

// The 3D counterparts: points of a Medit .mesh (its Vertices), a TetGen .node or a plain
// "x y z" file; a 3D mesh from a Medit .mesh or a TetGen .ele (with the .node beside it); Medit
// .mesh or TetGen .node + .ele output.
// `tetrahedra`: Keep reads negative and flat tetrahedra of a Medit or Gmsh file as written (for
// `dtlab quality` to count them); a TetGen .ele is read with one orientation for the file.
std::vector<Vec3> read_points3(const std::string& path);
MeshData3 read_mesh3(const std::string& path, NonPositiveTetrahedra tetrahedra = NonPositiveTetrahedra::Refuse);
void write_mesh3(const std::string& path, const MeshData3& mesh);

}  // namespace dtlab
