#include "algorithms/constrained3d/registry.hpp"

namespace dtlab {

void constrained3d_conforming(Constrained3dContext& context);
void constrained3d_recover(Constrained3dContext& context);
void constrained3d_cdt(Constrained3dContext& context);

const Registry<Constrained3dMethod>& constrained3d_methods() {
  static const Registry<Constrained3dMethod> entries{
      "constrained tetrahedralization method",
      {Constrained3dMethod{"conforming",
     "Delaunay of the vertices, then missing edge pieces split (concentric shells) and missing "
     "triangle pieces refined (circumcentres, Ruppert's rule) until the Delaunay "
     "tetrahedralization holds every input edge and triangle; Steiner points on the boundary only",
     &constrained3d_conforming},
    Constrained3dMethod{"recover",
     "Delaunay of the vertices, then missing edges recovered by flips along their pipes and missing "
     "triangles by removing the edges that cross them (2-3 flips, edge removal by shell "
     "retriangulation); Steiner points, as in conforming, only where these fail (where they "
     "cascade, conforming's result); not Delaunay",
     &constrained3d_recover},
    Constrained3dMethod{"cdt",
     "constrained Delaunay tetrahedralization of the meshed regions: recover's result made "
     "constrained Delaunay by flips, constraint pieces that block a flip split; where that fails, "
     "Shewchuk's construction (segments split until Delaunay, missing triangles inserted by "
     "cavity retriangulation)",
     &constrained3d_cdt}}};
  return entries;
}

}  // namespace dtlab
