// The edge structure the divide-and-conquer variant works on: Guibas & Stolfi's (1985) quad-edge
// restricted to a planar subdivision without its dual, as flat arrays. Each edge is a pair of
// half-edges 2e and 2e + 1 (sym flips the last bit); each half-edge stores its origin and its
// neighbours in the counter-clockwise ring of half-edges leaving that origin:
//
//            onext(h)                 lnext(h) = oprev(sym(h)): next half-edge around the
//               ^                        face on the left of h
//               |    left face of h   rprev(h) = onext(sym(h))
//             org(h) --------h-------> dest(h) = org(sym(h))
//               |
//               v
//            oprev(h)
//
// Deleted edges go to a free list and are reused, so a planar graph on n points never needs
// more than 3n edges: the arrays are sized once.
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include "mesh/triangulation2.hpp"

namespace dtlab::dc {

class EdgeMesh {
 public:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  // Room for the edges of any planar straight-line graph on `points` vertices.
  explicit EdgeMesh(std::uint32_t points);

  static constexpr std::uint32_t sym(std::uint32_t h) noexcept { return h ^ 1u; }
  std::uint32_t org(std::uint32_t h) const noexcept { return h_[h].org; }
  std::uint32_t dest(std::uint32_t h) const noexcept { return h_[h ^ 1u].org; }
  std::uint32_t onext(std::uint32_t h) const noexcept { return h_[h].onext; }
  std::uint32_t oprev(std::uint32_t h) const noexcept { return h_[h].oprev; }
  std::uint32_t lnext(std::uint32_t h) const noexcept { return h_[h ^ 1u].oprev; }
  std::uint32_t rprev(std::uint32_t h) const noexcept { return h_[h ^ 1u].onext; }

  // A new edge a -> b alone in both rings; returns the half-edge a -> b.
  std::uint32_t make_edge(std::uint32_t a, std::uint32_t b);
  // Puts h (alone in its ring) into x's ring, right after x counter-clockwise: onext(x) == h.
  void insert_after(std::uint32_t x, std::uint32_t h) noexcept;
  // A new edge from dest(a) to org(b) closing the face on the left of a and b (Guibas &
  // Stolfi's Connect): afterwards lnext(a) is the new edge and its lnext is b.
  std::uint32_t connect(std::uint32_t a, std::uint32_t b);
  // Removes the edge of h from both rings and frees it.
  void delete_edge(std::uint32_t h) noexcept;

  // Writes the triangulated subdivision into `out` (which holds the input points) and leaves
  // the mesh unusable (its rings hold output handles then). Every face but the outer one must
  // be a counter-clockwise triangle, and `outer` a half-edge with the outer face on its left.
  // Vertex v of the mesh becomes input id ids[v]; one ghost per outer half-edge. Throws
  // InternalError if a face is not a triangle or the count is not 2m - 2 for m = ids.size().
  void to_triangulation(std::uint32_t outer, std::span<const std::uint32_t> ids, Triangulation2& out);

 private:
  struct HalfEdge {
    std::uint32_t org, onext, oprev;
  };
  void unlink(std::uint32_t h) noexcept;

  // Left uninitialised: only the first 2 * used_ slots are ever read.
  std::unique_ptr<HalfEdge[]> h_;
  std::size_t capacity_;         // edges
  std::uint32_t used_ = 0;       // edges handed out from the end of the arrays
  std::uint32_t free_ = kNone;   // freed edges, chained through onext of their even half-edge
};

}  // namespace dtlab::dc
