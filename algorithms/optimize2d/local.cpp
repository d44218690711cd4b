// Shared pieces of the 2D optimization operators (local.hpp): quality and length in the vertex
// metrics, the locks that keep operators off the boundary and the exterior, and the replacement
// of a star of triangles (the "simulation, then effective application" of book §8.6.1: callers
// decide on coordinates, this routine only rewires).
#include "algorithms/optimize2d/local.hpp"

#include <array>
#include <string>

#include "algorithms/common/replace_elements.hpp"
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

namespace {

// The 2D side of replace_elements (algorithms/common/replace_elements.hpp): half-edges, keyed
// (origin, destination); a new one's copy runs the other way.
struct TriangleSide {
  static constexpr std::uint32_t kFacets = 3;
  static constexpr const char* kWho = "optimize2d";
  static constexpr const char* kElement = "triangle";
  using Key = std::array<std::uint32_t, 2>;
  static std::uint32_t facet(std::uint32_t t, std::uint32_t i) noexcept { return Mesh2::half_edge(t, i); }
  static std::uint32_t element_of(std::uint32_t h) noexcept { return Mesh2::triangle_of(h); }
  static Key key(const Mesh2& mesh, std::uint32_t h) noexcept { return {mesh.origin(h), mesh.destination(h)}; }
  static Key mate(const Key& k) noexcept { return {k[1], k[0]}; }
  static int ref(const Mesh2& mesh, std::uint32_t h) noexcept { return mesh.edge_ref(h); }
  static void set_outer(Mesh2& mesh, std::uint32_t h, bool c, int r) { mesh.set_constraint(h, c, r); }
  static void remove(Mesh2& mesh, std::uint32_t t) { mesh.remove_triangle(t); }
  static std::uint32_t add(Mesh2& mesh, const NewTriangle& n) { return mesh.add_triangle(n.a, n.b, n.c, n.ref); }
  static std::string describe(const Key& k) { return "edge " + std::to_string(k[0]) + " -> " + std::to_string(k[1]); }
};

}  // namespace

void replace_triangles(Mesh2& mesh, std::span<const std::uint32_t> old_triangles,
                       std::span<const NewTriangle> new_triangles, std::span<const MeshEdge2> constrained,
                       std::vector<std::uint32_t>& slots) {
  // An edge between two new triangles is constrained when `constrained` lists it.
  replace_elements<TriangleSide>(mesh, old_triangles, new_triangles, slots, [&](std::uint32_t h, const auto& key) {
    bool is_constrained = false;
    int ref = 0;
    for (const MeshEdge2& e : constrained) {
      if ((e.a == key[0] && e.b == key[1]) || (e.a == key[1] && e.b == key[0])) {
        is_constrained = true;
        ref = e.ref;
      }
    }
    mesh.set_constraint_both(h, is_constrained, ref);
  });
}

}  // namespace dtlab::optimize2d_detail
