// The 2D triangulation structure every 2D algorithm of dtlab builds and every caller reads
// (book §1.7, §10): flat arrays of 32-bit vertex ids and neighbour half-edge handles, the convex
// hull closed by an infinite vertex with ghost triangles.
//
// Numbering, drawn once (every 2D file follows it):
//
//   +-------------------------------------------+
//   |                    v2                     |
//   |                    /\                     |
//   |                   /  \                    |
//   |     h = 3t+1     /    \     h = 3t+0      |
//   |   (v2 -> v0)    /  t   \   (v1 -> v2)     |
//   |                /        \                 |
//   |               /__________\                |
//   |             v0   h = 3t+2  v1             |
//   |                  (v0 -> v1)               |
//   +-------------------------------------------+
//
//  - Triangle t has vertices v0, v1, v2 = vertices()[3t + 0..2], counter-clockwise.
//  - Half-edge h = 3t + i is edge i of t: it lies opposite vertex i and runs from v(i+1) to
//    v(i+2) (indices mod 3), so t is on its left. Hence, with the vertex array V:
//        origin(h) = V[next(h)],  destination(h) = V[prev(h)],  opposite vertex = V[h].
//  - next(h) = 3t + (i+1)%3 starts where h ends; prev(h) = 3t + (i+2)%3 ends where h starts.
//  - neighbours()[h] is the twin of h: the same edge, reversed, in the adjacent triangle.
//
// Convex hull: the infinite vertex kInfinite closes the plane into a sphere. Across each hull
// edge a -> b (interior on its left) lies the ghost triangle (kInfinite, b, a): the infinite
// vertex is always vertex 0 of a ghost, so edge 0 of a ghost is its hull edge (b -> a). Ghosts
// are linked to each other around kInfinite like any triangles: every half-edge has a twin.
// A ghost (kInfinite, a, b) stands for the limit of the circle through a, b and a point going to
// infinity on the far side: p is in conflict with it iff orient2d(a, b, p) > 0, or p is on the
// line ab strictly between a and b.
//
// Contract between algorithms and callers. Algorithms build the structure through the mutable
// accessors; when an algorithm returns, the structure is
//   - compact: every stored triangle is alive (no holes, no kNone anywhere);
//   - closed: neighbours()[neighbours()[h]] == h, twins run between the same two vertices in
//     opposite directions, ghosts carry kInfinite at index 0 and nowhere else;
//   - in input numbering: vertex ids are 0-based indices into points() (the input, in input
//     order); a point that is a duplicate of an earlier one is referenced by no triangle.
// With m distinct used vertices and h hull edges it holds 2m - 2 triangles: 2m - 2 - h finite
// ones and h ghosts. Callers read it; check_topology() verifies the combinatorial part cheaply
// (verify/ checks the geometry).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec.hpp"
#include "mesh/memory_hints.hpp"  // advise_huge_pages, for the 2D algorithms

namespace dtlab {

class Triangulation2 {
 public:
  // The infinite vertex, apex of every ghost triangle.
  static constexpr std::uint32_t kInfinite = 0xFFFFFFFEu;
  // No vertex / no triangle / no half-edge.
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  // Half-edge handles must stay below kInfinite: 3 * (2n - 2) half-edges for n points.
  static constexpr std::uint64_t kMaxPoints = 700'000'000;

  Triangulation2() = default;
  // The input points, in input order (vertex id = index). No triangles yet.
  explicit Triangulation2(std::vector<Vec2> points) : points_(std::move(points)) {}

  std::span<const Vec2> points() const noexcept { return points_; }
  const Vec2& point(std::uint32_t v) const noexcept { return points_[v]; }
  std::size_t point_count() const noexcept { return points_.size(); }

  // --- Navigation (pure arithmetic on handles) ------------------------------------------------
  static constexpr std::uint32_t triangle_of(std::uint32_t h) noexcept { return h / 3; }
  static constexpr std::uint32_t index_in_triangle(std::uint32_t h) noexcept { return h % 3; }
  static constexpr std::uint32_t half_edge(std::uint32_t t, std::uint32_t i) noexcept { return 3 * t + i; }
  static constexpr std::uint32_t next(std::uint32_t h) noexcept { return h % 3 == 2 ? h - 2 : h + 1; }
  static constexpr std::uint32_t prev(std::uint32_t h) noexcept { return h % 3 == 0 ? h + 2 : h - 1; }

  // --- Reading ------------------------------------------------------------------------------
  // Every stored triangle, ghosts included (3 entries per triangle in both arrays).
  std::size_t triangle_count() const noexcept { return vertices_.size() / 3; }
  const std::vector<std::uint32_t>& vertices() const noexcept { return vertices_; }
  const std::vector<std::uint32_t>& neighbours() const noexcept { return neighbours_; }

  std::uint32_t vertex(std::uint32_t t, std::uint32_t i) const noexcept { return vertices_[3 * t + i]; }
  std::uint32_t vertex_at(std::uint32_t h) const noexcept { return vertices_[h]; }  // opposite h
  std::uint32_t origin(std::uint32_t h) const noexcept { return vertices_[next(h)]; }
  std::uint32_t destination(std::uint32_t h) const noexcept { return vertices_[prev(h)]; }
  std::uint32_t twin(std::uint32_t h) const noexcept { return neighbours_[h]; }
  // The triangle across edge i of t.
  std::uint32_t adjacent(std::uint32_t t, std::uint32_t i) const noexcept {
    return triangle_of(neighbours_[3 * t + i]);
  }
  bool is_ghost(std::uint32_t t) const noexcept { return vertices_[3 * t] == kInfinite; }

  // Finite triangles (ghosts left out), counter-clockwise, input ids, in storage order.
  std::vector<std::array<std::uint32_t, 3>> finite_triangles() const;
  std::size_t finite_triangle_count() const noexcept;

  // Throws InternalError naming the first broken half-edge: sizes, vertex ids in range,
  // kInfinite only at index 0, no repeated vertex in a triangle, twins present, symmetric and
  // reversed. O(size), combinatorial only.
  void check_topology() const;

  // --- Building (for algorithms; see the contract above) -------------------------------------
  std::vector<Vec2>& mutable_points() noexcept { return points_; }
  std::vector<std::uint32_t>& mutable_vertices() noexcept { return vertices_; }
  std::vector<std::uint32_t>& mutable_neighbours() noexcept { return neighbours_; }
  // Appends triangle (a, b, c), rotated so that kInfinite (if present) is vertex 0, with no
  // neighbours yet (kNone). Returns its index.
  std::uint32_t add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  // Makes half-edges g and h twins of each other.
  void link(std::uint32_t g, std::uint32_t h) noexcept {
    neighbours_[g] = h;
    neighbours_[h] = g;
  }
  // Reserves room for `triangles` triangles (the arrays never reallocate below that), and for
  // large sizes asks for transparent huge pages (advise_huge_pages).
  void reserve_triangles(std::size_t triangles);
  void clear_triangles() noexcept {
    vertices_.clear();
    neighbours_.clear();
  }

 private:
  std::vector<Vec2> points_;
  std::vector<std::uint32_t> vertices_;
  std::vector<std::uint32_t> neighbours_;
};

}  // namespace dtlab
