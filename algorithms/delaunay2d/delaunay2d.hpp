// 2D Delaunay triangulation: the public entry point. One call, any registered variant
// (registry.hpp), one result structure for all of them.
//
//   dtlab::Delaunay2dResult r = dtlab::delaunay2d(points, {.algorithm = "incremental"});
//   for (auto [a, b, c] : r.triangulation.finite_triangles()) ...   // ccw, input ids
//
// Every variant returns the same triangles on every input (the perturbed Delaunay
// triangulation, kernel/predicates/perturbation.hpp), degenerate input included.
#pragma once

#include <span>

#include "algorithms/common/delaunay_call.hpp"
#include "kernel/vec.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

struct Delaunay2dVariant;  // registry.hpp

using Delaunay2dOptions = DelaunayOptions<Delaunay2dVariant>;  // algorithm: a name from delaunay2d_variants()

// The input points and, unless degenerate_message is set, their Delaunay triangulation.
struct Delaunay2dResult : DelaunayReport {
  Triangulation2 triangulation;
};

// Throws InputError for an unknown algorithm (the message lists the known ones), for a point
// with a NaN, infinite or out-of-range coordinate (naming the point), or for more than
// Triangulation2::kMaxPoints points.
Delaunay2dResult delaunay2d(std::span<const Vec2> points, const Delaunay2dOptions& options = {});

}  // namespace dtlab
