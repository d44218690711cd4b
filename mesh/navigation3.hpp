// Navigation around a vertex and an edge, written once for both 3D structures that share the
// numbering drawn in mesh/tetrahedralization3.hpp (Tetrahedralization3, Mesh3): any Mesh with
// vertex(t, i) and adjacent(t, i). The ball of a vertex (book §1.7) is not a cycle as in 2D, so
// it is searched across the facets that hold the vertex; the shell of an edge (§8.3.2) is a cycle,
// walked with the table below. The visibility walk of point location (Mesh3::locate and the
// control space's background, algorithms/mesh3d/control_space.hpp) is at the end.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "kernel/predicates.hpp"
#include "kernel/vec.hpp"

namespace dtlab::nav3 {

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;

// Which end of the list the search takes the next tetrahedron from: breadth first keeps the whole
// ball in the list, in an order that depends only on the structure; depth first pops it.
enum class Order : std::uint8_t { BreadthFirst, DepthFirst };

// The ball of v searched from t0 (which holds v) across the facets that hold v (those opposite
// the other vertices): a tetrahedron's neighbours across facets 0..3 are appended to `list` where
// first_time(u) accepts them (it marks what it accepts, and is asked about t0 first). visit(t)
// sees the tetrahedra in the search's order and stops it by returning true (search_ball returns
// that t, else kNone). visit runs as a tetrahedron is taken from the list, before its neighbours
// are appended; breadth first, the order of taking is the order of appending, so the first match
// is the first one found. (Visiting as one is appended instead gives the same answer but a
// looser loop: 52 % more instructions in FlipRecovery::tetrahedron_with, callgrind, 2026-12-07;
// that search, the hot loop of the 3D constrained methods, keeps its own loop.)
template <Order kOrder = Order::BreadthFirst, class Mesh, class FirstTime, class Visit>
inline std::uint32_t search_ball(const Mesh& m, std::uint32_t v, std::uint32_t t0, std::vector<std::uint32_t>& list,
                                 FirstTime&& first_time, Visit&& visit) {
  constexpr bool kBreadth = kOrder == Order::BreadthFirst;
  list.clear();
  first_time(t0);
  list.push_back(t0);
  for (std::size_t k = 0; kBreadth ? k < list.size() : !list.empty(); ++k) {
    std::uint32_t t;
    if constexpr (kBreadth) {
      t = list[k];
    } else {
      t = list.back();
      list.pop_back();
    }
    if (visit(t)) return t;
    for (std::uint32_t i = 0; i < 4; ++i) {
      if (m.vertex(t, i) == v) continue;
      const std::uint32_t u = m.adjacent(t, i);
      if (first_time(u)) list.push_back(u);
    }
  }
  return kNone;
}

// A first_time for search_ball that marks a slot with the search's own stamp (mark has an entry
// per tetrahedron slot; a fresh stamp per search, so earlier marks never read as seen).
inline auto marking(std::vector<std::uint32_t>& mark, std::uint32_t stamp) noexcept {
  return [&mark, stamp](std::uint32_t t) { return mark[t] != stamp && (mark[t] = stamp, true); };
}

// The whole ball, breadth first, into `out` (out[0] == t0).
template <class Mesh, class FirstTime>
inline void ball(const Mesh& m, std::uint32_t v, std::uint32_t t0, std::vector<std::uint32_t>& out, FirstTime&& first_time) {
  search_ball(m, v, t0, out, first_time, [](std::uint32_t) { return false; });
}

// The shell's step. In t = (a, b, c, d) positive, the next tetrahedron around edge ab lies across
// the facet (a, b, d) opposite c, and its fourth vertex e makes (a, b, d, e) positive again. With
// ia, ib the local indices of a and b, kShellStep[ia][ib] = {k, l} such that (ia, ib, k, l) is an
// even permutation of (0, 1, 2, 3), so (v_ia, v_ib, v_k, v_l) is positive: cross facet k (c = v_k),
// and v_l is the next tetrahedron's c. (The diagonal, ia == ib, is unused.)
inline constexpr std::uint8_t kShellStep[4][4][2] = {
    {{0, 0}, {2, 3}, {3, 1}, {1, 2}},
    {{3, 2}, {0, 0}, {0, 3}, {2, 0}},
    {{1, 3}, {3, 0}, {0, 0}, {0, 1}},
    {{2, 1}, {0, 2}, {1, 0}, {0, 0}},
};

// The local indices of a and b among a tetrahedron's four vertices v, in one scan (4 for one
// that is not there).
inline std::array<std::uint32_t, 2> local_indices(const std::uint32_t* v, std::uint32_t a, std::uint32_t b) noexcept {
  std::array<std::uint32_t, 2> out{4, 4};
  for (std::uint32_t i = 0; i < 4; ++i) {
    if (v[i] == a) out[0] = i;
    if (v[i] == b) out[1] = i;
  }
  return out;
}

// The visibility walk (Devillers, Pion, Teillaud 2002) towards p from t, on any Mesh with
// is_ghost, facet_vertices, point and twin. Each step tests t's facets from first(step) on, all
// but the one it came in by (p is on its near side), and at the first with p strictly beyond it
// (orient3d < 0: facet i followed by vertex i is positive) asks beyond(h) whether to cross it,
// to skip it (test the next) or to stop in t. The callers' policies: Mesh3::locate starts at a
// random facet and stops at constraints; the control space rotates the first facet with the
// step (a deterministic break of the cycles a non-Delaunay mesh allows) and skips its boundary.
enum class Beyond : std::uint8_t { Cross, Skip, Stop };
struct Walk {
  enum class End : std::uint8_t { Found, Stopped, Ghost, Bound };
  std::uint32_t tetrahedron;
  std::uint32_t came_from;    // the facet handle (in tetrahedron) it entered by; kNone at start
  std::uint32_t zero_facets;  // Found: bit i when p is on facet i (came_from not tested)
  End end;                    // Found: no facet has p beyond it that was not skipped
};
template <class Mesh, class First, class BeyondFn>
inline Walk visibility_walk(const Mesh& m, const Vec3& p, std::uint32_t t, std::uint64_t bound, First&& first,
                            BeyondFn&& beyond) {
  std::uint32_t came_from = kNone;
  for (std::uint64_t step = 0; step < bound; ++step) {
    if (m.is_ghost(t)) return {t, came_from, 0, Walk::End::Ghost};
    const std::uint32_t first_facet = first(step);
    std::uint32_t zero = 0, next = kNone;
    for (std::uint32_t k = 0; k < 4; ++k) {
      const std::uint32_t h = 4 * t + ((first_facet + k) & 3u);
      if (h == came_from) continue;
      const auto f = m.facet_vertices(h);
      const Sign s = orient3d(m.point(f[0]), m.point(f[1]), m.point(f[2]), p);
      if (s == Sign::Negative) {
        const Beyond b = beyond(h);
        if (b == Beyond::Stop) return {t, came_from, zero, Walk::End::Stopped};
        if (b == Beyond::Skip) continue;
        next = m.twin(h);
        break;
      }
      if (s == Sign::Zero) zero |= 1u << (h & 3u);
    }
    if (next == kNone) return {t, came_from, zero, Walk::End::Found};
    came_from = next;
    t = next >> 2;
  }
  return {t, came_from, 0, Walk::End::Bound};
}

}  // namespace dtlab::nav3
