// `dtlab constrain` in 3D: read a closed triangulated surface (plus internal faces, holes and
// region points where the format has them), refuse bad input by name (plc_checks.hpp), build the
// constrained tetrahedralization with any registered method (algorithms/constrained3d), write
// Medit, check the result exactly and report statistics.
#include "apps/constrain3d.hpp"

#include <algorithm>
#include <iostream>
#include <set>
#include <sstream>

#include "algorithms/constrained3d/constrained3d.hpp"
#include "apps/cli_util.hpp"
#include "apps/input_files.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/io/medit3.hpp"
#include "mesh/io/surface_input.hpp"
#include "verify/checks3d.hpp"

namespace dtlab::cli {

namespace {

// The exact checks of the result: tetrahedra positive in doubles, every Steiner point within
// its rounding bound, every output triangle a facet of the tetrahedralization, and the whole
// tetrahedralization Delaunay (checks3d) for the method that promises it.
struct Check {
  bool ok = true;
  std::vector<std::string> problems;
  void fail(std::string p) {
    ok = false;
    if (problems.size() < 20) problems.push_back(std::move(p));
  }
};

Check check_result(const Constrained3dResult& r, const std::string& method) {
  Check c;
  const auto& P = r.vertices;
  for (std::size_t t = 0; t < r.tetrahedra.size(); ++t) {
    const auto& v = r.tetrahedra[t];
    if (orient3d(P[v[0]], P[v[1]], P[v[2]], P[v[3]]) != Sign::Positive)
      c.fail("tetrahedron " + std::to_string(t + 1) + " is not positive in doubles");
  }
  const std::span<const Vec3> input(P.data(), r.input_point_count);
  for (std::size_t i = 0; i < r.steiner.size(); ++i)
    if (!steiner_point_within_rounding_bound(input, r.steiner[i], P[r.input_point_count + i]))
      c.fail("Steiner point " + std::to_string(r.input_point_count + i + 1) + " is not within its rounding bound");
  std::set<std::array<std::uint32_t, 3>> facets;
  const Tetrahedralization3& T = r.tetrahedralization;
  for (std::uint32_t t = 0; t < T.tetrahedron_count(); ++t)
    for (std::uint32_t i = 0; i < 4; ++i) {
      auto f = T.facet_vertices(Tetrahedralization3::facet(t, i));
      std::sort(f.begin(), f.end());
      facets.insert(f);
    }
  for (std::size_t k = 0; k < r.triangles.size(); ++k) {
    auto f = r.triangles[k];
    std::sort(f.begin(), f.end());
    if (!facets.count(f)) c.fail("triangle " + std::to_string(k + 1) + " (a piece of input face " +
                                 std::to_string(r.triangle_face[k] + 1) + ") is not a facet of the mesh");
  }
  if (method == "conforming") {
    const CheckReport3 d = verify_delaunay3d(T.points(), T);
    if (!d.ok) c.fail("the tetrahedralization is not Delaunay: " + to_text(d));
  }
  return c;
}

}  // namespace

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
    const Check c = check_result(result, args.method);
    std::cout << (c.ok ? "ok" : "FAILED") << ": " << result.tetrahedra.size() << " tetrahedra, "
              << result.triangles.size() << " boundary triangles, " << result.steiner_points.total()
              << " Steiner points\n";
    for (const std::string& p : c.problems) std::cout << "  " << p << "\n";
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
         << "},\"rounding_checks_failed\":" << result.rounding_checks_failed << ",\"seconds\":{\"checks\":"
         << json_number(s.checks) << ",\"delaunay\":" << json_number(s.delaunay)
         << ",\"edge_recovery\":" << json_number(s.edge_recovery) << ",\"face_recovery\":" << json_number(s.face_recovery)
         << ",\"regions\":" << json_number(s.regions) << ",\"total\":" << json_number(s.total)
         << "},\"peak_rss_mb\":" << json_number(peak_mb) << ",\"predicates\":" << result.predicate_stats.to_json() << "}";
    std::cout << json.str() << "\n";
  }
  return ok ? 0 : 3;
}

}  // namespace dtlab::cli
