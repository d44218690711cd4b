// The 3D mesher's field point methods (steps 3 and 4 of mesh3d.hpp), chosen by name from one
// table (registry.cpp). The contract is the 2D one (algorithms/mesh2d/registry.hpp) on Mesh3:
// field points until every internal edge is at most options.split_length long in the metric or
// no candidate survives the filter, inserted by the Delaunay kernel (delaunay_kernel.hpp), never
// through a constrained facet; the mesh is the same for every options.threads.
#pragma once

#include "algorithms/common/registry.hpp"
#include "algorithms/mesh3d/mesh3d.hpp"

namespace dtlab {

// Every registered method: the table of registry.cpp (algorithms/common/registry.hpp).
const Registry<FieldPointMethod3>& mesh3d_methods();

}  // namespace dtlab
