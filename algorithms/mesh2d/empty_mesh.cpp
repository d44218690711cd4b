// Step 1 of the 2D mesher (book §5.2, as §7.3 describes it in 3D): the empty mesh is the
// constrained Delaunay triangulation of the boundary discretisation with its regions coloured.
// The exterior and the holes stay in the structure as kExterior triangles, behind constrained
// edges, until the output drops them.
#include <string>
#include <unordered_map>

#include "algorithms/mesh2d/mesh2d.hpp"
#include "kernel/error.hpp"

namespace dtlab {

namespace {

// A triangle's key, invariant under rotation (the smallest vertex first, order kept).
std::array<std::uint32_t, 3> canonical(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  if (b < a && b < c) return {b, c, a};
  if (c < a && c < b) return {c, a, b};
  return {a, b, c};
}

struct KeyHash {
  std::size_t operator()(const std::array<std::uint32_t, 3>& k) const noexcept {
    std::uint64_t h = k[0];
    h = h * 0x9E3779B97F4A7C15ull ^ k[1];
    h = h * 0x9E3779B97F4A7C15ull ^ k[2];
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

}  // namespace

Mesh2 empty_mesh(const Constrained2dResult& cdt) {
  const Triangulation2& tri = cdt.triangulation;
  std::unordered_map<std::array<std::uint32_t, 3>, int, KeyHash> region;
  region.reserve(cdt.triangles.size() * 2);
  for (std::size_t i = 0; i < cdt.triangles.size(); ++i) {
    const auto& t = cdt.triangles[i];
    region.emplace(canonical(t[0], t[1], t[2]), cdt.triangle_region.empty() ? 0 : cdt.triangle_region[i]);
  }
  std::vector<int> refs(tri.triangle_count(), Mesh2::kExterior);
  std::size_t found = 0;
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    if (tri.is_ghost(t)) continue;
    const auto it = region.find(canonical(tri.vertex(t, 0), tri.vertex(t, 1), tri.vertex(t, 2)));
    if (it == region.end()) continue;
    refs[t] = it->second;
    ++found;
  }
  DTLAB_ASSERT(found == cdt.triangles.size());
  std::vector<MeshEdge2> edges;
  edges.reserve(cdt.constrained_edges.size());
  for (const ConstrainedEdge2& e : cdt.constrained_edges) edges.push_back({e.a, e.b, e.marker});
  return Mesh2(tri, refs, edges);
}

}  // namespace dtlab
