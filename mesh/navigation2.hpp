// Navigation written once for the 2D structures that share the numbering drawn in
// mesh/triangulation2.hpp (Triangulation2, Mesh2, and ConstrainedMesh2 through its
// Triangulation2): any Mesh with static next/prev/triangle_of and members twin, origin,
// destination and vertex_at. The ball of a vertex (book §1.7) is the fan of triangles around it;
// with the hull closed by ghosts every fan is a full cycle, so it is walked by half-edges, never
// searched. The geometric walks (point location, the pipe of a segment) are in
// mesh/navigation2_walk.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "kernel/error.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab::nav2 {

inline constexpr std::uint32_t kNone = Triangulation2::kNone;

// Where a point lies (nav2::locate in mesh/navigation2_walk.hpp).
enum class Where : std::uint8_t { Triangle, Edge, Vertex, Outside };
struct Location {
  Where where = Where::Triangle;
  std::uint32_t triangle = kNone;  // holding p (Edge: the half-edge's; Outside: a ghost p is beyond)
  std::uint32_t handle = kNone;    // Edge: the half-edge p lies on; Vertex: the vertex
  bool blocked = false;            // the walk stopped before an edge it may not cross
};

// h lies opposite v in its triangle: the half-edge opposite v in the next triangle
// counter-clockwise around v, across next(h) (the edge that ends at v).
template <class Mesh>
inline std::uint32_t turn_ccw(const Mesh& m, std::uint32_t h) noexcept {
  return Mesh::next(m.twin(Mesh::next(h)));
}

// f(h) for each half-edge h opposite v in the ball of v, counter-clockwise from h0 (opposite v)
// until the fan closes. f bounds the walk itself (it may throw) where the structure may be broken.
template <class Mesh, class F>
inline void for_each_in_ball(const Mesh& m, std::uint32_t h0, F&& f) {
  std::uint32_t h = h0;
  do {
    f(h);
    h = turn_ccw(m, h);
  } while (h != h0);
}

// The half-edge of triangle t opposite its vertex v, or kNone.
template <class Mesh>
inline std::uint32_t opposite(const Mesh& m, std::uint32_t t, std::uint32_t v) noexcept {
  for (std::uint32_t h = 3 * t; h < 3 * t + 3; ++h)
    if (m.vertex_at(h) == v) return h;
  return kNone;
}

// The half-edge u -> v, or kNone, turning around u from h0 (opposite u). InternalError past
// `bound` triangles (a fan that does not close).
template <class Mesh>
std::uint32_t find_half_edge(const Mesh& m, std::uint32_t h0, std::uint32_t v, std::size_t bound) {
  std::uint32_t h = h0;
  for (std::size_t k = 0; k < bound; ++k) {
    if (m.origin(h) == v) return Mesh::prev(h);  // h runs a -> b opposite u; u -> a is prev(h)
    h = turn_ccw(m, h);
    if (h == h0) return kNone;
  }
  throw InternalError("find_half_edge: the triangles around vertex " + std::to_string(m.vertex_at(h0)) +
                      " do not close");
}

// The re-linking of an edge flip on flat arrays V (vertices) and N (twins): h (a -> b, opposite
// p in t1) and its twin (opposite q in t2) become t1 = (p, a, q), t2 = (q, b, p), the new
// diagonal is edge 1 of both (returned: the one in t1). The four outer edges keep their twins
// and carry their per-half-edge payload along: store(new_slot, load(old_slot)); the diagonal gets
// `cleared`. Updating vertex -> triangle is the caller's.
template <class Load, class Store, class Payload>
std::uint32_t flip(std::uint32_t* V, std::uint32_t* N, std::uint32_t h, Load&& load, Store&& store,
                   const Payload& cleared) {
  using T2 = Triangulation2;
  const std::uint32_t g = N[h];
  const std::uint32_t t1 = T2::triangle_of(h), t2 = T2::triangle_of(g);
  const std::uint32_t p = V[h], a = V[T2::next(h)], b = V[T2::prev(h)], q = V[g];
  // Old outer edges a -> q, p -> a, b -> p, q -> b land in slots 3t1+0, 3t1+2, 3t2+0, 3t2+2.
  const std::array<std::uint32_t, 4> from{T2::next(g), T2::prev(h), T2::next(h), T2::prev(g)};
  const std::array<std::uint32_t, 4> to{3 * t1, 3 * t1 + 2, 3 * t2, 3 * t2 + 2};
  const std::array<std::uint32_t, 4> twins{N[from[0]], N[from[1]], N[from[2]], N[from[3]]};
  const std::array<Payload, 4> data{load(from[0]), load(from[1]), load(from[2]), load(from[3])};
  V[3 * t1] = p, V[3 * t1 + 1] = a, V[3 * t1 + 2] = q;
  V[3 * t2] = q, V[3 * t2 + 1] = b, V[3 * t2 + 2] = p;
  for (std::size_t k = 0; k < 4; ++k) {
    N[to[k]] = twins[k], N[twins[k]] = to[k];
    store(to[k], data[k]);
  }
  N[3 * t1 + 1] = 3 * t2 + 1, N[3 * t2 + 1] = 3 * t1 + 1;
  store(3 * t1 + 1, cleared);
  store(3 * t2 + 1, cleared);
  return 3 * t1 + 1;
}

}  // namespace dtlab::nav2
