// Shared pieces of the 2D optimization operators (local.hpp): quality and length in the vertex
// metrics, the locks that keep operators off the boundary and the exterior, and the replacement
// of a star of triangles (the "simulation, then effective application" of book §8.6.1: callers
// decide on coordinates, this routine only rewires).
#include "algorithms/optimize2d/local.hpp"

#include <algorithm>
#include <string>

#include "kernel/error.hpp"
#include "kernel/quality.hpp"

namespace dtlab::optimize2d_detail {

double quality(const Mesh2& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) noexcept {
  return shape_quality(mesh.point(a), mesh.point(b), mesh.point(c), mesh.metric(a), mesh.metric(b), mesh.metric(c));
}

double triangle_quality(const Mesh2& mesh, std::uint32_t t) noexcept {
  return quality(mesh, mesh.vertex(t, 0), mesh.vertex(t, 1), mesh.vertex(t, 2));
}

double edge_length(const Mesh2& mesh, std::uint32_t u, std::uint32_t v) noexcept {
  return dtlab::edge_length(mesh.point(u), mesh.metric(u), mesh.point(v), mesh.metric(v));
}

bool is_locked(const Mesh2& mesh, std::uint32_t h) noexcept {
  if (mesh.is_constrained(h)) return true;
  const std::uint32_t t = Mesh2::triangle_of(h);
  const std::uint32_t u = Mesh2::triangle_of(mesh.twin(h));
  return !mesh.in_domain(t) || !mesh.in_domain(u) || mesh.ref(t) != mesh.ref(u);
}

bool is_free(const Mesh2& mesh, std::uint32_t v, std::vector<std::uint32_t>& ring) {
  if (v >= mesh.vertex_capacity() || mesh.is_dead_vertex(v)) return false;
  if ((mesh.flags(v) & (Mesh2::kFixed | Mesh2::kOnBoundary)) != 0) return false;
  mesh.ball(v, ring);
  const int r = mesh.ref(Mesh2::triangle_of(ring.front()));
  for (const std::uint32_t h : ring) {
    const std::uint32_t t = Mesh2::triangle_of(h);
    // In triangle (v, a, b) with h = a -> b: prev(h) runs v -> a, next(h) runs b -> v.
    if (!mesh.in_domain(t) || mesh.ref(t) != r || mesh.is_constrained(Mesh2::prev(h))) return false;
  }
  return true;
}

void replace_triangles(Mesh2& mesh, std::span<const std::uint32_t> old_triangles,
                       std::span<const NewTriangle> new_triangles, std::span<const MeshEdge2> constrained,
                       std::vector<std::uint32_t>& slots) {
  // The outer boundary: half-edges of old triangles whose twin lies in no old triangle.
  struct Outer {
    std::uint32_t from, to, twin;
    bool constrained;
    int ref;
    bool used;
  };
  std::vector<Outer> outer;
  auto is_old = [&](std::uint32_t t) {
    return std::find(old_triangles.begin(), old_triangles.end(), t) != old_triangles.end();
  };
  for (const std::uint32_t t : old_triangles) {
    DTLAB_ASSERT(mesh.is_alive(t));
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      const std::uint32_t g = mesh.twin(h);
      if (is_old(Mesh2::triangle_of(g))) continue;
      outer.push_back({mesh.origin(h), mesh.destination(h), g, mesh.is_constrained(h), mesh.edge_ref(h), false});
    }
  }
  for (const std::uint32_t t : old_triangles) mesh.remove_triangle(t);
  slots.clear();
  for (const NewTriangle& n : new_triangles) slots.push_back(mesh.add_triangle(n.a, n.b, n.c, n.ref));
  // Link each new half-edge: to the outside through the outer edge it repeats, else to its
  // reversed copy in another new triangle. The sets are a handful of triangles: quadratic is fine.
  for (std::size_t k = 0; k < slots.size(); ++k) {
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(slots[k], i);
      if (mesh.twin(h) != Mesh2::kNone) continue;
      const std::uint32_t from = mesh.origin(h), to = mesh.destination(h);
      bool linked = false;
      for (Outer& o : outer) {
        if (o.used || o.from != from || o.to != to) continue;
        mesh.link(h, o.twin);
        mesh.set_constraint(h, o.constrained, o.ref);
        o.used = true;
        linked = true;
        break;
      }
      for (std::size_t m = k + 1; !linked && m < slots.size(); ++m) {
        for (std::uint32_t j = 0; j < 3 && !linked; ++j) {
          const std::uint32_t g = Mesh2::half_edge(slots[m], j);
          if (mesh.twin(g) != Mesh2::kNone || mesh.origin(g) != to || mesh.destination(g) != from) continue;
          mesh.link(h, g);
          bool is_constrained = false;
          int ref = 0;
          for (const MeshEdge2& e : constrained) {
            if ((e.a == from && e.b == to) || (e.a == to && e.b == from)) {
              is_constrained = true;
              ref = e.ref;
            }
          }
          mesh.set_constraint_both(h, is_constrained, ref);
          linked = true;
        }
      }
      if (!linked) {
        throw InternalError("optimize2d: new edge " + std::to_string(from) + " -> " + std::to_string(to) +
                            " matches neither the outer boundary nor another new triangle");
      }
    }
  }
  for (const Outer& o : outer) {
    if (!o.used) {
      throw InternalError("optimize2d: outer edge " + std::to_string(o.from) + " -> " + std::to_string(o.to) +
                          " is left without a triangle");
    }
  }
}

}  // namespace dtlab::optimize2d_detail
