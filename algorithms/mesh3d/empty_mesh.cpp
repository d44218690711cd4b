// Step 1 of the 3D mesher (book §7.2, §7.12 "construction of the empty mesh"): the empty mesh is
// the constrained tetrahedralization of the input surface, recovered with the fewest Steiner
// points, its regions coloured. The exterior (hull side, holes) stays in the structure as
// kExterior tetrahedra behind constrained facets until the output drops it.
#include <algorithm>
#include <array>
#include <vector>

#include "algorithms/mesh3d/mesh3d.hpp"
#include "kernel/error.hpp"

namespace dtlab {

namespace {

struct Keyed {
  std::array<std::uint32_t, 4> v;  // sorted
  int region;
};

}  // namespace

Mesh3 empty_mesh(const Constrained3dResult& r) {
  const Tetrahedralization3& tet = r.tetrahedralization;
  // The kept (domain) tetrahedra by their sorted vertices; every other one is exterior.
  std::vector<Keyed> kept(r.tetrahedra.size());
  for (std::size_t i = 0; i < r.tetrahedra.size(); ++i) {
    kept[i].v = r.tetrahedra[i];
    std::sort(kept[i].v.begin(), kept[i].v.end());
    kept[i].region = r.tetrahedron_regions.empty() ? 0 : r.tetrahedron_regions[i];
  }
  const auto less = [](const Keyed& a, const Keyed& b) { return a.v < b.v; };
  std::sort(kept.begin(), kept.end(), less);
  std::vector<int> refs(tet.tetrahedron_count(), Mesh3::kExterior);
  std::size_t found = 0;
  for (std::uint32_t t = 0; t < tet.tetrahedron_count(); ++t) {
    if (tet.is_ghost(t)) continue;
    Keyed k{tet.records()[t].vertex, 0};
    std::sort(k.v.begin(), k.v.end());
    const auto it = std::lower_bound(kept.begin(), kept.end(), k, less);
    if (it == kept.end() || it->v != k.v) continue;
    refs[t] = it->region;
    ++found;
  }
  DTLAB_ASSERT(found == r.tetrahedra.size());
  std::vector<MeshTriangle3> constrained;
  constrained.reserve(r.triangles.size());
  for (std::size_t i = 0; i < r.triangles.size(); ++i) {
    const auto& f = r.triangles[i];
    constrained.push_back({f[0], f[1], f[2], r.triangle_refs.empty() ? 0 : r.triangle_refs[i]});
  }
  return Mesh3(tet, refs, constrained);
}

}  // namespace dtlab
