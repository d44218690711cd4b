// parameter_quality (surface_mesh_quality.hpp): the charts' meshes side by side, one report.
#include "algorithms/parametric/surface_mesh_quality.hpp"

namespace dtlab {

QualityReport parameter_quality(const SurfaceMeshResult& result) {
  std::vector<Vec2> points;
  std::vector<Metric2> metrics;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (const ChartMesh& c : result.charts) {
    const auto offset = static_cast<std::uint32_t>(points.size());
    points.insert(points.end(), c.parameters.vertices.begin(), c.parameters.vertices.end());
    metrics.insert(metrics.end(), c.metrics.begin(), c.metrics.end());
    for (const auto& t : c.parameters.triangles) triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  return measure_quality(points, triangles, metrics);
}

}  // namespace dtlab
