// Variant "parallel" of the 3D Delaunay tetrahedralization: being written (issue 5); until then it
// refuses to run rather than return anything.
#include "algorithms/delaunay3d/registry.hpp"
#include "kernel/error.hpp"

namespace dtlab {

void delaunay3d_parallel(const PreparedPoints3& /*input*/, const Delaunay3dOptions& /*options*/,
                            Tetrahedralization3& /*tetrahedralization*/) {
  throw InternalError("3D Delaunay variant 'parallel' is not built yet");
}

}  // namespace dtlab
