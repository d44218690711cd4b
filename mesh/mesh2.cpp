// The shared mutable 2D mesh (mesh2.hpp): storage, free lists, navigation, the visibility walk
// and the edge flip. Operators that change the mesh live in algorithms/ (one a file).
#include "mesh/mesh2.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/domain_vertices.hpp"
#include "mesh/edge_key.hpp"
#include "mesh/element_sets2.hpp"
#include "mesh/navigation2_walk.hpp"

namespace dtlab {

Mesh2::Mesh2(const Triangulation2& tri, std::span<const int> triangle_refs, std::span<const MeshEdge2> constrained,
             const Metric2& metric) {
  const std::size_t nt = tri.triangle_count();
  if (triangle_refs.size() != nt) {
    throw InputError("Mesh2: " + std::to_string(triangle_refs.size()) + " triangle references for " +
                     std::to_string(nt) + " triangles");
  }
  adopt_vertices(tri.points(), metric, vertex_triangles(tri, /*finite_first=*/false));
  vertices_ = tri.vertices();
  neighbours_ = tri.neighbours();
  refs_.assign(triangle_refs.begin(), triangle_refs.end());
  constrained_.assign(vertices_.size(), 0);
  edge_refs_.assign(vertices_.size(), 0);
  for (std::uint32_t t = 0; t < nt; ++t)
    if (is_ghost(t)) refs_[t] = kExterior;
  if (constrained.empty()) return;
  std::unordered_map<std::uint64_t, std::uint32_t> by_edge;
  by_edge.reserve(constrained.size() * 2);
  for (std::uint32_t i = 0; i < constrained.size(); ++i) by_edge.emplace(edge_key(constrained[i].a, constrained[i].b), i);
  std::vector<std::uint8_t> found(constrained.size(), 0);
  for (std::uint32_t h = 0; h < vertices_.size(); ++h) {
    const std::uint32_t a = origin(h), b = destination(h);
    if (a == kInfinite || b == kInfinite) continue;
    const auto it = by_edge.find(edge_key(a, b));
    if (it == by_edge.end()) continue;
    constrained_[h] = 1;
    edge_refs_[h] = constrained[it->second].ref;
    found[it->second] = 1;
    vertex_flags_[a] |= kOnBoundary;
    vertex_flags_[b] |= kOnBoundary;
  }
  for (std::uint32_t i = 0; i < constrained.size(); ++i) {
    if (!found[i]) {
      throw InputError("Mesh2: constrained edge " + std::to_string(i) + " (" + std::to_string(constrained[i].a) + ", " +
                           std::to_string(constrained[i].b) + ") is not an edge of the triangulation",
                       {i});
    }
  }
}

std::uint32_t Mesh2::add_vertex(const Vec2& p, const Metric2& m, std::uint8_t flags) {
  DTLAB_ASSERT((flags & kDead) == 0);
  const std::uint32_t v = take_slot(Triangulation2::kMaxPoints);
  points_[v] = p;
  metrics_[v] = m;
  vertex_flags_[v] = flags;
  return v;
}

std::uint32_t Mesh2::add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, int r) {
  DTLAB_ASSERT(b != kInfinite && c != kInfinite);
  std::uint32_t t;
  if (!free_triangles_.empty()) {
    t = free_triangles_.back();
    free_triangles_.pop_back();
  } else {
    t = triangle_capacity();
    DTLAB_ASSERT(3ull * t + 3 < kInfinite);
    vertices_.resize(vertices_.size() + 3);
    neighbours_.resize(neighbours_.size() + 3);
    refs_.push_back(0);
    constrained_.resize(constrained_.size() + 3);
    edge_refs_.resize(edge_refs_.size() + 3);
  }
  vertices_[3 * t] = a;
  vertices_[3 * t + 1] = b;
  vertices_[3 * t + 2] = c;
  refs_[t] = r;
  for (std::uint32_t i = 0; i < 3; ++i) {
    neighbours_[3 * t + i] = kNone;
    constrained_[3 * t + i] = 0;
    edge_refs_[3 * t + i] = 0;
  }
  if (a != kInfinite) vertex_element_[a] = t;
  vertex_element_[b] = t;
  vertex_element_[c] = t;
  return t;
}

void Mesh2::remove_triangle(std::uint32_t t) {
  DTLAB_ASSERT(is_alive(t));
  vertices_[3 * t] = kNone;
  free_triangles_.push_back(t);
}

void Mesh2::ball(std::uint32_t v, std::vector<std::uint32_t>& out) const {
  out.clear();
  const std::uint32_t t0 = vertex_element_[v];
  DTLAB_ASSERT(t0 != kNone && is_alive(t0));
  const std::uint32_t h0 = nav2::opposite(*this, t0, v);
  DTLAB_ASSERT(h0 != kNone);
  const std::size_t bound = live_triangle_count() + 1;
  nav2::for_each_in_ball(*this, h0, [&](std::uint32_t h) {
    out.push_back(h);
    if (out.size() > bound) throw InternalError("Mesh2::ball: the triangles around vertex " + std::to_string(v) + " do not close");
  });
}

std::uint32_t Mesh2::find_half_edge(std::uint32_t u, std::uint32_t v) const {
  const std::uint32_t t0 = vertex_element_[u];
  DTLAB_ASSERT(t0 != kNone && is_alive(t0));
  return nav2::find_half_edge(*this, nav2::opposite(*this, t0, u), v, live_triangle_count() + 1);
}

Mesh2::Location Mesh2::locate(const Vec2& p, std::uint32_t start, bool stop_at_constraints) const {
  DTLAB_ASSERT(start < triangle_capacity() && is_alive(start));
  std::uint64_t rng = 0x9E3779B97F4A7C15ull ^ (static_cast<std::uint64_t>(start) * 0xBF58476D1CE4E5B9ull);
  return nav2::locate(*this, p, start, rng, 64ull * live_triangle_count() + 64,
                      [this, stop_at_constraints](std::uint32_t h) { return stop_at_constraints && constrained_[h]; });
}

std::uint32_t Mesh2::flip(std::uint32_t h) {
  const std::uint32_t g = neighbours_[h];
  const std::uint32_t t1 = triangle_of(h), t2 = triangle_of(g);
  DTLAB_ASSERT(is_alive(t1) && is_alive(t2) && !is_ghost(t1) && !is_ghost(t2) && !constrained_[h]);
  struct Payload {
    std::uint8_t constrained = 0;
    int ref = 0;
  };
  const std::uint32_t d = nav2::flip(
      vertices_.data(), neighbours_.data(), h, [&](std::uint32_t e) { return Payload{constrained_[e], edge_refs_[e]}; },
      [&](std::uint32_t e, const Payload& x) { constrained_[e] = x.constrained, edge_refs_[e] = x.ref; }, Payload{});
  // t1 = (p, a, q), t2 = (q, b, p).
  vertex_element_[vertices_[3 * t1]] = vertex_element_[vertices_[3 * t1 + 1]] = vertex_element_[vertices_[3 * t1 + 2]] = t1;
  vertex_element_[vertices_[3 * t2 + 1]] = t2;
  return d;
}

void Mesh2::check() const {
  auto fail = [](const std::string& what) { throw InternalError("Mesh2::check: " + what); };
  const std::uint32_t nt = triangle_capacity();
  std::vector<std::uint8_t> free_t(nt, 0);
  for (const std::uint32_t t : free_triangles_) {
    if (t >= nt || is_alive(t) || free_t[t]) fail("free triangle list holds " + std::to_string(t));
    free_t[t] = 1;
  }
  for (std::uint32_t v : free_vertices_) {
    if (v >= vertex_capacity() || !is_dead_vertex(v)) fail("free vertex list holds " + std::to_string(v));
  }
  std::vector<std::uint8_t> used(vertex_capacity(), 0);
  for (std::uint32_t t = 0; t < nt; ++t) {
    if (!is_alive(t)) {
      if (!free_t[t]) fail("dead triangle " + std::to_string(t) + " not in the free list");
      continue;
    }
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = 3 * t + i;
      const std::uint32_t v = vertices_[h];
      if (v == kInfinite) {
        if (i != 0) fail("kInfinite at index " + std::to_string(i) + " of triangle " + std::to_string(t));
        continue;
      }
      if (v >= vertex_capacity() || is_dead_vertex(v)) fail("triangle " + std::to_string(t) + " uses dead vertex " + std::to_string(v));
      used[v] = 1;
      const std::uint32_t g = neighbours_[h];
      if (g == kNone || g >= vertices_.size() || !is_alive(triangle_of(g))) fail("half-edge " + std::to_string(h) + " has no live twin");
      if (neighbours_[g] != h) fail("half-edge " + std::to_string(h) + " twin not symmetric");
      if (origin(g) != destination(h) || destination(g) != origin(h)) fail("half-edge " + std::to_string(h) + " twin not reversed");
      if (constrained_[g] != constrained_[h] || (constrained_[h] && edge_refs_[g] != edge_refs_[h])) {
        fail("half-edge " + std::to_string(h) + " constrained differently from its twin");
      }
    }
    const std::uint32_t a = vertices_[3 * t], b = vertices_[3 * t + 1], c = vertices_[3 * t + 2];
    if (a == b || b == c || a == c) fail("triangle " + std::to_string(t) + " repeats a vertex");
    if (a != kInfinite && orient2d(points_[a], points_[b], points_[c]) != Sign::Positive) {
      fail("triangle " + std::to_string(t) + " is not positively oriented");
    }
  }
  for (std::uint32_t v = 0; v < vertex_capacity(); ++v) {
    if (is_dead_vertex(v)) continue;
    const std::uint32_t t = vertex_element_[v];
    if (t == kNone || t >= nt || !is_alive(t) ||
        (vertices_[3 * t] != v && vertices_[3 * t + 1] != v && vertices_[3 * t + 2] != v)) {
      fail("vertex_triangle of vertex " + std::to_string(v) + " is stale");
    }
    if (!used[v]) fail("live vertex " + std::to_string(v) + " is used by no triangle");
  }
}

MeshData2 Mesh2::domain(std::vector<std::uint32_t>* vertex_ids) const {
  const auto emit_edge = [this](MeshData2& out, std::span<const std::uint32_t> number, std::uint32_t h) {
    out.edges.push_back({number[origin(h)], number[destination(h)]});
    out.edge_refs.push_back(edge_refs_[h]);
  };
  return mesh_domain<3, MeshData2>(*this, vertices_, neighbours_, refs_, &MeshData2::triangles, &MeshData2::triangle_refs,
                                   vertex_ids, [this](std::uint32_t h) { return constrained_[h] != 0; }, emit_edge);
}

}  // namespace dtlab
