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

#include <span>
#include <string_view>

#include "algorithms/constrained3d/context.hpp"

namespace dtlab {

struct Constrained3dMethod {
  std::string_view name;
  std::string_view description;
  void (*run)(Constrained3dContext& context);
};

std::span<const Constrained3dMethod> constrained3d_methods() noexcept;
const Constrained3dMethod* find_constrained3d_method(std::string_view name) noexcept;

}  // namespace dtlab
