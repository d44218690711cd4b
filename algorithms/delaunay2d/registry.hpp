// The 2D Delaunay variants, chosen by name from one table (registry.cpp).
//
// A variant's contract: run(input, triangulation) receives distinct points, not all collinear
// (prepare.hpp), and a Triangulation2 holding the input points and no triangles. It fills the
// triangles so that, on return, the structure meets the contract of mesh/triangulation2.hpp
// (compact, closed by ghosts, input vertex ids, duplicates unreferenced) and is the Delaunay
// triangulation of input.distinct under the kernel's perturbed in-circle test
// (incircle_perturbed, kernel/predicates/perturbation.hpp) with exact orient2d, so that every
// variant yields the same set of triangles on every input. Ghost triangles decide conflicts as
// triangulation2.hpp says. A variant may reorder or overwrite triangulation.mutable_points()
// while it runs but must leave it equal to input.points. It throws InternalError on a broken
// invariant, never loops without bound, never exits.
//
// Adding a variant: one new file defining its run function, one line in the table.
#pragma once

#include <string_view>

#include "algorithms/common/registry.hpp"
#include "algorithms/delaunay2d/prepare.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

struct Delaunay2dVariant {
  std::string_view name;
  std::string_view description;
  void (*run)(const PreparedPoints2& input, Triangulation2& triangulation);
};

// Every registered variant: the table of registry.cpp (algorithms/common/registry.hpp).
const Registry<Delaunay2dVariant>& delaunay2d_variants();

}  // namespace dtlab
