// The 2D optimization operators as the rounds of the strategy (optimize2d.hpp, book §8.6.3) run
// them: by name from one table (registry.cpp), in the order of Optimize2dOptions::sequence.
//
// An operator's contract: pass(mesh, options, field, stats) applies it once to the mesh (a pass
// over its edges, vertices or bad triangles), each change as §8.6.1 asks (operators.hpp), or does
// nothing when its option is off; it adds its counts to `stats` and returns its size changes and,
// when it stopped at a bound, limit with stats.stopped_by naming the bound.
#pragma once

#include <string_view>

#include "algorithms/common/registry.hpp"
#include "algorithms/optimize2d/optimize2d.hpp"

namespace dtlab {

struct Optimize2dOperator {
  std::string_view name;
  std::string_view description;
  OperatorResult (*pass)(Mesh2& mesh, const Optimize2dOptions& options, const MetricField2& field,
                         Optimize2dStats& stats);
};

// Every registered operator, in the book's order: the table of registry.cpp.
const Registry<Optimize2dOperator>& optimize2d_operators();

namespace optimize2d_detail {
// The bad triangles, worst first, each by the operators its pathology calls for (strategy.cpp).
OperatorResult treat_bad_triangles(Mesh2& mesh, const Optimize2dOptions& options, const MetricField2& field,
                                   Optimize2dStats& stats);
}  // namespace optimize2d_detail

}  // namespace dtlab
