// Step 1 of the 2D mesher (book §5.2, as §7.3 describes it in 3D): the empty mesh is the
// constrained Delaunay triangulation of the boundary discretisation with its regions coloured.
// The exterior and the holes stay in the structure as kExterior triangles, behind constrained
// edges, until the output drops them. constrained2d hands over each slot's region and a half-edge
// of each constrained edge, so nothing is looked up here.
#include "algorithms/mesh2d/mesh2d.hpp"

namespace dtlab {

Mesh2 empty_mesh(const Constrained2dResult& cdt) {
  Mesh2 mesh(cdt.triangulation, cdt.slot_regions, {});
  for (const ConstrainedEdge2& e : cdt.constrained_edges) {
    mesh.set_constraint_both(e.half_edge, true, e.marker);
    for (const std::uint32_t v : {e.a, e.b}) mesh.set_flags(v, mesh.flags(v) | Mesh2::kOnBoundary);
  }
  return mesh;
}

}  // namespace dtlab
