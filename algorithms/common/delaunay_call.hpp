// What a Delaunay call is in 2D and 3D alike (algorithms/delaunay2d/delaunay2d.hpp,
// algorithms/delaunay3d/delaunay3d.hpp): its options, the report beside the triangulation, and
// the frame around the variant (predicate counts, clock, the preparation's findings).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "kernel/stats.hpp"

namespace dtlab {

template <class Entry>
class Registry;  // algorithms/common/registry.hpp

template <class Variant>
struct DelaunayOptions {
  std::string algorithm = "incremental";          // a name from the dimension's variants (registry.hpp)
  std::uint64_t seed = 0x5EED'D71A'B000'0001ull;  // randomised steps (BRIO); fixed for reproducibility
  unsigned threads = 1;                           // for parallel variants; sequential ones ignore it
  const Registry<Variant>* variants = nullptr;    // where `algorithm` is looked up; null: the built-in table
};

// Delaunay2dResult and Delaunay3dResult: this and the triangulation.
struct DelaunayReport {
  // Input indices dropped as duplicates (ascending) and, for each, the first index with the
  // same coordinates (the one kept). Dropped points are referenced by no element.
  std::vector<std::uint32_t> duplicates;
  std::vector<std::uint32_t> duplicate_of;
  // Empty, or why there are no elements (too few distinct points, all collinear or coplanar).
  std::string degenerate_message;
  // This thread's predicate counts over the call (stats.hpp); a parallel variant adds its
  // workers' counts.
  PredicateStats predicate_stats;
  // Wall time of the call (checks, duplicate detection, triangulation), in seconds.
  double seconds = 0.0;
};

// The call: `build(result)` prepares the points (prepare.hpp), runs the variant on them unless
// they are degenerate and returns them; their findings go to the result with the counts and time.
template <class Result, class Build>
Result delaunay_call(const Build& build) {
  const PredicateStats before = predicate_stats();
  const auto start = std::chrono::steady_clock::now();
  Result result;
  auto prepared = build(result);
  result.duplicates = std::move(prepared.duplicates);
  result.duplicate_of = std::move(prepared.duplicate_of);
  result.degenerate_message = std::move(prepared.degenerate_message);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.predicate_stats = predicate_stats() - before;
  return result;
}

}  // namespace dtlab
