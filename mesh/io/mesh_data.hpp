// A neutral 2D mesh container that every file format reads into and writes from.
//
// Indices are 0-based in memory (formats that count from 1 convert on the way in and out).
// A reader fills every *_refs vector to the size of its elements (0 where the file has no
// reference); a writer accepts an empty *_refs vector and writes 0 for each element.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

struct MeshData2 {
  std::vector<Vec2> vertices;
  std::vector<int> vertex_refs;
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::vector<int> edge_refs;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise
  std::vector<int> triangle_refs;

  friend bool operator==(const MeshData2&, const MeshData2&) = default;
};

}  // namespace dtlab
