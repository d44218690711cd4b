// Method "cdt" on closed surfaces of real objects from Debian's CGAL data (libcgal-demo:
// /usr/share/doc/libcgal-dev/data.tar.gz), checked exactly (verify/checks_constrained3d.hpp):
// where recover and flips make a constrained Delaunay tetrahedralization (eight.off) it needs
// far fewer Steiner points than splitting every segment until it is Delaunay; where recover
// cascades (anchor.off: a flat face on the convex hull) the method hands over at once and says so.
// Method "recover" on couplingdown.off: in place, with fewer Steiner points than TetGen's 289.
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "algorithms/constrained3d/constrained3d.hpp"
#include "algorithms/constrained3d/plc/facet_triangulation.hpp"
#include "mesh/io/surface_input.hpp"
#include "verify/checks_constrained3d.hpp"

namespace dtlab {
namespace {

const char* const kCgalData = "/usr/share/doc/libcgal-dev/data.tar.gz";

// Extracts data/meshes/<names> into a temporary directory; empty if the archive is absent.
std::filesystem::path extract_cgal_meshes(const std::vector<std::string>& names) {
  if (!std::filesystem::exists(kCgalData)) return {};
  const auto dir = std::filesystem::temp_directory_path() / "dtlab_constrained3d_real_data_test";
  std::filesystem::create_directories(dir);
  std::string command = "tar -xzf " + std::string(kCgalData) + " -C " + dir.string();
  for (const std::string& n : names) command += " data/meshes/" + n;
  if (std::system(command.c_str()) != 0) return {};
  return dir / "data" / "meshes";
}

struct CheckedResult {
  Constrained3dResult result;
  bool checked = false;
};

CheckedResult run(const std::filesystem::path& file, const std::string& method) {
  const SurfaceInput s = read_surface(file.string());
  const FacetTriangulation facets = triangulate_facets(s.plc);
  const ConstrainedInput3 in{.points = s.plc.vertices, .triangles = facets.triangles, .triangle_refs = {},
                             .holes = {}, .regions = {}};
  CheckedResult r;
  r.result = constrained3d(in, {.method = method});
  const ConstrainedCheckReport3 report = check_constrained3d(in, r.result, {.method = method});
  EXPECT_TRUE(report.ok) << file << " " << method << ": " << to_text(report);
  r.checked = report.ok;
  return r;
}

bool says(const Constrained3dResult& r, const std::string& text) {
  for (const std::string& m : r.messages)
    if (m.find(text) != std::string::npos) return true;
  return false;
}

TEST(Constrained3dRealData, CdtByRecoverAndFlipsOrByDelaunaySegments) {
  const auto dir = extract_cgal_meshes({"eight.off", "anchor.off"});
  if (dir.empty()) GTEST_SKIP() << kCgalData << " (Debian package libcgal-demo) is absent";

  const CheckedResult eight = run(dir / "eight.off", "cdt");
  ASSERT_TRUE(eight.checked);
  EXPECT_TRUE(eight.result.constrained_delaunay);
  EXPECT_FALSE(says(eight.result, "instead")) << eight.result.messages.front();
  const CheckedResult eight_conforming = run(dir / "eight.off", "conforming");
  // Recover and flips: 22 Steiner points here (2026-11-23); every segment made Delaunay: 82.
  EXPECT_LT(2 * eight.result.steiner.size(), eight_conforming.result.steiner.size());

  const CheckedResult anchor = run(dir / "anchor.off", "cdt");
  ASSERT_TRUE(anchor.checked);
  EXPECT_TRUE(anchor.result.constrained_delaunay);
  EXPECT_TRUE(says(anchor.result, "segments split until they are Delaunay (Shewchuk 2002) instead"));
}

TEST(Constrained3dRealData, RecoverInPlaceOnCouplingdown) {
  const auto dir = extract_cgal_meshes({"couplingdown.off"});
  if (dir.empty()) GTEST_SKIP() << kCgalData << " (Debian package libcgal-demo) is absent";
  const CheckedResult r = run(dir / "couplingdown.off", "recover");
  ASSERT_TRUE(r.checked);
  // In place: 130 points (2026-11-24). Before, the search of each triangle's pieces in the final
  // mesh was misled by a sliver a hair off a triangle's plane, in-place recovery gave up and the
  // rounds took 257; `tetgen -p` takes 289.
  EXPECT_TRUE(r.result.messages.empty()) << r.result.messages.front();
  EXPECT_LT(r.result.steiner.size(), 289u);
}

}  // namespace
}  // namespace dtlab
