#include "mesh/element_sets2.hpp"

#include <string>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/navigation2_walk.hpp"

namespace dtlab {

namespace {

using T2 = Triangulation2;

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
  if (triangle >= tri.triangle_count() || nav2::opposite(tri, triangle, v) == T2::kNone)
    throw InternalError("ball: triangle " + std::to_string(triangle) + " does not have vertex " + std::to_string(v));
  std::vector<std::uint32_t> out;
  nav2::for_each_in_ball(tri, nav2::opposite(tri, triangle, v), [&](std::uint32_t h) {
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
  if (triangle >= tri.triangle_count() || nav2::opposite(tri, triangle, p) == T2::kNone)
    throw InternalError("pipe: triangle " + std::to_string(triangle) + " does not have vertex " + std::to_string(p));
  const std::size_t bound = tri.triangle_count() + 1;
  Pipe2 out;
  std::uint32_t s = p;
  // One piece of the walk per vertex on the segment (nav2::pipe_start, nav2::pipe_cross).
  for (std::size_t piece = 0; piece < points.size(); ++piece) {
    const nav2::PipeStart start = nav2::pipe_start(tri, nav2::opposite(tri, triangle, s), q, bound);
    triangle = T2::triangle_of(start.at);
    s = start.stop;
    if (s == T2::kNone) {
      out.triangles.push_back(triangle);
      s = nav2::pipe_cross(tri, start.at, points[p], q, bound, [&](std::uint32_t h) {
        triangle = T2::triangle_of(tri.twin(h));
        out.triangles.push_back(triangle);
      });
    }
    if (s == q) return out;
    out.through.push_back(s);
  }
  throw InternalError("pipe: more pieces than vertices (broken adjacency)");
}

}  // namespace dtlab
