#include "algorithms/constrained2d/registry.hpp"

namespace dtlab {

void constrained2d_conforming(const Constrained2dContext& context);  // conforming.cpp

namespace {

// §3.3.3: the segments enforced by swaps; the rest of the Delaunay triangulation as it was.
void run_swap(const Constrained2dContext& context) { resolve_and_enforce_segments(context); }

// §3.4: insertion (the Delaunay triangulation), enforcement, then Lawson flips of every
// non-constrained edge that fails the perturbed empty-circle test. An edge between two
// triangles sees every point visible from its triangles' vertices, so local constrained
// Delaunay everywhere is Definition 3.6 (Lee and Lin 1986, Chew 1989). Edges whose two
// triangles enforcement left as they were are still locally Delaunay: Lawson starts from the
// edges of the triangles it wrote.
void run_cdt(const Constrained2dContext& context) {
  resolve_and_enforce_segments(context);
  context.mesh.lawson(context.mesh.take_changed_edges(), true);
}

}  // namespace

const Registry<Constrained2dMethod>& constrained2d_methods() {
  static const Registry<Constrained2dMethod> entries{
      "constrained triangulation method",
      {    Constrained2dMethod{"cdt",
                        "constrained Delaunay (§3.4): segments enforced by swaps along their pipes, then Lawson "
                        "flips of every non-constrained edge failing the empty circle",
                        &run_cdt},
    Constrained2dMethod{"swap",
                        "enforcement by edge swapping along each segment's pipe (§3.3.3: Sloan's queue, or a "
                        "random order with --swap-order random); no Steiner points beyond crossings; not Delaunay",
                        &run_swap},
    Constrained2dMethod{"conforming",
                        "conforming Delaunay (§3.2, §3.3.2): pieces that are not Delaunay edges split (midpoint, or "
                        "concentric power-of-two shells around input vertices) until all are; result Delaunay",
                        &constrained2d_conforming}}};
  return entries;
}

}  // namespace dtlab
