// Real scanned data: the point clouds of CGAL's demo data (Debian's libcgal-demo package ships
// them in /usr/share/doc/libcgal-dev/data.tar.gz), projected to their x y columns. Scans
// projected to a plane are full of coincident and nearly collinear points, rows of equal
// coordinates and clusters, in coordinates written with few decimals. Every registered variant
// must triangulate each file so that verify_delaunay2d holds, and all must give the same
// triangles. Skipped, with a message, where the package is not installed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/delaunay2d/registry.hpp"
#include "kernel/coordinate_range.hpp"
#include "verify/checks2d.hpp"

namespace dtlab {
namespace {

namespace fs = std::filesystem;

constexpr const char* kArchive = "/usr/share/doc/libcgal-dev/data.tar.gz";

// The .xyz files of the archive, extracted once per process under the build directory.
// Returns them sorted by name, or an empty list with `error` set.
std::vector<fs::path> extracted_xyz_files(std::string& error) {
  const fs::path dir = fs::path(DTLAB_BINARY_DIR) / "real-data2d";
  fs::create_directories(dir);
  const std::string command = "tar -xzf '" + std::string(kArchive) + "' -C '" + dir.string() +
                              "' --wildcards 'data/points_3/*.xyz'";
  if (const int rc = std::system(command.c_str()); rc != 0) {
    error = "'" + command + "' failed with status " + std::to_string(rc);
    return {};
  }
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(dir / "data" / "points_3")) {
    if (e.path().extension() == ".xyz") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The first two numbers of every line that starts with two numbers.
std::vector<Vec2> read_xy(const fs::path& file) {
  std::ifstream in(file);
  std::vector<Vec2> points;
  std::string line;
  while (std::getline(in, line)) {
    const char* s = line.c_str();
    char* end = nullptr;
    const double x = std::strtod(s, &end);
    if (end == s) continue;
    s = end;
    const double y = std::strtod(s, &end);
    if (end == s) continue;
    points.push_back({x, y});
  }
  return points;
}

TEST(RealData2d, CgalScannedPointCloudsProjectedToXy) {
  if (!fs::exists(kArchive)) {
    GTEST_SKIP() << kArchive << " not found: install Debian's libcgal-demo package (scripts/install-deps.sh does)";
  }
  std::string error;
  const std::vector<fs::path> files = extracted_xyz_files(error);
  ASSERT_TRUE(error.empty()) << error;
  // The archive holds radar.xyz, kitten.xyz, poste_france.xyz and more: an empty list means
  // the extraction went wrong, not that there is nothing to test.
  ASSERT_GE(files.size(), 3u);

  std::size_t triangulated = 0;
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    const std::vector<Vec2> P = read_xy(file);
    ASSERT_FALSE(P.empty()) << "no 'x y ...' line in " << file;
    ASSERT_TRUE(std::all_of(P.begin(), P.end(),
                            [](const Vec2& p) { return coordinate_in_range(p.x) && coordinate_in_range(p.y); }));

    std::vector<TriangleIds> reference;
    std::string reference_name;
    for (const Delaunay2dVariant& v : delaunay2d_variants()) {
      const std::string name(v.name);
      const Delaunay2dResult r = delaunay2d(P, {.algorithm = name});
      const std::vector<TriangleIds> triangles = r.triangulation.finite_triangles();
      const CheckReport2 report = verify_delaunay2d(P, triangles, r.duplicates);
      EXPECT_TRUE(report.ok) << name << " on " << P.size() << " points: " << to_text(report);
      const std::vector<TriangleIds> canonical = canonical_triangle_set(triangles);
      if (reference_name.empty()) {
        reference = canonical;
        reference_name = name;
        if (!reference.empty()) ++triangulated;
      } else {
        EXPECT_TRUE(canonical == reference)
            << name << " and " << reference_name << " differ: " << canonical.size() << " vs " << reference.size()
            << " triangles";
      }
    }
  }
  EXPECT_GT(triangulated, 0u);
}

}  // namespace
}  // namespace dtlab
