// The 2D mesher's pipeline (mesh2d.hpp): empty mesh, control space, field points, optimization.
#include "algorithms/mesh2d/mesh2d.hpp"

#include <algorithm>
#include <cstring>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algorithms/common/element_estimate.hpp"
#include "algorithms/common/mesh_pipeline.hpp"
#include "algorithms/mesh2d/registry.hpp"
#include "algorithms/optimize2d/optimize2d.hpp"
#include "kernel/error.hpp"
#include "kernel/interrupt.hpp"

namespace dtlab {

using mesh_pipeline::seconds_since;

namespace {

// The control space's one metric when every vertex of its live finite triangles carries the same
// bits (a uniform size): metric_at returns a vertex's metric, or the interpolation of three equal
// ones, which is one of them, wherever it locates p; nullopt otherwise. The optimizer asks the
// field at every candidate point of a relocation: the constant spares the walk, same values.
std::optional<Metric2> constant_metric(const ControlSpace2& control) {
  const Mesh2& background = control.background();
  const std::vector<Metric2>& metrics = control.vertex_metrics();
  std::optional<Metric2> common;
  for (std::uint32_t t = 0; t < background.triangle_capacity(); ++t) {
    if (!background.is_alive(t) || background.is_ghost(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const Metric2& m = metrics[background.vertex(t, i)];
      if (!common) common = m;
      else if (std::memcmp(common->m.data(), m.m.data(), sizeof(m.m)) != 0) return std::nullopt;
    }
  }
  return common;
}

}  // namespace

Mesh2dResult mesh2d(const Mesh2dInput& input, const Mesh2dOptions& options) {
  const auto start = mesh_pipeline::Clock::now();
  const FieldPointMethod2& method = mesh_pipeline::method_of("mesh2d", options, mesh2d_methods());
  Mesh2dResult result;
  result.stats.input_points = input.points.size();
  result.stats.segments = input.segments.size();

  // 1. Empty mesh.
  auto phase = mesh_pipeline::Clock::now();
  Constrained2dOptions cdt_options;
  cdt_options.method = "cdt";
  cdt_options.first_number = options.first_number;
  const auto build_empty_mesh = [&](std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 2>> segments,
                                    std::span<const int> markers) {
    const Constrained2dResult cdt = constrained2d(
        {.points = points, .segments = segments, .segment_markers = markers, .holes = input.holes, .regions = input.regions},
        cdt_options);
    result.messages = cdt.messages;
    if (!cdt.degenerate_message.empty()) throw InputError("mesh2d: no domain: " + cdt.degenerate_message);
    if (cdt.triangles.empty()) {
      throw InputError("mesh2d: the domain has no triangle: the segments enclose no region (an open boundary?), or "
                       "the holes remove every region");
    }
    Mesh2 mesh = empty_mesh(cdt);
    // Segments with no piece beside the domain are not meshed: say so, naming them.
    std::vector<std::uint8_t> inside(segments.size(), 0);
    for (const ConstrainedEdge2& e : cdt.constrained_edges) {
      const std::uint32_t h = e.half_edge;
      if (mesh.in_domain(Mesh2::triangle_of(h)) || mesh.in_domain(Mesh2::triangle_of(mesh.twin(h)))) inside[e.segment] = 1;
    }
    std::string outside;
    std::size_t count = 0;
    for (std::size_t k = 0; k < segments.size(); ++k) {
      if (inside[k]) continue;
      if (++count <= 20) outside += (outside.empty() ? "" : ", ") + std::to_string(k + options.first_number);
    }
    if (count > 0) {
      result.messages.push_back(std::to_string(count) + " segment(s) outside the domain, not meshed: " + outside +
                                (count > 20 ? ", ..." : ""));
    }
    return mesh;
  };
  result.mesh = build_empty_mesh(input.points, input.segments, input.segment_markers);
  result.stats.seconds_empty_mesh = seconds_since(phase);
  poll_interrupt(options.interrupt, "mesh2d: after the empty mesh");

  // 2. Control space: the given one, or the classical sizes on a frozen copy of the empty mesh.
  phase = mesh_pipeline::Clock::now();
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
  // The options the later steps run with: the vertex bound lowered to the element limit.
  Mesh2dOptions bounded = options;
  const bool sized = options.control || !options.input_metrics.empty();
  if (sized) {
    // The work the size asks for, estimated before any point is made (element_estimate.hpp).
    std::uint32_t hint = ControlSpace2::kNoHint;
    const element_estimate::Checked checked = element_estimate::check_elements(
        "mesh2d", result.mesh, [&](const Vec2& p) { return control.metric_at(p, hint); }, options.max_elements);
    result.stats.estimated_triangles = checked.estimate.elements;
    if (checked.limit != element_estimate::kNoElementLimit)
      bounded.max_vertices = std::min<std::uint64_t>(options.max_vertices, checked.limit + input.points.size());
    // The boundary cut in the metric where it is longer than sqrt 2, then the empty mesh of the
    // new boundary (the control space stays the one built on the input).
    const ResampledBoundary boundary = resample_boundary(input, control, bounded);
    if (options.keep_boundary) {
      result.stats.long_boundary_segments = boundary.long_segments;
      if (boundary.long_segments > 0) {
        result.messages.push_back(std::to_string(boundary.long_segments) +
                                  " input segment(s) longer than sqrt 2 in the metric kept as given (keep the boundary): "
                                  "the triangles beside them are as long");
      }
    } else if (boundary.long_segments > 0) {
      result.stats.boundary_points = boundary.points.size() - input.points.size();
      result.mesh = build_empty_mesh(boundary.points, boundary.segments, boundary.markers);
    }
  }
  mesh_pipeline::assign_vertex_metrics(result.mesh, control);
  result.stats.seconds_control_space = seconds_since(phase);
  poll_interrupt(options.interrupt, "mesh2d: after the control space");

  mesh_pipeline::field_points(result, method, control, bounded);  // 3.+4.

  // 5. Optimization.
  mesh_pipeline::optimize_step<MetricField2>(result, options, control, [&](const MetricField2& field, const auto& optimization) {
    const std::optional<Metric2> constant = constant_metric(control);
    const MetricField2 constant_field = constant ? MetricField2([m = *constant](const Vec2&) { return m; }) : MetricField2{};
    const Optimize2dStats o = optimize2d(result.mesh, optimization, constant ? constant_field : field);
    result.stats.swaps = o.swaps + o.valence_swaps;
    return o;
  });

  mesh_pipeline::finish(result, start);
  return result;
}

}  // namespace dtlab
