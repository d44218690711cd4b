// Element sets of a 2D triangulation (book §1.7): the ball of a vertex, the edges, the pipe of a
// segment. All of them walk the adjacency of Triangulation2 (mesh/triangulation2.hpp) with loops
// bounded by the number of triangles; a broken structure gives InternalError, never a hang.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/triangulation2.hpp"

namespace dtlab {

// For each vertex id, the first triangle in storage order incident to it (with finite_first,
// ghosts only if no finite one is), or Triangulation2::kNone for points that no triangle uses
// (duplicates). O(size).
std::vector<std::uint32_t> vertex_triangles(const Triangulation2& tri, bool finite_first = true);

// The ball of vertex v: every triangle incident to v, ghosts included, counter-clockwise around v
// starting from `triangle` (which must have v as a vertex).
std::vector<std::uint32_t> ball(const Triangulation2& tri, std::uint32_t triangle, std::uint32_t v);

// Every edge between two finite vertices, once, as {a, b} with a < b, in storage order of the
// lower-numbered half-edge.
std::vector<std::array<std::uint32_t, 2>> edges(const Triangulation2& tri);

// The pipe of segment [p, q] between two vertices (§1.7; used by constrained triangulation, §3):
// the triangles whose interior the open segment crosses, in order from p to q, decided by exact
// orient2d. If the segment runs through other vertices, they are listed in `through` (in order)
// and the pipe goes on past them; an edge pq gives an empty pipe.
struct Pipe2 {
  std::vector<std::uint32_t> triangles;
  std::vector<std::uint32_t> through;
};
// `triangle` must have p as a vertex (vertex_triangles() gives one). p != q, both finite.
Pipe2 pipe(const Triangulation2& tri, std::uint32_t triangle, std::uint32_t p, std::uint32_t q);

}  // namespace dtlab
