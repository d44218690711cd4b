// `dtlab constrain` in 3D: read a closed triangulated surface (plus internal faces, holes and
// region points where the format has them), refuse bad input by name (plc_checks.hpp), build the
// constrained tetrahedralization with any registered method (algorithms/constrained3d), write
// Medit, check the result exactly (verify/checks_constrained3d.hpp) and report statistics.
#include "apps/constrain3d.hpp"

#include <iostream>
#include <sstream>

#include "algorithms/constrained3d/constrained3d.hpp"
#include "apps/cli_util.hpp"
#include "apps/input_files.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit3.hpp"
#include "mesh/io/surface_input.hpp"
#include "verify/checks_constrained3d.hpp"

namespace dtlab::cli {

bool is_surface_input(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == "off" || ext == "stl" || ext == "smesh") return true;
  if (ext == "poly" || ext == "mesh") return input_dimension(path) == 3;
  return false;
}

int list_constrained3d_methods() {
  for (const auto& m : constrained3d_method_list()) std::cout << m.name << "\t" << m.description << "\n";
  return 0;
}

int run_constrain3d(const Constrain3dCliArgs& args) {
  const SurfaceInput in = read_surface(args.input);
  std::vector<RegionSeed3> seeds;
  for (const PlcRegion3& r : in.regions) {
    const int attribute = static_cast<int>(r.attribute);
    if (static_cast<double>(attribute) != r.attribute)
      std::cerr << "dtlab: region attribute " << r.attribute << " is not an integer; the reference is " << attribute
                << "\n";
    seeds.push_back({r.point, attribute});
  }
  ConstrainedInput3 input{.points = in.surface.vertices,
                          .triangles = in.surface.triangles,
                          .triangle_refs = in.surface.triangle_refs,
                          .holes = in.holes,
                          .regions = seeds};
  Constrained3dOptions options;
  options.method = args.method;
  options.keep_exterior = args.keep_exterior;
  options.remove_cavities = args.remove_cavities;
  options.steiner_limit_factor = args.steiner_limit;
  Constrained3dResult result;
  try {
    result = constrained3d(input, options);
  } catch (const InputError& e) {
    throw InputError(args.input + ": " + e.what(), e.items());
  }
  const double peak_mb = peak_rss_mb();
  for (const std::string& m : result.messages) std::cerr << "dtlab: " << m << "\n";

  if (!args.output.empty()) {
    MeshData3 mesh;
    mesh.vertices = result.vertices;
    mesh.triangles = result.triangles;
    mesh.triangle_refs = result.triangle_refs;
    mesh.tetrahedra = result.tetrahedra;
    mesh.tetrahedron_refs = result.tetrahedron_regions;
    write_mesh3(args.output, mesh);
  }
  bool ok = true;
  if (args.verify) {
    const ConstrainedCheckReport3 c = check_constrained3d(
        input, result, {.method = args.method, .keep_exterior = args.keep_exterior, .first_number = 1});
    std::cout << (c.ok ? "ok" : "FAILED") << ": " << result.tetrahedra.size() << " tetrahedra, "
              << result.triangles.size() << " boundary triangles, " << result.steiner_points.total()
              << " Steiner points; " << c.input_triangles << " input triangles covered exactly, " << c.input_edges
              << " input edges as chains, " << c.regions << " region volumes (" << c.exact_volumes << " exact)\n";
    for (const std::string& p : c.problems) std::cout << "  " << p << "\n";
    if (c.problems.size() < c.problem_count)
      std::cout << "  ... and " << c.problem_count - c.problems.size() << " more\n";
    ok = c.ok;
  }
  if (args.stats) {
    const auto& s = result.seconds;
    std::ostringstream json;
    json << "{\"input\":" << json_string(args.input) << ",\"dim\":3,\"method\":" << json_string(args.method)
         << ",\"points\":" << result.input_point_count << ",\"input_triangles\":" << in.surface.triangles.size()
         << ",\"elements\":" << result.tetrahedra.size() << ",\"regions\":" << result.region_count
         << ",\"steiner_points\":{\"on_edges\":" << result.steiner_points.on_edges
         << ",\"on_faces\":" << result.steiner_points.on_faces << ",\"interior\":" << result.steiner_points.interior
         << "},\"rounding_checks_failed\":" << result.rounding_checks_failed
         << ",\"constrained_delaunay\":" << (result.constrained_delaunay ? "true" : "false") << ",\"rounds\":" << result.rounds
         << ",\"seconds\":{\"checks\":"
         << json_number(s.checks) << ",\"delaunay\":" << json_number(s.delaunay)
         << ",\"edge_recovery\":" << json_number(s.edge_recovery) << ",\"face_recovery\":" << json_number(s.face_recovery)
         << ",\"regions\":" << json_number(s.regions) << ",\"total\":" << json_number(s.total)
         << "},\"peak_rss_mb\":" << json_number(peak_mb) << ",\"predicates\":" << result.predicate_stats.to_json() << "}";
    std::cout << json.str() << "\n";
  }
  return ok ? 0 : 3;
}

}  // namespace dtlab::cli
