// 3D Delaunay tetrahedralization: the public entry point. One call, any registered variant
// (registry.hpp), one result structure for all of them.
//
//   dtlab::Delaunay3dResult r = dtlab::delaunay3d(points, {.algorithm = "incremental"});
//   for (auto [a, b, c, d] : r.tetrahedralization.finite_tetrahedra()) ...   // positive, input ids
//
// Every variant returns the same tetrahedra on every input (the perturbed Delaunay
// tetrahedralization, kernel/predicates/perturbation.hpp), degenerate input included.
#pragma once

#include <span>
#include <vector>

#include "algorithms/common/delaunay_call.hpp"
#include "kernel/vec.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

struct Delaunay3dVariant;  // registry.hpp

using Delaunay3dOptions = DelaunayOptions<Delaunay3dVariant>;  // algorithm: a name from delaunay3d_variants()

// The input points and, unless degenerate_message is set, their Delaunay tetrahedralization.
struct Delaunay3dResult : DelaunayReport {
  Tetrahedralization3 tetrahedralization;
};

// Throws InputError for an unknown algorithm (the message lists the known ones), for a point
// with a NaN, infinite or out-of-range coordinate (naming the point), for threads == 0, or for
// more than Tetrahedralization3::kMaxPoints points, or when the result would need more than
// Tetrahedralization3::kMaxTetrahedra tetrahedra (possible only for very large, very degenerate
// inputs such as points on the moment curve).
Delaunay3dResult delaunay3d(std::span<const Vec3> points, const Delaunay3dOptions& options = {});
// The same, taking the points over instead of copying them (they come back as
// result.tetrahedralization.points()): for large inputs, one copy fewer of the coordinates.
Delaunay3dResult delaunay3d(std::vector<Vec3>&& points, const Delaunay3dOptions& options = {});

}  // namespace dtlab
