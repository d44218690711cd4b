// Structured triangle meshes of the unit square for tests: an n x n grid, its interior vertices
// moved by a deterministic jitter, the diagonals alternating.
#pragma once

#include "mesh/io/mesh_data.hpp"

namespace dtlab::gen {

// Vertices (i/n, j/n), the interior ones moved by up to jitter / n in each direction (by fixed
// trigonometric hashes of (i, j): the same mesh every time); triangles counter-clockwise with
// reference 1; no Edges (the boundary is that of the triangles).
MeshData2 jittered_grid(int n, double jitter);

}  // namespace dtlab::gen
