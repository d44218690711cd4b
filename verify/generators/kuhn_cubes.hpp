// Tetrahedral meshes made of unit cubes: each cube at an integer corner cut into Kuhn's
// (Freudenthal's) 6 positive tetrahedra around its main diagonal, conforming across cubes. Any
// union of cells: convex blocks, an L, a ring around a hole (non-convex backgrounds for tests).
#pragma once

#include <array>
#include <vector>

#include "mesh/io/mesh_data3.hpp"

namespace dtlab::gen {

// The cells at `corners` (cell (i, j, k) spans [i, i+1] x [j, j+1] x [k, k+1]); the tetrahedra
// of the second cell get `ref_of_second`, the others 0.
MeshData3 kuhn_cubes(const std::vector<std::array<int, 3>>& corners, int ref_of_second = 0);

}  // namespace dtlab::gen
