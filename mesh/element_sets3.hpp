// Element sets of a 3D tetrahedralization (book §1.7): the ball of a vertex, the shell of an edge,
// the pipe of a segment. Each walks the adjacency of Tetrahedralization3 (mesh/tetrahedralization3.hpp) with loops
// bounded by the number of tetrahedra; a broken structure gives InternalError, never a hang.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

// Which tetrahedron vertex_tetrahedra gives a vertex, in storage order: the first (ghosts too,
// as Mesh3 starts), the first finite one (a ghost only where no finite one is), the last.
enum class Incident : std::uint8_t { First, FirstFinite, Last };
// For each vertex id, one tetrahedron incident to it (`which`), or Tetrahedralization3::kNone for
// points that no tetrahedron uses (duplicates). O(size).
std::vector<std::uint32_t> vertex_tetrahedra(const Tetrahedralization3& tet, Incident which = Incident::FirstFinite);

// Whether each of `edges` and `faces` (vertex ids in any order) is an edge or a face of a finite
// tetrahedron: edge_present[k] for edges[k], face_present[k] for faces[k]. One search of the ball
// of each item's lowest vertex, shared by all the items at that vertex (a check of a whole
// surface at once, rather than one search per item). O(size of the balls searched).
void find_in_mesh(const Tetrahedralization3& tet, std::span<const std::array<std::uint32_t, 2>> edges,
                  std::span<const std::array<std::uint32_t, 3>> faces, std::vector<std::uint8_t>& edge_present,
                  std::vector<std::uint8_t>& face_present);

// The ball of vertex v: every tetrahedron incident to v, ghosts included, starting with
// `tetrahedron` (which must have v as a vertex), in breadth-first order over the facets through v.
std::vector<std::uint32_t> ball(const Tetrahedralization3& tet, std::uint32_t tetrahedron, std::uint32_t v);

// The shell of edge [a, b]: every tetrahedron containing both a and b, ghosts included, in
// order around the edge, starting with `tetrahedron` (which must have a and b as vertices).
// The order turns counter-clockwise seen from b looking at a (right-handed about a -> b): the
// tetrahedron after (a, b, c, d), positively oriented, is the one across facet (a, b, d).
std::vector<std::uint32_t> shell(const Tetrahedralization3& tet, std::uint32_t tetrahedron, std::uint32_t a,
                                 std::uint32_t b);

// The general pipe of segment [a, b] between vertices a != b (book §1.7): every finite
// tetrahedron that the open segment meets, closed: through its interior, along one of its faces
// or edges, or at one of its vertices, so that where the segment passes through an edge or a
// vertex the whole shell or ball is in it; the finite shell of [a, b] when it is an edge.
// Decided exactly (orient3d, kernel/intersections.hpp); breadth-first from `tetrahedron`
// (which must have a as a vertex) through the tetrahedra it takes, in that order.
std::vector<std::uint32_t> pipe(const Tetrahedralization3& tet, std::uint32_t tetrahedron, std::uint32_t a,
                                std::uint32_t b);

}  // namespace dtlab
