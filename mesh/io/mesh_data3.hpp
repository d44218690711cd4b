// A neutral 3D mesh container that every 3D file format reads into and writes from.
//
// Indices are 0-based in memory (formats that count from 1 convert on the way in and out).
// A reader fills every *_refs vector to the size of its elements (0 where the file has no
// reference); a writer accepts an empty *_refs vector and writes 0 for each element.
// Tetrahedra are positive: orient3d(a, b, c, d) > 0, i.e. det(b-a, c-a, d-a) > 0, Medit's
// convention (kernel/predicates.hpp); readers of formats with another convention convert, and
// refuse a flat tetrahedron. Triangles carry no orientation constraint.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

struct MeshData3 {
  std::vector<Vec3> vertices;
  std::vector<int> vertex_refs;
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::vector<int> edge_refs;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<int> triangle_refs;
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;  // positive
  std::vector<int> tetrahedron_refs;

  friend bool operator==(const MeshData3&, const MeshData3&) = default;
};

}  // namespace dtlab
