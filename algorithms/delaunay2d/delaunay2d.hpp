// 2D Delaunay triangulation: the public entry point. One call, any registered variant
// (registry.hpp), one result structure for all of them.
//
//   dtlab::Delaunay2dResult r = dtlab::delaunay2d(points, {.algorithm = "incremental"});
//   for (auto [a, b, c] : r.triangulation.finite_triangles()) ...   // ccw, input ids
//
// Every variant returns the same triangles on every input (the perturbed Delaunay
// triangulation, kernel/predicates/perturbation.hpp), degenerate input included.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/stats.hpp"
#include "kernel/vec.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

template <class Entry>
class Registry;  // algorithms/common/registry.hpp
struct Delaunay2dVariant;  // registry.hpp

struct Delaunay2dOptions {
  std::string algorithm = "incremental";   // a name from delaunay2d_variants()
  std::uint64_t seed = 0x5EED'D71A'B000'0001ull;  // randomised steps (BRIO); fixed for reproducibility
  const Registry<Delaunay2dVariant>* variants = nullptr;  // where `algorithm` is looked up; null: delaunay2d_variants()
};

struct Delaunay2dResult {
  // The input points and, unless degenerate_message is set, their Delaunay triangulation.
  Triangulation2 triangulation;
  // Input indices dropped as duplicates (ascending) and, for each, the first index with the
  // same coordinates (the one kept). Dropped points are referenced by no triangle.
  std::vector<std::uint32_t> duplicates;
  std::vector<std::uint32_t> duplicate_of;
  // Empty, or why there are no triangles: fewer than 3 distinct points, all points collinear.
  std::string degenerate_message;
  // This thread's predicate counts over the call (stats.hpp).
  PredicateStats predicate_stats;
  // Wall time of the call (checks, duplicate detection, triangulation), in seconds.
  double seconds = 0.0;
};

// Throws InputError for an unknown algorithm (the message lists the known ones), for a point
// with a NaN, infinite or out-of-range coordinate (naming the point), or for more than
// Triangulation2::kMaxPoints points.
Delaunay2dResult delaunay2d(std::span<const Vec2> points, const Delaunay2dOptions& options = {});

}  // namespace dtlab
