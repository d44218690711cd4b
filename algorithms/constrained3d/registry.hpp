// The constrained tetrahedralization methods, chosen by name from one table (registry.cpp).
//
// A method's contract: run(context) receives the Delaunay tetrahedralization of the input
// points in context.mesh and the input's edges and triangles (context.hpp); on return every
// input edge is a chain of mesh edges and every input triangle's pieces (context.facets[f].pieces)
// are mesh faces that triangulate it in its (s, t) parameters, the mesh is closed and valid
// (tetrahedralization3.hpp), and every Steiner point is recorded in context.steiner. It throws
// InputError naming the triangle or edge when its Steiner limit is reached, InternalError on a
// broken invariant, and never loops without bound.
#pragma once

#include <string_view>

#include "algorithms/common/registry.hpp"
#include "algorithms/constrained3d/context.hpp"

namespace dtlab {

struct Constrained3dMethod {
  std::string_view name;
  std::string_view description;
  void (*run)(Constrained3dContext& context);
};

// Every registered method: the table of registry.cpp (algorithms/common/registry.hpp).
const Registry<Constrained3dMethod>& constrained3d_methods();

}  // namespace dtlab
