// The 2D mesher's field point methods (steps 3 and 4 of mesh2d.hpp), chosen by name from one
// table (registry.cpp).
//
// A method's contract: run(mesh, control, options, stats) receives the empty mesh with a metric
// at every vertex (steps 1 and 2) and inserts field points until every internal edge is at most
// options.split_length long in the control space's metric or no candidate survives the filter,
// each by the constrained, anisotropic Delaunay kernel (delaunay_kernel.hpp), never crossing a
// constrained edge; it adds its counts to `stats`, polls options.interrupt, and throws InputError
// naming the bound (options.max_passes, options.max_vertices) it reaches.
#pragma once

#include "algorithms/common/registry.hpp"
#include "algorithms/mesh2d/mesh2d.hpp"

namespace dtlab {

// Every registered method: the table of registry.cpp (algorithms/common/registry.hpp).
const Registry<FieldPointMethod2>& mesh2d_methods();

}  // namespace dtlab
