// `dtlab mesh PATCH.json -o OUT.mesh --surface-only`: a parametric patch (algorithms/surface/
// patch_description.hpp) meshed in its parameter space under the metric of a 3D size (--size),
// of a gap to the surface (--hausdorff E, or the book's --relative-gap eps, with --geometric
// isotropic | anisotropic), or both intersected (book §6.3), then mapped to the surface
// (algorithms/parametric/mesh_patch.hpp). Output: Medit .mesh, Triangles (ref: chart) and Edges.
#include <iostream>
#include <sstream>

#include "algorithms/parametric/mesh_patch.hpp"
#include "algorithms/parametric/surface_mesh_quality.hpp"
#include "algorithms/surface/patch_description.hpp"
#include "apps/cli_util.hpp"
#include "apps/mesh_args.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit3.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "mesh/io/json_value.hpp"

namespace dtlab::cli {

bool is_patch_description(const std::string& path) {
  return path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
}

int run_mesh_patch(const MeshCliArgs& args) {
  if (!is_patch_description(args.input))
    throw InputError("--surface-only: for a patch description (PATCH.json); " + args.input + " is not one");
  if (!args.surface_only)
    throw InputError(args.input + ": a patch is meshed as a surface: give --surface-only (the volume inside is not "
                     "meshed from a patch yet)");
  for (const auto& [given, name] : {std::pair{!args.size_map.empty(), "--size-map"}, std::pair{!args.metric.empty(), "--metric"},
                                    std::pair{!args.background.empty(), "--background"},
                                    std::pair{args.keep_boundary, "--keep-boundary"},
                                    std::pair{!args.output_metric.empty(), "--output-metric"},
                                    std::pair{args.verify, "--verify"}}) {
    if (given) throw InputError(std::string(name) + ": not an option for a patch (" + args.input + ")");
  }
  if (args.hausdorff != 0.0 && args.relative_gap != 0.0) throw InputError("give one of --hausdorff and --relative-gap");
  const bool geometric = args.hausdorff != 0.0 || args.relative_gap != 0.0;
  if (!geometric && !args.geometric.empty()) throw InputError("--geometric needs --hausdorff or --relative-gap");
  if (!args.size_given && !geometric) throw InputError(args.input + ": give --size H, --hausdorff E or --relative-gap EPS");

  PatchSurface3 surface;
  try {
    surface = patch_from_description(read_json(args.input));
  } catch (const InputError& e) {
    throw InputError(args.input + ": " + e.what(), e.items());
  }
  SurfaceMeshOptions options;
  options.optimize = !args.no_optimize;
  options.method = args.method;
  options.max_elements = args.max_elements;
  options.background_cells = args.background_cells;
  options.interpolation = args.interpolation == "log-euclidean" ? MetricInterpolation::LogEuclidean : MetricInterpolation::Sizes;
  SurfaceMetricSpec& spec = options.metric;
  if (args.size_given) spec.size = parse_size(args.size);
  if (geometric) {
    spec.geometric = args.geometric == "anisotropic" ? GeometricMetric::Anisotropic : GeometricMetric::Isotropic;
    spec.hausdorff = args.hausdorff;
    if (args.relative_gap != 0.0) spec.relative_gap = args.relative_gap;
    spec.h_min = args.hmin;
    spec.h_max = args.hmax != 0.0 ? args.hmax : args.size_given ? spec.size : surface.extent() / 10.0;
  } else if (args.hmin != 0.0 || args.hmax != 0.0) {
    throw InputError("--hmin / --hmax bound the geometric sizes: give --hausdorff or --relative-gap");
  }

  StagedOutputs outputs({args.output});
  SurfaceMeshResult result;
  try {
    result = mesh_patch_surface(surface, options);
  } catch (const InputError& e) {
    throw InputError(args.input + ": " + e.what(), e.items());
  }
  outputs.write(args.output, [&](const std::string& path) { write_medit3(path, result.surface); });
  outputs.commit();
  if (args.stats) {
    const QualityReport quality = parameter_quality(result);
    std::cout << quality_table(quality);
    std::ostringstream json;
    json << "{\"input\":" << json_string(args.input) << ",\"patch\":" << json_string(surface.name())
         << ",\"charts\":" << surface.charts().size() << ",\"vertices\":" << result.surface.vertices.size()
         << ",\"triangles\":" << result.surface.triangles.size() << ",\"boundary_edges\":" << result.surface.edges.size()
         << ",\"seconds\":" << json_number(result.seconds) << ",\"peak_rss_mb\":" << json_number(peak_rss_mb())
         << ",\"quality\":" << quality_json(quality) << "}";
    std::cout << json.str() << "\n";
  }
  return 0;
}

}  // namespace dtlab::cli
