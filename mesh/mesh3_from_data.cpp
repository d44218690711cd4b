// Building a Mesh3 from a neutral 3D mesh (mesh3_from_data.hpp).
#include "mesh/mesh3_from_data.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/element_sets3.hpp"
#include "mesh/navigation3.hpp"
#include "mesh/tetrahedralization3_build.hpp"

namespace dtlab {

namespace {

using T3 = Tetrahedralization3;

struct TripleHash {
  std::size_t operator()(const std::array<std::uint32_t, 3>& k) const noexcept {
    std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
    h ^= (h >> 29) + k[1] * 0xBF58476D1CE4E5B9ull;
    h ^= (h >> 31) + k[2] * 0x94D049BB133111EBull;
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
};

std::array<std::uint32_t, 3> sorted(std::array<std::uint32_t, 3> v) noexcept {
  std::sort(v.begin(), v.end());
  return v;
}

std::string number(std::uint64_t i) { return std::to_string(i + 1); }

// Every vertex's tetrahedra (ghosts included) must be connected across the facets that hold it,
// or Mesh3::ball would see only part of them: the boundary pinches there (two solids touching at
// a vertex).
void check_vertex_balls(const T3& tet) {
  const std::size_t n = tet.point_count();
  const auto& records = tet.records();
  const std::vector<std::uint32_t> first = vertex_tetrahedra(tet, Incident::First);
  std::vector<std::uint32_t> incident(n, 0);
  for (const auto& r : records)
    for (const std::uint32_t v : r.vertex)
      if (v != T3::kInfinite) ++incident[v];
  std::vector<std::uint32_t> stamp(records.size(), T3::kNone), queue;
  for (std::uint32_t v = 0; v < n; ++v) {
    if (first[v] == T3::kNone) continue;
    nav3::ball(tet, v, first[v], queue, nav3::marking(stamp, v));
    if (queue.size() != incident[v]) {
      throw InputError("the boundary is not a closed 2-manifold at vertex " + number(v) +
                           " (its tetrahedra are not connected across facets: two solids touch there)",
                       {v});
    }
  }
}

}  // namespace

Mesh3 mesh3_from_data(const MeshData3& data, const Metric3& metric, std::vector<std::string>* messages) {
  const std::size_t n = data.vertices.size();
  const std::size_t nt = data.tetrahedra.size();
  // An empty mesh would reach the algorithms as one with no domain (no boundary, no metric).
  if (nt == 0) throw InputError("no tetrahedra (" + std::to_string(n) + " vertices): a mesh needs at least one");
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& v = data.tetrahedra[t];
    for (const std::uint32_t x : v)
      if (x >= n)
        throw InputError("tetrahedron " + number(t) + " uses vertex " + number(x) + ", out of range (" +
                             std::to_string(n) + " vertices)",
                         {t});
    if (orient3d(data.vertices[v[0]], data.vertices[v[1]], data.vertices[v[2]], data.vertices[v[3]]) != Sign::Positive)
      throw InputError("tetrahedron " + number(t) + " is not positive (flat or negative)", {t});
  }
  const T3 tet = tetrahedralization_from_tetrahedra(data.vertices, data.tetrahedra);
  check_vertex_balls(tet);
  const auto& records = tet.records();

  std::vector<int> refs(records.size(), Mesh3::kExterior);
  for (std::size_t t = 0; t < nt; ++t) refs[t] = data.tetrahedron_refs.empty() ? 0 : data.tetrahedron_refs[t];

  // Constrained: the listed triangles (first listing wins), then the boundary facets and the
  // facets between different references that are not listed (reference 0).
  std::unordered_map<std::array<std::uint32_t, 3>, std::uint32_t, TripleHash> listed;
  listed.reserve(2 * data.triangles.size() + 16);
  std::vector<MeshTriangle3> constrained;
  std::vector<std::uint32_t> constrained_listing;  // the Triangles entry of each listed constraint
  std::vector<std::uint8_t> found;
  for (std::size_t i = 0; i < data.triangles.size(); ++i) {
    const auto& f = data.triangles[i];
    for (const std::uint32_t x : f)
      if (x >= n)
        throw InputError("triangle " + number(i) + " uses vertex " + number(x) + ", out of range (" +
                             std::to_string(n) + " vertices)",
                         {i});
    if (!listed.emplace(sorted(f), static_cast<std::uint32_t>(i)).second) continue;
    constrained.push_back({f[0], f[1], f[2], data.triangle_refs.empty() ? 0 : data.triangle_refs[i]});
    constrained_listing.push_back(static_cast<std::uint32_t>(i));
  }
  found.assign(data.triangles.size(), 0);
  std::vector<std::uint8_t> interior(data.triangles.size(), 0);  // listed, one region on both sides
  std::size_t interior_facets = 0, interior_listed = 0;
  for (std::uint32_t t = 0; t < nt; ++t)
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = T3::facet(t, i);
      const auto f = tet.facet_vertices(h);
      const std::uint32_t u = T3::tetrahedron_of(tet.twin(h));
      const bool same_region_inside = !tet.is_ghost(u) && refs[u] == refs[t];
      if (same_region_inside && t < u) ++interior_facets;
      const auto it = listed.find(sorted(f));
      if (it != listed.end()) {
        found[it->second] = 1;
        if (same_region_inside && t < u) interior[it->second] = 1, ++interior_listed;
        continue;
      }
      if (tet.is_ghost(u) || (refs[u] != refs[t] && t < u)) constrained.push_back({f[0], f[1], f[2], 0});
    }
  for (std::size_t i = 0; i < data.triangles.size(); ++i) {
    const auto& f = data.triangles[i];
    if (!found[i] && listed.at(sorted(f)) == i)
      throw InputError("triangle " + number(i) + " (" + number(f[0]) + ", " + number(f[1]) + ", " + number(f[2]) +
                           ") is not a facet of the tetrahedra",
                       {i});
  }

  // Interior faces listed as Triangles with one region on both sides: internal constraints when
  // some are listed; when every interior face is (TetGen's -g output lists every face), none is a
  // constraint, else nothing could move. Either way it is said, never silent.
  if (interior_listed > 0) {
    const bool all = interior_listed == interior_facets;
    if (all) {
      std::size_t k = 0;
      for (std::size_t c = 0; c < constrained.size(); ++c)
        if (c >= constrained_listing.size() || !interior[constrained_listing[c]]) constrained[k++] = constrained[c];
      constrained.resize(k);
    }
    if (messages)
      messages->push_back(std::to_string(interior_listed) + " Triangles entr" + (interior_listed == 1 ? "y is" : "ies are") +
                          " interior face" + (interior_listed == 1 ? "" : "s") + " with one region on both sides" +
                          (all ? ": every interior face is listed (as TetGen's -g writes them), so none is kept as a "
                                 "constraint"
                               : ", kept as internal constraints (never moved or swapped)"));
  }
  Mesh3 mesh(tet, refs, constrained, metric);
  for (std::size_t e = 0; e < data.edges.size(); ++e) {
    const auto [a, b] = data.edges[e];
    if (a >= n || b >= n || a == b || mesh.find_edge(a, b) == Mesh3::kNone)
      throw InputError("edge " + number(e) + " (" + number(a) + ", " + number(b) + ") is not an edge of the tetrahedra", {e});
    mesh.set_constrained_edge(a, b, true);
    mesh.set_flags(a, mesh.flags(a) | Mesh3::kOnBoundary);
    mesh.set_flags(b, mesh.flags(b) | Mesh3::kOnBoundary);
  }
  for (std::uint32_t v = 0; v < n; ++v) {
    if (mesh.is_dead_vertex(v)) continue;
    mesh.set_flags(v, (mesh.flags(v) & Mesh3::kOnBoundary) ? static_cast<std::uint8_t>(Mesh3::kFixed | Mesh3::kOnBoundary) : 0);
  }
  return mesh;
}

}  // namespace dtlab
