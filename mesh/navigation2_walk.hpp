// The geometric walks of the 2D structures (numbering of mesh/triangulation2.hpp; the Mesh
// concept of mesh/navigation2.hpp plus point(v) and is_ghost(t)), written once: point location
// by the stochastic visibility walk (Devillers, Pion, Teillaud 2002) and the pipe of a segment
// (book §1.7, §3.3.3). Exact orient2d throughout; every loop bounded, InternalError past it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "kernel/vec.hpp"
#include "mesh/navigation2.hpp"

namespace dtlab::nav2 {

// Where p lies, walking from triangle `start`: in each triangle the edges are tested from one
// drawn by the xorshift state `rng` (the caller's policy: seeded per call, or carried from call
// to call), and the walk steps across the first with p strictly beyond it, unless blocked(h)
// (it then stops there, `blocked` set). On a non-degenerate triangle, p on two edge lines is on
// their vertex. InternalError after `bound` steps (the walk ends with probability 1). Inlined:
// the 2D mesher calls it millions of times, and as a call it costs 1% more instructions.
template <class Mesh, class Blocked>
[[gnu::always_inline]] inline Location locate(const Mesh& m, const Vec2& p, std::uint32_t start, std::uint64_t& rng,
                                              std::uint64_t bound, Blocked&& blocked) {
  std::uint32_t t = start;
  if (m.is_ghost(t)) t = Mesh::triangle_of(m.twin(3 * t));
  std::uint32_t came_from = kNone;
  std::uint64_t state = rng;  // in a register across the orient2d calls, stored back at the end
  for (std::uint64_t step = 0; step < bound; ++step) {
    if (m.is_ghost(t)) return rng = state, Location{Where::Outside, t, kNone, false};
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    const auto first = static_cast<std::uint32_t>(state % 3);
    bool moved = false;
    int zero_edges = 0;
    std::uint32_t zero_edge = kNone;
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t h = 3 * t + (first + k) % 3;
      if (h == came_from) continue;
      const Sign s = orient2d(m.point(m.origin(h)), m.point(m.destination(h)), p);
      if (s == Sign::Negative) {
        if (blocked(h)) return rng = state, Location{Where::Triangle, t, kNone, true};
        came_from = m.twin(h);
        t = Mesh::triangle_of(came_from);
        moved = true;
        break;
      }
      if (s == Sign::Zero) ++zero_edges, zero_edge = h;
    }
    if (moved) continue;
    // came_from was skipped: p is not strictly beyond it (we came from there), but it may be on it.
    if (came_from != kNone && orient2d(m.point(m.origin(came_from)), m.point(m.destination(came_from)), p) == Sign::Zero)
      ++zero_edges, zero_edge = came_from;
    if (zero_edges >= 2) {
      for (std::uint32_t h = 3 * t; h < 3 * t + 3; ++h)
        if (m.point(m.vertex_at(h)) == p) return rng = state, Location{Where::Vertex, t, m.vertex_at(h), false};
    }
    if (zero_edges >= 1) return rng = state, Location{Where::Edge, t, zero_edge, false};
    return rng = state, Location{Where::Triangle, t, kNone, false};
  }
  throw InternalError("locate: no triangle found for (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                      ") within " + std::to_string(bound) + " steps");
}

// a, s, q collinear: does a lie on the same side of s as q?
inline bool same_direction(const Vec2& s, const Vec2& a, const Vec2& q) noexcept {
  if (s.x != q.x) return (a.x > s.x) == (q.x > s.x);
  return (a.y > s.y) == (q.y > s.y);
}

// The first step of the pipe from vertex s = vertex_at(h0) towards vertex q != s: turning
// counter-clockwise around s from h0 to `at` (opposite s), either the wedge (s, a, b) that holds
// direction q (stop == kNone; `at` runs a -> b, a right of s -> q) or a triangle with the vertex
// that ends the walk (stop: q if sq is an edge, or the first vertex on the open segment).
struct PipeStart {
  std::uint32_t at = kNone;
  std::uint32_t stop = kNone;
};
template <class Mesh>
PipeStart pipe_start(const Mesh& m, std::uint32_t h0, std::uint32_t q, std::size_t bound) {
  const std::uint32_t s = m.vertex_at(h0);
  const Vec2& S = m.point(s);
  const Vec2& Q = m.point(q);
  std::uint32_t h = h0;
  for (std::size_t k = 0; k <= bound; ++k) {
    if (!m.is_ghost(Mesh::triangle_of(h))) {
      const std::uint32_t a = m.origin(h), b = m.destination(h);
      if (a == q || b == q) return {h, q};
      const Sign oa = orient2d(S, m.point(a), Q);
      const Sign ob = orient2d(S, m.point(b), Q);
      if (oa == Sign::Zero && same_direction(S, m.point(a), Q)) return {h, a};
      if (ob == Sign::Zero && same_direction(S, m.point(b), Q)) return {h, b};
      if (oa == Sign::Positive && ob == Sign::Negative) return {h, kNone};
    }
    h = turn_ccw(m, h);
    if (h == h0)
      throw InternalError("segment walk: no triangle around vertex " + std::to_string(s) + " faces vertex " +
                          std::to_string(q));
  }
  throw InternalError("segment walk: the triangles around vertex " + std::to_string(s) + " do not close");
}

// The rest of the pipe: from `crossing` (a -> b, a right of the line P -> Q, Q = point(q)),
// f(h) for each crossed half-edge in order (each oriented so), until q or the first vertex on
// the line PQ, which is returned.
template <class Mesh, class F>
std::uint32_t pipe_cross(const Mesh& m, std::uint32_t crossing, const Vec2& P, std::uint32_t q, std::size_t bound,
                         F&& f) {
  const Vec2& Q = m.point(q);
  for (std::size_t k = 0; k <= bound; ++k) {
    f(crossing);
    const std::uint32_t g = m.twin(crossing);
    if (m.is_ghost(Mesh::triangle_of(g))) throw InternalError("segment walk: the segment leaves the convex hull");
    const std::uint32_t c = m.vertex_at(g);
    if (c == q) return q;
    const Sign oc = orient2d(P, Q, m.point(c));
    if (oc == Sign::Zero) return c;
    crossing = oc == Sign::Positive ? Mesh::next(g) : Mesh::prev(g);
  }
  throw InternalError("segment walk: exceeded its bound of " + std::to_string(bound) + " triangles (broken adjacency)");
}

}  // namespace dtlab::nav2
