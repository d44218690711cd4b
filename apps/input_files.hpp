// Reading the inputs and writing the outputs of the subcommands, by file extension.
#pragma once

#include <string>
#include <vector>

#include "kernel/vec.hpp"
#include "mesh/io/mesh_data.hpp"
#include "mesh/io/mesh_data3.hpp"

namespace dtlab::cli {

// Medit binary .meshb and Gmsh .msh (a 2D mesh: no tetrahedra, every z = 0) are read and written
// beside the formats below, for 2D and 3D alike.
//
// 2 or 3: the dimension of a point or mesh input: a .mesh file's Dimension keyword, a .node or
// .poly file's header (Triangle's 2 or TetGen's 3), the numbers per line of a plain point file.
int input_dimension(const std::string& path);

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
std::vector<Vec3> read_points3(const std::string& path);
MeshData3 read_mesh3(const std::string& path);
void write_mesh3(const std::string& path, const MeshData3& mesh);

}  // namespace dtlab::cli
