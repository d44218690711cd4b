// 3D local mesh adaptation, book §9.3.1 (adapt3d.hpp): rounds of the optimize3d operators driven
// by the background control space, stopped when the metric edge lengths converge.
#include "algorithms/adapt/adapt3d.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "algorithms/common/element_estimate.hpp"
#include "algorithms/optimize3d/boundary_split.hpp"
#include "algorithms/optimize3d/relocate_boundary.hpp"
#include "algorithms/surface/boundary_support3.hpp"
#include "kernel/error.hpp"

namespace dtlab {

Adapt3dStats adapt3d(Mesh3& mesh, const ControlSpace3& metric, const Adapt3dOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  Adapt3dStats stats;
  // One walk hint shared by the calls: successive queries are near each other (same result
  // whatever the hint: the walk ends in the tetrahedron holding the point).
  auto hint = std::make_shared<std::uint32_t>(ControlSpace3::kNoHint);
  const MetricField3 field = [&metric, hint](const Vec3& p) { return metric.metric_at(p, *hint); };
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (!mesh.is_dead_vertex(v)) mesh.set_metric(v, field(mesh.point(v)));
  stats.before = domain_quality(mesh);
  if (stats.before.elements == 0) throw InputError("adapt3d: the mesh has no tetrahedron in its domain");

  const element_estimate::Checked checked = element_estimate::check_elements("adapt3d", mesh, field, options.max_elements);
  Optimize3dOptions round;
  round.max_rounds = 1;
  round.relocation_sweeps = options.relocation_sweeps;
  round.split.max_vertices = options.max_vertices;
  if (checked.limit != element_estimate::kNoElementLimit)
    round.split.max_vertices = std::min<std::uint64_t>(options.max_vertices, checked.limit / 3 + mesh.live_vertex_count());
  round.max_elements = element_estimate::kNoElementLimit;  // estimated above
  // The support of the boundary as given, before any split: new boundary vertices go onto it.
  std::optional<BoundarySupport3> support;
  if (options.boundary && options.surface_support)
    support.emplace(boundary_support3(mesh, SurfaceSupportOptions{.ridge_angle_degrees = options.ridge_angle_degrees,
                                                                  .non_manifold_ridges = true}));
  double share = stats.before.unit_edge_share;
  stats.stopped_by = "max_rounds";
  for (std::uint32_t r = 0; r < options.max_rounds; ++r) {
    // The boundary first (§9.3.1: the surface mesh conforms to the metric, then the volume).
    const std::uint64_t boundary_splits =
        options.boundary ? boundary_split_pass3(mesh, field, round.split, support ? &support->support : nullptr) : 0;
    stats.boundary_splits += boundary_splits;
    const Optimize3dStats s = optimize3d(mesh, round, field);
    ++stats.rounds;
    stats.collapses += s.collapses;
    stats.splits += s.splits;
    stats.face_swaps += s.face_swaps;
    stats.shell_transformations += s.shell_transformations;
    stats.relocations += s.relocations;
    // The boundary's vertices moved on the support after the volume's (their balls' worst Q_K).
    if (support && options.boundary_relocation) {
      const BoundaryRelocate3Options relocate{.ridge_angle_degrees = options.ridge_angle_degrees};
      for (std::uint32_t k = 0; k < options.relocation_sweeps; ++k)
        stats.boundary_relocations += boundary_relocate_sweep3(mesh, field, support->support, relocate);
    }
    if (s.stopped_by == "vertex_limit" || s.stopped_by == "swap_limit") {
      stats.stopped_by = s.stopped_by;
      break;
    }
    const QualityReport now = domain_quality(mesh);
    const bool sizes_settled = (s.collapses + s.splits + boundary_splits) * 1000 <= s.vertices_after;
    const bool converged = std::fabs(now.unit_edge_share - share) < options.share_tolerance && sizes_settled;
    share = now.unit_edge_share;
    if (converged) {
      stats.stopped_by = "converged";
      break;
    }
  }
  stats.after = domain_quality(mesh);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.tetrahedra_per_second = stats.seconds > 0.0 ? static_cast<double>(stats.after.elements) / stats.seconds : 0.0;
  return stats;
}

}  // namespace dtlab
