#include "mesh/element_sets2.hpp"

#include <string>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/navigation2.hpp"

namespace dtlab {

namespace {

using T2 = Triangulation2;

std::uint32_t index_of(const T2& tri, std::uint32_t t, std::uint32_t v) {
  for (std::uint32_t i = 0; i < 3; ++i)
    if (tri.vertex(t, i) == v) return i;
  return T2::kNone;
}

// a, s, q collinear: does a lie on the same side of s as q?
bool same_direction(const Vec2& s, const Vec2& a, const Vec2& q) {
  if (s.x != q.x) return (a.x > s.x) == (q.x > s.x);
  return (a.y > s.y) == (q.y > s.y);
}

}  // namespace

std::vector<std::uint32_t> vertex_triangles(const Triangulation2& tri, bool finite_first) {
  std::vector<std::uint32_t> out(tri.point_count(), T2::kNone);
  const auto count = static_cast<std::uint32_t>(tri.triangle_count());
  for (int pass = 0; pass < (finite_first ? 2 : 1); ++pass) {  // finite first: ghosts fill the gaps
    for (std::uint32_t t = 0; t < count; ++t) {
      if (finite_first && tri.is_ghost(t) != (pass == 1)) continue;
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t v = tri.vertex(t, i);
        if (v != T2::kInfinite && v < out.size() && out[v] == T2::kNone) out[v] = t;
      }
    }
  }
  return out;
}

std::vector<std::uint32_t> ball(const Triangulation2& tri, std::uint32_t triangle, std::uint32_t v) {
  if (triangle >= tri.triangle_count() || index_of(tri, triangle, v) == T2::kNone)
    throw InternalError("ball: triangle " + std::to_string(triangle) + " does not have vertex " + std::to_string(v));
  std::vector<std::uint32_t> out;
  nav2::for_each_in_ball(tri, T2::half_edge(triangle, index_of(tri, triangle, v)), [&](std::uint32_t h) {
    if (tri.vertices()[h] != v)
      throw InternalError("ball of vertex " + std::to_string(v) + ": twin in triangle " +
                          std::to_string(T2::triangle_of(h)) + " lacks the vertex (broken adjacency)");
    out.push_back(T2::triangle_of(h));
    if (out.size() > tri.triangle_count())
      throw InternalError("ball of vertex " + std::to_string(v) + " does not close (broken adjacency)");
  });
  return out;
}

std::vector<std::array<std::uint32_t, 2>> edges(const Triangulation2& tri) {
  std::vector<std::array<std::uint32_t, 2>> out;
  const auto size = static_cast<std::uint32_t>(tri.vertices().size());
  for (std::uint32_t h = 0; h < size; ++h) {
    if (tri.twin(h) < h) continue;
    const std::uint32_t a = tri.origin(h), b = tri.destination(h);
    if (a == T2::kInfinite || b == T2::kInfinite) continue;
    out.push_back(a < b ? std::array{a, b} : std::array{b, a});
  }
  return out;
}

Pipe2 pipe(const Triangulation2& tri, std::uint32_t triangle, std::uint32_t p, std::uint32_t q) {
  const auto points = tri.points();
  if (p == q || p >= points.size() || q >= points.size())
    throw InternalError("pipe: segment [" + std::to_string(p) + ", " + std::to_string(q) + "] is not between two vertices");
  if (triangle >= tri.triangle_count() || index_of(tri, triangle, p) == T2::kNone)
    throw InternalError("pipe: triangle " + std::to_string(triangle) + " does not have vertex " + std::to_string(p));
  const Vec2& P = points[p];
  const Vec2& Q = points[q];
  Pipe2 out;
  const std::size_t bound = 2 * tri.triangle_count() + 2;
  std::size_t steps = 0;
  auto step = [&] {
    if (++steps > bound) throw InternalError("pipe: walk exceeded its bound (broken adjacency)");
  };

  std::uint32_t s = p, t = triangle;
  while (true) {
    // Turn around s to the wedge (s, a, b) that holds direction q, or to a vertex on [s, q].
    std::uint32_t i = index_of(tri, t, s);
    std::uint32_t crossing = T2::kNone;  // half-edge a -> b of the wedge
    const std::uint32_t first = t;
    bool moved_on = false;
    do {
      step();
      if (!tri.is_ghost(t)) {
        const std::uint32_t a = tri.vertex(t, (i + 1) % 3), b = tri.vertex(t, (i + 2) % 3);
        if (a == q || b == q) return out;
        const Vec2& S = points[s];
        const Sign oa = orient2d(S, points[a], Q);
        const Sign ob = orient2d(S, points[b], Q);
        if (oa == Sign::Zero && same_direction(S, points[a], Q)) {
          out.through.push_back(a), s = a, moved_on = true;
          break;
        }
        if (ob == Sign::Zero && same_direction(S, points[b], Q)) {
          out.through.push_back(b), s = b, moved_on = true;
          break;
        }
        if (oa == Sign::Positive && ob == Sign::Negative) {
          crossing = T2::half_edge(t, i);
          break;
        }
      }
      const std::uint32_t h = nav2::turn_ccw(tri, T2::half_edge(t, i));
      t = T2::triangle_of(h), i = T2::index_in_triangle(h);
    } while (t != first);
    if (moved_on) continue;
    if (crossing == T2::kNone)
      throw InternalError("pipe: no triangle around vertex " + std::to_string(s) + " faces vertex " + std::to_string(q));

    // Cross triangles until q or a vertex on the segment: a (origin) is right of p -> q, b left.
    out.triangles.push_back(t);
    while (true) {
      step();
      const std::uint32_t g = tri.twin(crossing);
      t = T2::triangle_of(g);
      if (tri.is_ghost(t)) throw InternalError("pipe: segment leaves the convex hull (broken triangulation)");
      out.triangles.push_back(t);
      const std::uint32_t c = tri.vertex(t, T2::index_in_triangle(g));
      if (c == q) return out;
      const Sign oc = orient2d(P, Q, points[c]);
      if (oc == Sign::Zero) {
        out.through.push_back(c), s = c;
        break;
      }
      crossing = oc == Sign::Positive ? T2::next(g) : T2::prev(g);
    }
  }
}

}  // namespace dtlab
