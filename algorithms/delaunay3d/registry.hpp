// The 3D Delaunay variants, chosen by name from one table (registry.cpp).
//
// A variant's contract: run(input, options, tetrahedralization) receives distinct points, not
// all coplanar (prepare.hpp), and a Tetrahedralization3 holding the input points and no
// tetrahedra. It fills the tetrahedra so that, on return, the structure meets the contract of
// mesh/tetrahedralization3.hpp (compact, closed by ghosts, input vertex ids, duplicates
// unreferenced) and is the Delaunay tetrahedralization of input.distinct under the kernel's
// perturbed in-sphere test (insphere_perturbed, kernel/predicates/perturbation.hpp) with exact
// orient3d, so that every variant yields the same set of tetrahedra on every input. Ghost
// tetrahedra decide conflicts as tetrahedralization3.hpp says: strictly beyond the hull facet's
// plane, or on it and inside the facet's circle under the same perturbation (the cofactors
// that insphere_perturbed(a, b, c, d, p) uses for a coplanar p, with d the finite tetrahedron
// across the hull facet; see incremental.cpp). input.points is the very array
// tetrahedralization.points() holds (delaunay3d moves the caller's points there rather than
// copy them): a variant may reorder tetrahedralization.mutable_points() in place while it runs
// (input.points then shows the reordered coordinates: read what you need first) but must
// restore input order before it returns.
// It honours options.threads if it is parallel (predicate counts of worker threads are added to
// the caller's thread, stats.hpp), throws InternalError on a broken invariant, never loops
// without bound, never exits.
//
// Adding a variant (flip, divide-conquer, parallel, ...): one new file defining its run
// function, one line in the table of registry.cpp.
#pragma once

#include <string_view>

#include "algorithms/common/registry.hpp"
#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "algorithms/delaunay3d/prepare.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

struct Delaunay3dVariant {
  std::string_view name;
  std::string_view description;
  void (*run)(PreparedPoints3& input, const Delaunay3dOptions& options, Tetrahedralization3& tetrahedralization);
  // Whether it runs on options.threads threads; the shared preparation (prepare_points3) then
  // does too.
  bool threaded = false;
};

// Every registered variant: the table of registry.cpp (algorithms/common/registry.hpp).
const Registry<Delaunay3dVariant>& delaunay3d_variants();

}  // namespace dtlab
