// Navigation around a vertex, written once for both 2D structures that share the numbering drawn
// in mesh/triangulation2.hpp (Triangulation2, Mesh2): any Mesh with static next(h) and twin(h).
// The ball of a vertex (book §1.7) is the fan of triangles around it; with the hull closed by
// ghosts every fan is a full cycle, so it is walked by half-edges, never searched.
#pragma once

#include <cstdint>

namespace dtlab::nav2 {

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

}  // namespace dtlab::nav2
