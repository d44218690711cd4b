// Building a Mesh2 from a neutral mesh (mesh2_from_data.hpp).
#include "mesh/mesh2_from_data.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

namespace {

std::uint64_t directed(std::uint32_t a, std::uint32_t b) { return (static_cast<std::uint64_t>(a) << 32) | b; }

}  // namespace

Mesh2 mesh2_from_data(const MeshData2& data, const Metric2& metric) {
  const std::uint32_t n = static_cast<std::uint32_t>(data.vertices.size());
  const std::uint32_t nt = static_cast<std::uint32_t>(data.triangles.size());
  // An empty mesh would reach the algorithms as one with no domain (no boundary, no metric).
  if (nt == 0) throw InputError("no triangles (" + std::to_string(n) + " vertices): a mesh needs at least one");
  Triangulation2 tri(data.vertices);
  std::vector<std::uint32_t>& V = tri.mutable_vertices();
  std::vector<std::uint32_t>& N = tri.mutable_neighbours();
  V.reserve(3 * nt + 3 * 64);
  std::unordered_map<std::uint64_t, std::uint32_t> half_edge;  // a -> b  to  half-edge
  half_edge.reserve(3 * static_cast<std::size_t>(nt) + 16);
  for (std::uint32_t t = 0; t < nt; ++t) {
    const auto& v = data.triangles[t];
    for (int i = 0; i < 3; ++i) {
      if (v[i] >= n) throw InputError("triangle " + std::to_string(t + 1) + " uses vertex " + std::to_string(v[i] + 1) + ", out of range", {t});
    }
    if (orient2d(data.vertices[v[0]], data.vertices[v[1]], data.vertices[v[2]]) != Sign::Positive) {
      throw InputError("triangle " + std::to_string(t + 1) + " is not strictly counter-clockwise (flat or clockwise)", {t});
    }
    V.insert(V.end(), {v[0], v[1], v[2]});
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = 3 * t + i;
      const std::uint32_t a = v[(i + 1) % 3], b = v[(i + 2) % 3];
      if (!half_edge.emplace(directed(a, b), h).second) {
        throw InputError("edge (" + std::to_string(a + 1) + ", " + std::to_string(b + 1) + ") is in two triangles with the same "
                         "orientation, or in more than two (triangle " + std::to_string(t + 1) + ")", {t});
      }
    }
  }
  N.assign(V.size(), Triangulation2::kNone);
  // Twins; a half-edge without one is on the boundary and gets a ghost (kInfinite, b, a).
  std::unordered_map<std::uint32_t, std::uint32_t> ghost_into, ghost_out_of;  // boundary vertex -> ghost
  for (std::uint32_t h = 0; h < 3 * nt; ++h) {
    const std::uint32_t a = V[Triangulation2::next(h)], b = V[Triangulation2::prev(h)];
    const auto it = half_edge.find(directed(b, a));
    if (it != half_edge.end()) {
      N[h] = it->second;
      continue;
    }
    const std::uint32_t g = tri.add_triangle(Triangulation2::kInfinite, b, a);
    N.resize(V.size(), Triangulation2::kNone);
    tri.link(3 * g, h);
    // The boundary runs a -> b (domain on its left): ghost g comes into b and goes out of a.
    if (!ghost_into.emplace(b, g).second || !ghost_out_of.emplace(a, g).second) {
      const std::uint32_t v = ghost_into.count(b) ? b : a;
      throw InputError("the boundary passes twice through vertex " + std::to_string(v + 1) + " (the mesh is not a manifold there)", {v});
    }
  }
  // Around boundary vertex b: the ghost of the edge into b, (kInf, b, a), has edge 2 running
  // kInf -> b; the ghost of the edge out of b, (kInf, c, b), has edge 1 running b -> kInf.
  for (const auto& [b, g_in] : ghost_into) {
    const std::uint32_t g_out = ghost_out_of.at(b);
    tri.link(3 * g_in + 2, 3 * g_out + 1);
  }
  std::vector<int> refs(tri.triangle_count(), Mesh2::kExterior);
  for (std::uint32_t t = 0; t < nt; ++t) refs[t] = data.triangle_refs.empty() ? 0 : data.triangle_refs[t];
  // Constrained: the listed edges, then the boundary edges not listed (reference 0).
  std::vector<MeshEdge2> constrained;
  std::unordered_map<std::uint64_t, int> listed;
  for (std::size_t e = 0; e < data.edges.size(); ++e) {
    const auto [a, b] = data.edges[e];
    if (a >= n || b >= n || (!half_edge.count(directed(a, b)) && !half_edge.count(directed(b, a)))) {
      throw InputError("edge " + std::to_string(e + 1) + " (" + std::to_string(a + 1) + ", " + std::to_string(b + 1) +
                       ") is not an edge of the triangles", {e});
    }
    const int ref = data.edge_refs.empty() ? 0 : data.edge_refs[e];
    if (listed.emplace(directed(std::min(a, b), std::max(a, b)), ref).second) constrained.push_back({a, b, ref});
  }
  for (std::uint32_t t = nt; t < tri.triangle_count(); ++t) {
    const std::uint32_t a = tri.vertex(t, 1), b = tri.vertex(t, 2);
    if (!listed.count(directed(std::min(a, b), std::max(a, b)))) constrained.push_back({a, b, 0});
  }
  Mesh2 mesh(tri, refs, constrained, metric);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (mesh.is_dead_vertex(v)) continue;
    mesh.set_flags(v, (mesh.flags(v) & Mesh2::kOnBoundary) ? static_cast<std::uint8_t>(Mesh2::kFixed | Mesh2::kOnBoundary) : 0);
  }
  return mesh;
}

}  // namespace dtlab
