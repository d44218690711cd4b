// The 3D mesher's pipeline (mesh3d.hpp, book §7.12): empty mesh, control space, field points,
// optimization, domain output.
#include "algorithms/mesh3d/mesh3d.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "algorithms/common/element_estimate.hpp"
#include "algorithms/common/mesh_pipeline.hpp"
#include "algorithms/mesh3d/local_remesh.hpp"
#include "algorithms/mesh3d/registry.hpp"
#include "algorithms/mesh3d/spatial_renumber.hpp"
#include "algorithms/optimize3d/boundary_split.hpp"
#include "kernel/error.hpp"

namespace dtlab {

using mesh_pipeline::seconds_since;

namespace {

// The Q_K above which the empty mesh's tetrahedra are swapped before and after the surface cut:
// the flat ones between boundary facets coplanar up to rounding (Q_K 1e4 and more), not the
// merely poor ones, which the field points replace (all of them: +0.5 s of 1.7 on a 32k-tetrahedron
// empty mesh).
constexpr double kFlatQuality = 1e3;

}  // namespace

Constrained3dResult recover_domain(const Mesh3dInput& input, bool remove_cavities, std::uint32_t steiner_limit_factor) {
  Constrained3dOptions recovery;
  recovery.method = "recover";
  recovery.keep_exterior = false;  // the exterior is told apart by what is not kept
  recovery.remove_cavities = remove_cavities;
  recovery.steiner_limit_factor = steiner_limit_factor;
  return constrained3d(input, recovery);
}

Mesh3dResult mesh3d(const Mesh3dInput& input, const Mesh3dOptions& options) {
  const auto start = mesh_pipeline::Clock::now();
  if (options.method == "front") {
    throw InputError("mesh3d: the advancing-front method (book §7.8) is not implemented in 3D yet (use edge)");
  }
  const FieldPointMethod3& method = mesh_pipeline::method_of("mesh3d", options, mesh3d_methods());
  Mesh3dResult result;
  result.stats.input_points = input.points.size();
  result.stats.input_triangles = input.triangles.size();

  // 1. Empty mesh: boundary recovery with the fewest Steiner points; the whole tetrahedralization
  //    comes back in `tetrahedralization`, the domain's tetrahedra with their regions.
  auto phase = mesh_pipeline::Clock::now();
  {
    const Constrained3dResult r = recover_domain(input, options.remove_cavities, options.steiner_limit_factor);
    result.messages = r.messages;
    if (r.tetrahedra.empty()) {
      throw InputError("mesh3d: the domain has no tetrahedron: the surface encloses no region, or the holes remove "
                       "every region");
    }
    result.stats.steiner_points = r.steiner_points.total();
    result.stats.empty_mesh_tetrahedra = r.tetrahedra.size();
    result.mesh = empty_mesh(r);
  }
  result.stats.seconds_empty_mesh = seconds_since(phase);
  poll_interrupt(options.interrupt, "mesh3d: after the empty mesh");

  // 2. Control space: the given one, or the classical sizes on the empty mesh (a frozen copy).
  phase = mesh_pipeline::Clock::now();
  std::unique_ptr<ControlSpace3> classical;
  if (!options.control) classical = std::make_unique<ControlSpace3>(classical_control_space(result.mesh));
  const ControlSpace3& control = options.control ? *options.control : *classical;
  mesh_pipeline::assign_vertex_metrics(result.mesh, control);
  // The options the later steps run with: the vertex bound lowered to the element limit.
  Mesh3dOptions bounded = options;
  if (options.control) {
    // The work the size asks for, estimated before any point is made (element_estimate.hpp).
    std::uint32_t hint = ControlSpace3::kNoHint;
    const element_estimate::Checked checked = element_estimate::check_elements(
        "mesh3d", result.mesh, [&](const Vec3& p) { return control.metric_at(p, hint); }, options.max_elements);
    result.stats.estimated_tetrahedra = checked.estimate.elements;
    if (checked.limit != kNoElementLimit)
      bounded.max_vertices = std::min<std::uint64_t>(options.max_vertices, checked.limit / 3 + input.points.size());
    // The surface cut in the size: its constrained edges longer than sqrt 2, split longest first
    // whatever the quality of the empty mesh's tetrahedra around them (those are meshed again).
    if (!options.keep_boundary) {
      // The empty mesh's flat tetrahedra in the domain (between boundary facets coplanar up to
      // rounding: a rotated box's faces) swapped away first: split, each would become many, all
      // of them boundary-bound where the optimization cannot reach them.
      swap_pass3(result.mesh, kImprovementMargin, {}, kFlatQuality);
      std::uint32_t field_hint = 0;
      const MetricField3 field = mesh_pipeline::metric_field<MetricField3>(control, field_hint);
      Split3Options split;
      split.long_length = options.split_length;
      split.short_length = 0.0;
      split.quality_limit = HUGE_VAL;
      split.max_vertices = bounded.max_vertices;
      result.stats.boundary_points = boundary_split_pass3(result.mesh, field, split);
      swap_pass3(result.mesh, kImprovementMargin, {}, kFlatQuality);  // and those the cut made
      if (result.mesh.live_vertex_count() >= bounded.max_vertices) {
        throw InputError("mesh3d: the surface cut in the size reached the vertex bound of " +
                         std::to_string(bounded.max_vertices) + " (max_vertices, max_elements)");
      }
    }
    result.stats.long_boundary_edges = long_constrained_edges(result.mesh, options.split_length);
    if (result.stats.long_boundary_edges > 0) {
      result.messages.push_back(std::to_string(result.stats.long_boundary_edges) + " surface edge(s) longer than sqrt 2 " +
                                (options.keep_boundary ? "in the metric kept as given (keep the boundary)"
                                                       : "in the metric could not be split (beside a flat tetrahedron, "
                                                         "or the longest edge of a facet that could not)") +
                                ": the tetrahedra beside them are as long");
    }
  }
  result.stats.seconds_control_space = seconds_since(phase);
  poll_interrupt(options.interrupt, "mesh3d: after the control space");

  mesh_pipeline::field_points(result, method, control, bounded);  // 3.+4.

  // 5. Optimization, on the mesh renumbered for locality (spatial_renumber.hpp).
  mesh_pipeline::optimize_step<MetricField3>(result, options, control, [&](const MetricField3& field,
                                                                          const Optimize3dOptions& optimization) {
    renumber_spatially(result.mesh);
    const Optimize3dStats o = optimize3d(result.mesh, optimization, field);
    result.stats.face_swaps = o.face_swaps;
    result.stats.shell_transformations = o.shell_transformations;
    result.stats.optimization_stopped_by = o.stopped_by;
    // What the optimization leaves below the goal's smallest dihedral angle, meshed again
    // (local_remesh.hpp, whose regions are meshed with local_remesh off: no deeper nesting).
    if (options.local_remesh && optimization.goal_min_dihedral_deg > 0.0) {
      LocalRemesh3Options remesh;
      remesh.below_deg = optimization.goal_min_dihedral_deg;
      if (optimization.goal_max_dihedral_deg > 0.0) remesh.max_dihedral_deg = optimization.goal_max_dihedral_deg;
      if (optimization.goal_worst_quality > 0.0) remesh.quality_limit = optimization.goal_worst_quality;
      const LocalRemesh3Stats r = remesh_small_angles(result.mesh, field, remesh);
      result.stats.remeshed_regions = r.remeshed;
      result.stats.remesh_work_bound_reached = r.work_bound_reached;
    }
    return o;
  });

  // The domain (exterior dropped), regions and boundary triangles with their references.
  mesh_pipeline::finish(result, start);
  return result;
}

}  // namespace dtlab

