// The 3D mesher's pipeline (mesh3d.hpp, book §7.12): empty mesh, control space, field points,
// optimization, domain output.
#include "algorithms/mesh3d/mesh3d.hpp"

#include <memory>
#include <string>

#include "algorithms/common/mesh_pipeline.hpp"
#include "algorithms/mesh3d/local_remesh.hpp"
#include "algorithms/mesh3d/registry.hpp"
#include "algorithms/mesh3d/spatial_renumber.hpp"
#include "kernel/error.hpp"

namespace dtlab {

using mesh_pipeline::seconds_since;

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
  const FieldPointMethod3& method = (options.methods ? *options.methods : mesh3d_methods()).at(options.method);
  if (!(options.filter_distance > 0.0 && options.filter_distance < 1.0)) {
    throw InputError("mesh3d: filter_distance must lie in (0, 1)");
  }
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
  result.stats.seconds_control_space = seconds_since(phase);
  poll_interrupt(options.interrupt, "mesh3d: after the control space");

  // 3.+4. Field points and their insertion.
  phase = mesh_pipeline::Clock::now();
  method.run(result.mesh, control, options, result.stats);
  result.stats.seconds_field_points = seconds_since(phase);

  // 5. Optimization, on the mesh renumbered for locality (spatial_renumber.hpp).
  phase = mesh_pipeline::Clock::now();
  if (options.optimize) {
    renumber_spatially(result.mesh);
    std::uint32_t field_hint = 0;
    const MetricField3 field = mesh_pipeline::metric_field<MetricField3>(control, field_hint);
    const Optimize3dOptions optimization = mesh_pipeline::with_interrupt(options.optimization, options.interrupt);
    const Optimize3dStats o = optimize3d(result.mesh, optimization, field);
    result.stats.face_swaps = o.face_swaps;
    result.stats.shell_transformations = o.shell_transformations;
    result.stats.relocations = o.relocations;
    result.stats.collapses = o.collapses;
    result.stats.splits = o.splits;
    result.stats.optimization_rounds = o.rounds;
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
  }
  result.stats.seconds_optimization = seconds_since(phase);

  // The domain (exterior dropped), regions and boundary triangles with their references.
  mesh_pipeline::finish(result, start);
  return result;
}

}  // namespace dtlab
