// Variant "flip" of the 3D Delaunay tetrahedralization: being written (issue 5); until then it
// refuses to run rather than return anything.
#include "algorithms/delaunay3d/registry.hpp"
#include "kernel/error.hpp"

namespace dtlab {

void delaunay3d_flip(const PreparedPoints3& /*input*/, const Delaunay3dOptions& /*options*/,
                            Tetrahedralization3& /*tetrahedralization*/) {
  throw InternalError("3D Delaunay variant 'flip' is not built yet");
}

}  // namespace dtlab
