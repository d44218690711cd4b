// libFuzzer target: bytes -> a size and an OFF surface file -> the 3D mesher (algorithms/mesh3d).
// The result must pass Mesh3::check and check_mesh3d (validity, conformity, the boundary as
// recovered, region volumes). ParseError (a malformed file) and InputError (an open,
// self-intersecting or degenerate surface, polygons that are not planar, a bound reached) are
// accepted answers; any other exception or a failed check prints the input and traps.
//
// Input layout: byte 0 the size (0: the classical case; otherwise h = (0.2 + byte / 300) times
// the bounding box's diagonal, so that a run stays under about a thousand tetrahedra), byte 1 the
// flags (bit 0: no optimization, bit 1: remove cavities), then the OFF text. Bounded before the
// mesher: at most 64 vertices and 96 faces, coordinates within [-1e3, 1e3], the bounding box's
// diagonal at least 1e-3 (smaller surfaces are the readers' fuzzer's business).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/constrained3d/plc/facet_triangulation.hpp"
#include "algorithms/mesh3d/mesh3d.hpp"
#include "kernel/error.hpp"
#include "mesh/io/off_format.hpp"
#include "verify/checks_mesh3d.hpp"

namespace {

[[noreturn]] void fail(const std::string& text, const std::string& what) {
  std::fprintf(stderr, "mesh3d_fuzz: %s\ninput:\n%s\n", what.c_str(), text.c_str());
  std::fflush(stderr);
  __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2 || size > 4096) return 0;
  const std::uint8_t size_byte = data[0], flags = data[1];
  const std::string text(reinterpret_cast<const char*>(data + 2), size - 2);
  dtlab::Plc3 plc;
  try {
    std::istringstream in(text);
    plc = dtlab::read_off_surface(in, "fuzz.off");
  } catch (const dtlab::Error&) {
    return 0;
  }
  if (plc.vertices.size() < 4 || plc.vertices.size() > 64 || plc.facets.size() > 96) return 0;
  dtlab::Vec3 lo = plc.vertices.front(), hi = lo;
  for (const dtlab::Vec3& p : plc.vertices) {
    if (!(std::abs(p.x) <= 1e3 && std::abs(p.y) <= 1e3 && std::abs(p.z) <= 1e3)) return 0;
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double diagonal = dtlab::norm(hi - lo);
  if (!(diagonal >= 1e-3)) return 0;

  dtlab::FacetTriangulation facets;
  try {
    facets = dtlab::triangulate_facets(plc);
  } catch (const dtlab::Error&) {
    return 0;
  }
  const dtlab::Mesh3dInput input{.points = plc.vertices,
                                 .triangles = facets.triangles,
                                 .triangle_refs = facets.triangle_refs,
                                 .holes = {},
                                 .regions = {}};
  std::optional<dtlab::ControlSpace3> control;
  if (size_byte != 0) {
    const double h = (0.2 + size_byte / 300.0) * diagonal;
    const dtlab::Vec3 margin{diagonal, diagonal, diagonal};
    control.emplace(dtlab::ControlSpace3::uniform(dtlab::Metric3::isotropic(h), lo - margin, hi + margin));
  }
  dtlab::Mesh3dOptions options;
  options.control = control ? &*control : nullptr;
  options.optimize = (flags & 1) == 0;
  options.remove_cavities = (flags & 2) != 0;
  options.max_vertices = 5'000;
  dtlab::Mesh3dResult result;
  try {
    result = dtlab::mesh3d(input, options);
  } catch (const dtlab::InputError&) {
    return 0;
  } catch (const std::exception& e) {
    fail(text, std::string("mesh3d threw: ") + e.what());
  }
  try {
    result.mesh.check();
  } catch (const std::exception& e) {
    fail(text, std::string("Mesh3::check: ") + e.what());
  }
  const dtlab::MeshCheckReport3 report =
      dtlab::check_mesh3d(input, dtlab::recover_domain(input, options.remove_cavities), result.output,
                          result.output_metrics, {.remove_cavities = options.remove_cavities});
  if (!report.ok) fail(text, "check_mesh3d: " + dtlab::to_text(report));
  return 0;
}
