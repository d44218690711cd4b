// Step 1 of the 3D mesher (book §7.2, §7.12 "construction of the empty mesh"): the empty mesh is
// the constrained tetrahedralization of the input surface, recovered with the fewest Steiner
// points, its regions coloured. The exterior (hull side, holes) stays in the structure as
// kExterior tetrahedra behind constrained facets until the output drops it. constrained3d hands
// over each slot's region and a facet handle of each constrained triangle, so nothing is looked up.
#include "algorithms/mesh3d/mesh3d.hpp"
#include "kernel/error.hpp"

namespace dtlab {

Mesh3 empty_mesh(const Constrained3dResult& r) {
  Mesh3 mesh(r.tetrahedralization, r.slot_regions, {});
  for (std::size_t k = 0; k < r.triangles.size(); ++k) {
    const auto& [a, b, c] = r.triangles[k];
    DTLAB_ASSERT(r.triangle_facets[k] != Mesh3::kNone);
    mesh.constrain_triangle(r.triangle_facets[k], {a, b, c, r.triangle_refs[k]});
  }
  return mesh;
}

}  // namespace dtlab
