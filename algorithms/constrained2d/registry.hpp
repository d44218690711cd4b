// The constrained triangulation methods, chosen by name from one table (registry.cpp).
//
// A method's contract: run(context) receives the Delaunay triangulation of the input points in
// context.mesh and the validated segments; on return every segment is a chain of constrained
// edges of a closed, valid triangulation (triangulation2.hpp), with the method's property:
// "swap" none beyond that, "cdt" constrained Delaunay (§3.4, Definition 3.6), "conforming"
// Delaunay. It throws InternalError on a broken invariant, never loops without bound.
#pragma once

#include <string_view>

#include "algorithms/common/registry.hpp"
#include "algorithms/constrained2d/context.hpp"

namespace dtlab {

struct Constrained2dMethod {
  std::string_view name;
  std::string_view description;
  void (*run)(const Constrained2dContext& context);
};

// Every registered method: the table of registry.cpp (algorithms/common/registry.hpp).
const Registry<Constrained2dMethod>& constrained2d_methods();

}  // namespace dtlab
