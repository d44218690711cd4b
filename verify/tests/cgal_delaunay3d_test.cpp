// dtlab's 3D Delaunay variants against CGAL's Delaunay_triangulation_3 (verify/cgal_delaunay3d).
// In general position the Delaunay tetrahedralization is unique, so every variant must return
// exactly CGAL's tetrahedra. On degenerate input (lattices, exactly cospherical points, coplanar
// layers, collinear runs, duplicates) both break ties by a symbolic perturbation: CGAL's
// Delaunay_triangulation_3 perturbs the lifted points in lexicographic order (Devillers and
// Teillaud, "Perturbations for Delaunay and weighted Delaunay 3D triangulations", CGTA 2011),
// and dtlab's insphere_perturbed follows the same scheme (kernel/predicates/perturbation.hpp).
// Measured here: they give identical tetrahedra on every degenerate input tried, including the
// flat hull faces (where dtlab's ghost rule decides), so the test asserts equality there too.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "verify/cgal_delaunay3d.hpp"
#include "verify/checks3d.hpp"
#include "verify/generators/points3d.hpp"

namespace dtlab {
namespace {

// Every built variant's canonical tetrahedra must equal CGAL's; registered stubs ("not built
// yet") are left out. Returns the number of variants compared.
int expect_all_variants_equal(const std::vector<Vec3>& P, const std::vector<TetrahedronIds>& cgal,
                              const std::string& what) {
  int compared = 0;
  for (const Delaunay3dVariant& v : delaunay3d_variants()) {
    Delaunay3dResult r;
    try {
      r = delaunay3d(P, {.algorithm = std::string(v.name)});
    } catch (const InternalError& e) {
      if (std::string(e.what()).find("not built yet") != std::string::npos) continue;
      throw;
    }
    ++compared;
    const auto mine = canonical_tetrahedron_set(r.tetrahedralization);
    EXPECT_EQ(mine.size(), cgal.size()) << what << " " << v.name;
    EXPECT_TRUE(mine == cgal) << what << " " << v.name << ": tetrahedra differ from CGAL's";
    if (v.name == std::string_view("incremental")) {
      const CheckReport3 report = verify_delaunay3d(P, r.tetrahedralization, r.duplicates);
      EXPECT_TRUE(report.ok) << what << ": " << to_text(report);
    }
  }
  return compared;
}

TEST(CgalDelaunay3d, CellsArePositiveInDtlabsConvention) {
  const auto P = generate_points3d("uniform", 1000, 1);
  const auto cells = cgal_delaunay3d(P);
  ASSERT_FALSE(cells.empty());
  for (const TetrahedronIds& t : cells) {
    ASSERT_EQ(orient3d(P[t[0]], P[t[1]], P[t[2]], P[t[3]]), Sign::Positive);
  }
}

TEST(CgalDelaunay3d, GeneralPositionEveryVariantEqualsCgal) {
  for (const char* name : {"uniform", "normal", "clustered"}) {
    for (const std::size_t n : {1'000, 10'000, 100'000}) {
      const auto P = generate_points3d(name, n, 11);
      const std::string what = std::string(name) + " n=" + std::to_string(n);
      const auto cgal = canonical_tetrahedron_set(cgal_delaunay3d(P));
      ASSERT_FALSE(cgal.empty()) << what;
      EXPECT_GE(expect_all_variants_equal(P, cgal, what), 1) << what;
    }
  }
}

// Degenerate inputs: both perturbations are the lexicographic lifting one, so the sets agree.
TEST(CgalDelaunay3d, DegenerateInputsSameTetrahedra) {
  std::vector<std::pair<std::string, std::vector<Vec3>>> inputs;
  for (const std::size_t n : {1'000, 8'000, 27'000}) inputs.emplace_back("grid n=" + std::to_string(n), generate_points3d("grid", n, 5));
  for (const std::size_t n : {500, 5'000, 10'000}) {
    inputs.emplace_back("exact_sphere n=" + std::to_string(n), generate_points3d("exact_sphere", n, 5));
  }
  for (const char* name : {"coplanar", "collinear", "duplicates", "translated", "multiscale"}) {
    inputs.emplace_back(std::string(name) + " n=10000", generate_points3d(name, 10'000, 5));
  }
  // A lattice with power-of-two spacing far from the origin, and an exact sphere with its centre.
  std::vector<Vec3> shifted;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 15; ++j)
      for (int k = 0; k < 10; ++k) shifted.push_back({1e9 + i * 0x1.0p-10, -1e9 + j * 0x1.0p-10, 3e8 + k * 0x1.0p-10});
  inputs.emplace_back("20x15x10 lattice, spacing 2^-10, at (1e9, -1e9, 3e8)", shifted);
  auto centred = generate_points3d("exact_sphere", 2'000, 9);
  centred.push_back({0, 0, 0});
  inputs.emplace_back("exact_sphere n=2000 and its centre", centred);

  for (const auto& [what, P] : inputs) {
    const auto cgal = canonical_tetrahedron_set(cgal_delaunay3d(P));
    ASSERT_FALSE(cgal.empty()) << what;
    EXPECT_GE(expect_all_variants_equal(P, cgal, what), 1) << what;
  }
}

// The wrapper's own contract on small degenerate cases: coplanar or fewer than four distinct
// points give no tetrahedra; duplicates map to the smallest index.
TEST(CgalDelaunay3d, DegenerateInputs) {
  EXPECT_TRUE(cgal_delaunay3d(std::vector<Vec3>{}).empty());
  EXPECT_TRUE(cgal_delaunay3d(std::vector<Vec3>{{0, 0, 0}, {1, 1, 1}, {2, 0, 1}}).empty());
  EXPECT_TRUE(cgal_delaunay3d(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {5, 3, 0}}).empty());
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {0, 0, 1}};
  const auto t = canonical_tetrahedron_set(cgal_delaunay3d(P));
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0], (TetrahedronIds{0, 1, 3, 5}));
  const CgalDelaunay3dRun run = cgal_delaunay3d_timed(P);
  EXPECT_EQ(canonical_tetrahedron_set(run.tetrahedra), t);
  EXPECT_GE(run.total_seconds, run.insert_seconds);
}

}  // namespace
}  // namespace dtlab
