// 3D Delaunay tetrahedralization: the public entry point. One call, any registered variant
// (registry.hpp), one result structure for all of them.
//
//   dtlab::Delaunay3dResult r = dtlab::delaunay3d(points, {.algorithm = "incremental"});
//   for (auto [a, b, c, d] : r.tetrahedralization.finite_tetrahedra()) ...   // positive, input ids
//
// Every variant returns the same tetrahedra on every input (the perturbed Delaunay
// tetrahedralization, kernel/predicates/perturbation.hpp), degenerate input included.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/stats.hpp"
#include "kernel/vec.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

template <class Entry>
class Registry;  // algorithms/common/registry.hpp
struct Delaunay3dVariant;  // registry.hpp

struct Delaunay3dOptions {
  std::string algorithm = "incremental";          // a name from delaunay3d_variants()
  std::uint64_t seed = 0x5EED'D71A'B000'0001ull;  // randomised steps (BRIO); fixed for reproducibility
  unsigned threads = 1;                           // for parallel variants; sequential ones ignore it
  const Registry<Delaunay3dVariant>* variants = nullptr;  // where `algorithm` is looked up; null: delaunay3d_variants()
};

struct Delaunay3dResult {
  // The input points and, unless degenerate_message is set, their Delaunay tetrahedralization.
  Tetrahedralization3 tetrahedralization;
  // Input indices dropped as duplicates (ascending) and, for each, the first index with the
  // same coordinates (the one kept). Dropped points are referenced by no tetrahedron.
  std::vector<std::uint32_t> duplicates;
  std::vector<std::uint32_t> duplicate_of;
  // Empty, or why there are no tetrahedra: fewer than 4 distinct points, all points collinear
  // or coplanar.
  std::string degenerate_message;
  // This thread's predicate counts over the call (stats.hpp); a parallel variant adds its
  // workers' counts.
  PredicateStats predicate_stats;
  // Wall time of the call (checks, duplicate detection, tetrahedralization), in seconds.
  double seconds = 0.0;
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
