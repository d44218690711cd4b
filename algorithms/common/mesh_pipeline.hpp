// The pieces of the meshers' pipeline (algorithms/mesh2d/mesh2d.hpp, algorithms/mesh3d/mesh3d.hpp,
// book §7.12) that are the same in 2D and 3D: the options, counts and result they share, the
// phase clock, the metric of the empty mesh's vertices from the control space (end of step 2),
// steps 3 and 4 by the chosen method, the metric field and options of the optimization (step 5),
// and the output of the domain with its vertex metrics. Steps 1 and 2 and the optimization's
// operators stay per dimension.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/common/element_estimate.hpp"
#include "algorithms/common/registry.hpp"
#include "kernel/interrupt.hpp"

namespace dtlab {

// The options of both meshers. Traits: Method (the field point method's registry entry),
// ControlSpace, Optimization (the optimizer's options), kMaxVertices and optimization() (defaults).
template <class Traits>
struct MesherOptions {
  // Field point placement, a name from the dimension's methods (registry.hpp): "edge" (the edge
  // method, §7.5-§7.7) or "front" (advancing-front placement, §7.8); looked up in `methods` when given.
  std::string method = "edge";
  const Registry<typename Traits::Method>* methods = nullptr;
  // The size specification; null: the classical case (sizes from the boundary discretisation).
  const typename Traits::ControlSpace* control = nullptr;
  bool optimize = true;
  typename Traits::Optimization optimization = Traits::optimization();  // step 5
  // With a size or metric given, the boundary edges longer than sqrt 2 in it are cut first, so
  // that the size holds on the boundary too and a domain with no interior edge is still refined;
  // keep_boundary keeps the boundary as given (`messages` counts its long edges). Not in the
  // classical case, whose sizes come from the boundary itself.
  bool keep_boundary = false;
  // A field point closer than this (metric length, in the metric at the point) to a vertex that
  // would become its neighbour is filtered out.
  double filter_distance = 0.7;
  // Internal edges longer than this in the metric get field points.
  double split_length = 1.4142135623730951;
  // Bounds, each with a named error when reached: passes of the field point loop, vertices in all.
  std::uint32_t max_passes = 200;
  std::uint64_t max_vertices = Traits::kMaxVertices;
  // The elements the size or metric may ask for, estimated before any point is made from the
  // metric's complexity (element_estimate.hpp): past it, InputError with the estimate, and the
  // vertex bound is lowered. 0: half this machine's memory at the bytes an element costs. Not
  // checked in the classical case.
  std::uint64_t max_elements = 0;
  // Asked between the phases and at each pass of the field point loop (kernel/interrupt.hpp);
  // yes: Interrupted. The optimization asks its own check, or this one when it has none.
  InterruptCheck interrupt{};
};

// The counts of both meshers (Mesh2dStats and Mesh3dStats add their own).
struct MesherStats {
  double seconds_empty_mesh = 0, seconds_control_space = 0, seconds_field_points = 0, seconds_optimization = 0;
  double seconds = 0;  // the whole call
  std::uint32_t passes = 0;
  std::uint64_t field_points = 0;        // inserted
  std::uint64_t filtered = 0;            // candidates rejected as too close
  std::uint64_t not_inserted = 0;        // candidates outside the domain or that could not go in
  std::uint64_t cavity_corrections = 0;  // elements taken out of cavities (star-shapedness, §2.6.3)
  std::uint64_t input_points = 0;
  std::uint64_t boundary_points = 0;  // added on the boundary where it is longer than the size
  // Optimization counts, filled when it ran.
  std::uint64_t relocations = 0, collapses = 0, splits = 0;
  std::uint32_t optimization_rounds = 0;
};

template <class Mesh, class MeshData, class Metric, class Stats>
struct MesherResult {
  Mesh mesh;        // the whole structure, exterior included
  MeshData output;  // the domain: vertices, boundary with its references, elements with regions
  std::vector<std::uint32_t> output_vertex_ids;  // the slot in `mesh` of each output vertex
  std::vector<Metric> output_metrics;            // the metric at each output vertex
  Stats stats;
  std::vector<std::string> messages;  // from the empty mesh (duplicates, crossings, recovery ...)
};

}  // namespace dtlab

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

// The method named by options.method, after the options' check; InputError naming what is wrong.
template <class Options>
const auto& method_of(const char* mesher, const Options& options, const auto& built_in) {
  const auto& method = (options.methods ? *options.methods : built_in).at(options.method);
  if (!(options.filter_distance > 0.0 && options.filter_distance < 1.0)) {
    throw InputError(std::string(mesher) + ": filter_distance must lie in (0, 1)");
  }
  return method;
}

// The field point loop's check before pass `pass` (0-based) of `method`: the interrupt, then the
// pass bound (InputError naming it).
template <class Options, class Stats>
void check_pass(const char* mesher, const char* method, std::uint32_t pass, const Options& options, const Stats& stats) {
  if (options.interrupt && options.interrupt())
    throw Interrupted(std::string(mesher) + ": during the field points (" + method + ")");
  if (pass == options.max_passes) {
    throw InputError(std::string(mesher) + ": the " + method + " did not saturate within " +
                     std::to_string(options.max_passes) + " passes (" + std::to_string(stats.field_points) +
                     " field points so far)");
  }
}

// Steps 3 and 4: field points by `method` and their insertion, timed.
template <class Result, class Method, class ControlSpace, class Options>
void field_points(Result& result, const Method& method, const ControlSpace& control, const Options& bounded) {
  const auto phase = Clock::now();
  method.run(result.mesh, control, bounded, result.stats);
  result.stats.seconds_field_points = seconds_since(phase);
}

// Step 5, timed: with options.optimize, `optimize(field, optimization)` on the control space's
// field (one walk hint for all: moved and new points take their metric from it) and the options'
// optimization with the pipeline's interrupt check where it has none and no element estimate (the
// pipeline made it); the counts both dimensions keep go to result.stats.
template <class Field, class Result, class Options, class ControlSpace, class Optimize>
void optimize_step(Result& result, const Options& options, const ControlSpace& control, const Optimize& optimize) {
  const auto phase = Clock::now();
  if (options.optimize) {
    std::uint32_t field_hint = 0;
    const Field field = metric_field<Field>(control, field_hint);
    auto optimization = options.optimization;
    if (!optimization.interrupt) optimization.interrupt = options.interrupt;
    optimization.max_elements = element_estimate::kNoElementLimit;
    const auto o = optimize(field, optimization);
    result.stats.relocations = o.relocations;
    result.stats.collapses = o.collapses;
    result.stats.splits = o.splits;
    result.stats.optimization_rounds = o.rounds;
  }
  result.stats.seconds_optimization = seconds_since(phase);
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
