// The pieces of the meshers' pipeline (algorithms/mesh2d/mesh2d.hpp, algorithms/mesh3d/mesh3d.hpp,
// book §7.12) that are the same in 2D and 3D: the phase clock, the metric of the empty mesh's
// vertices from the control space (end of step 2), the metric field the optimization asks
// (step 5), and the output of the domain with its vertex metrics. Steps 1, 3 and 4 and the
// optimization's operators stay per dimension.
#pragma once

#include <chrono>
#include <cstdint>
#include <vector>

namespace dtlab::mesh_pipeline {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Every live vertex of `mesh` takes the control space's metric at its point, one walk hint for all.
template <class Mesh, class ControlSpace>
void assign_vertex_metrics(Mesh& mesh, const ControlSpace& control) {
  std::uint32_t hint = ControlSpace::kNoHint;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (!mesh.is_dead_vertex(v)) mesh.set_metric(v, control.metric_at(mesh.point(v), hint));
  }
}

// The metric field of the optimization: the control space at any point, with one walk hint that
// `hint` holds (it must outlive the field).
template <class Field, class ControlSpace>
Field metric_field(const ControlSpace& control, std::uint32_t& hint) {
  hint = ControlSpace::kNoHint;
  return [&control, &hint](const auto& p) { return control.metric_at(p, hint); };
}

// The optimization's options with the pipeline's interrupt check where they have none.
template <class Options, class Check>
Options with_interrupt(Options options, const Check& interrupt) {
  if (!options.interrupt) options.interrupt = interrupt;
  return options;
}

// The result's output: the domain of result.mesh (exterior dropped), the slot of each output
// vertex, and the metric at each; the total time since `start`.
template <class Result>
void finish(Result& result, Clock::time_point start) {
  result.output = result.mesh.domain(&result.output_vertex_ids);
  result.output_metrics.reserve(result.output_vertex_ids.size());
  for (const std::uint32_t v : result.output_vertex_ids) result.output_metrics.push_back(result.mesh.metric(v));
  result.stats.seconds = seconds_since(start);
}

}  // namespace dtlab::mesh_pipeline
