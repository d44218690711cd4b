// The 2D mesher's pipeline (mesh2d.hpp): empty mesh, control space, field points, optimization.
#include "algorithms/mesh2d/mesh2d.hpp"

#include <chrono>
#include <memory>
#include <string>

#include "kernel/error.hpp"

namespace dtlab {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Mesh2dResult mesh2d(const Mesh2dInput& input, const Mesh2dOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (options.method != "edge" && options.method != "front") {
    throw InputError("unknown field point method '" + options.method + "' (edge, front)");
  }
  if (!(options.filter_distance > 0.0 && options.filter_distance < 1.0)) {
    throw InputError("mesh2d: filter_distance must lie in (0, 1)");
  }
  Mesh2dResult result;
  result.stats.input_points = input.points.size();
  result.stats.segments = input.segments.size();

  // 1. Empty mesh.
  auto phase = std::chrono::steady_clock::now();
  Constrained2dOptions cdt_options;
  cdt_options.method = "cdt";
  cdt_options.first_number = options.first_number;
  const Constrained2dResult cdt = constrained2d({.points = input.points,
                                                 .segments = input.segments,
                                                 .segment_markers = input.segment_markers,
                                                 .holes = input.holes,
                                                 .regions = input.regions},
                                                cdt_options);
  result.messages = cdt.messages;
  if (!cdt.degenerate_message.empty()) throw InputError("mesh2d: no domain: " + cdt.degenerate_message);
  if (cdt.triangles.empty()) {
    throw InputError("mesh2d: the domain has no triangle: the segments enclose no region (an open boundary?), or "
                     "the holes remove every region");
  }
  result.mesh = empty_mesh(cdt);
  result.stats.seconds_empty_mesh = seconds_since(phase);

  // 2. Control space: the given one, or the classical sizes on a frozen copy of the empty mesh.
  phase = std::chrono::steady_clock::now();
  std::unique_ptr<ControlSpace2> classical;
  if (!options.control && !options.input_metrics.empty()) {
    if (options.input_metrics.size() != input.points.size()) {
      throw InputError("mesh2d: " + std::to_string(options.input_metrics.size()) + " metrics for " +
                       std::to_string(input.points.size()) + " input points");
    }
    classical = std::make_unique<ControlSpace2>(input_control_space(result.mesh, options.input_metrics, options.interpolation));
  } else if (!options.control) {
    classical = std::make_unique<ControlSpace2>(classical_control_space(result.mesh));
  }
  const ControlSpace2& control = options.control ? *options.control : *classical;
  std::uint32_t hint = ControlSpace2::kNoHint;
  for (std::uint32_t v = 0; v < result.mesh.vertex_capacity(); ++v) {
    if (!result.mesh.is_dead_vertex(v)) result.mesh.set_metric(v, control.metric_at(result.mesh.point(v), hint));
  }
  result.stats.seconds_control_space = seconds_since(phase);

  // 3.+4. Field points and their insertion.
  phase = std::chrono::steady_clock::now();
  if (options.method == "edge") {
    insert_edge_points(result.mesh, control, options, result.stats);
  } else {
    throw InputError("the advancing-front placement (--method front) is not built yet");
  }
  result.stats.seconds_field_points = seconds_since(phase);

  // 5. Optimization.
  phase = std::chrono::steady_clock::now();
  result.stats.seconds_optimization = seconds_since(phase);

  result.output = result.mesh.domain(&result.output_vertex_ids);
  result.output_metrics.reserve(result.output_vertex_ids.size());
  for (const std::uint32_t v : result.output_vertex_ids) result.output_metrics.push_back(result.mesh.metric(v));
  result.stats.seconds = seconds_since(start);
  return result;
}

}  // namespace dtlab
