// Reading the inputs and writing the outputs of the subcommands, by file extension.
#pragma once

#include <string>
#include <vector>

#include "kernel/vec.hpp"
#include "mesh/io/mesh_data.hpp"

namespace dtlab::cli {

// 2 or 3: the dimension of a point input (.node and .mesh files are 2D for now; a plain point
// file has 2 or 3 numbers per line).
int input_dimension(const std::string& path);

// Points of a 2D input: Triangle .node, Medit .mesh (its Vertices), or a plain point file.
std::vector<Vec2> read_points2(const std::string& path);

// A 2D mesh: Medit .mesh, or Triangle .ele (with the .node beside it).
MeshData2 read_mesh2(const std::string& path);

// Writes Medit .mesh, or Triangle .node + .ele for OUT.ele / OUT.node; other extensions are an
// InputError naming the supported ones.
void write_mesh2(const std::string& path, const MeshData2& mesh);

}  // namespace dtlab::cli
