// Region colouring by breadth-first search across unconstrained facets (regions.hpp; book §5.2).
#include "algorithms/constrained3d/regions.hpp"

#include <algorithm>
#include <set>

#include "kernel/predicates.hpp"

namespace dtlab {

using T3 = Tetrahedralization3;

TetrahedronComponents tetrahedron_components(const Tetrahedralization3& mesh,
                                             std::span<const std::array<std::uint32_t, 3>> walls) {
  std::set<std::array<std::uint32_t, 3>> wall;
  for (auto w : walls) {
    std::sort(w.begin(), w.end());
    wall.insert(w);
  }
  TetrahedronComponents c;
  const std::size_t n = mesh.tetrahedron_count();
  c.component.assign(n, T3::kNone);
  c.exterior = T3::kNone;
  std::vector<std::uint32_t> queue;
  for (std::uint32_t s = 0; s < n; ++s) {
    if (c.component[s] != T3::kNone) continue;
    const std::uint32_t id = c.count++;
    c.component[s] = id;
    queue.assign(1, s);
    while (!queue.empty()) {
      const std::uint32_t t = queue.back();
      queue.pop_back();
      if (mesh.is_ghost(t)) c.exterior = id;
      for (std::uint32_t i = 0; i < 4; ++i) {
        const std::uint32_t u = mesh.adjacent(t, i);
        if (c.component[u] != T3::kNone) continue;
        auto f = mesh.facet_vertices(T3::facet(t, i));
        std::sort(f.begin(), f.end());
        if (wall.count(f)) continue;
        c.component[u] = id;
        queue.push_back(u);
      }
    }
  }
  return c;
}

std::uint32_t tetrahedron_containing(const Tetrahedralization3& mesh, const Vec3& p) {
  const auto pts = mesh.points();
  for (std::uint32_t t = 0; t < mesh.tetrahedron_count(); ++t) {
    if (mesh.is_ghost(t)) continue;
    bool inside = true;
    for (std::uint32_t i = 0; i < 4 && inside; ++i) {
      const auto f = mesh.facet_vertices(T3::facet(t, i));
      inside = orient3d(pts[f[0]], pts[f[1]], pts[f[2]], p) != Sign::Negative;
    }
    if (inside) return t;
  }
  return T3::kNone;
}

}  // namespace dtlab
