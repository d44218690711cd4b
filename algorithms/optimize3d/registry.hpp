// The 3D optimization operators as the rounds of the strategy (optimize3d.hpp, book §8.6) run
// them: by name from one table (registry.cpp), in the order of Optimize3dOptions::sequence.
//
// An operator's contract: pass(mesh, options, field, stats, scope) applies it once to the mesh
// (a pass over its edges, vertices or bad tetrahedra, within scope.region when that is not
// empty), each change as §8.6.1 asks (operators.hpp), or does nothing when its option is off; it
// adds its counts to `stats` and returns its size changes and, when it stopped at a bound, limit
// with stats.stopped_by naming the bound.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "algorithms/common/registry.hpp"
#include "algorithms/optimize3d/optimize3d.hpp"

namespace dtlab {

namespace optimize3d_detail {
struct AttemptMemo;  // local.hpp
}

// What a round hands its operators besides the mesh, options, field and stats (strategy.cpp).
struct OperatorScope3 {
  // With a goal and goal_rings, after the first round: the vertices (by slot, != 0) the passes
  // work on; empty: all.
  std::span<const std::uint8_t> region;
  std::span<const std::uint32_t> seeds;   // the domain tetrahedra with a vertex in the region
  optimize3d_detail::AttemptMemo* memo;   // the failures remembered (options.remember_failures), or null
};

struct Optimize3dOperator {
  std::string_view name;
  std::string_view description;
  OperatorResult (*pass)(Mesh3& mesh, const Optimize3dOptions& options, const MetricField3& field,
                         Optimize3dStats& stats, const OperatorScope3& scope);
};

// Every registered operator, in the book's order: the table of registry.cpp.
const Registry<Optimize3dOperator>& optimize3d_operators();

namespace optimize3d_detail {
// The bad tetrahedra, worst first, each by the operators its pathology calls for (strategy.cpp).
OperatorResult treat_bad_tetrahedra(Mesh3& mesh, const Optimize3dOptions& options, const MetricField3& field,
                                    Optimize3dStats& stats, const OperatorScope3& scope);
}  // namespace optimize3d_detail

}  // namespace dtlab
