// 3D local mesh adaptation (algorithms/adapt/adapt3d.hpp, book §9.3.1) and the 3D path of
// `dtlab adapt` (apps/adapt3.hpp): validity, references and volume kept, convergence toward a
// unit mesh in a cube for constant isotropic and anisotropic metrics, bad input
// named.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

#include "algorithms/adapt/adapt3d.hpp"
#include "algorithms/mesh3d/mesh3d.hpp"
#include "apps/adapt3.hpp"
#include "mesh/io/any_format.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/io/medit_sol.hpp"
#include "mesh/mesh3_from_data.hpp"
#include "verify/generators/surfaces3.hpp"

namespace dtlab {
namespace {

double comp(const Vec3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

// The unit cube as n^3 cells of six tetrahedra each (Kuhn's split along the main diagonal),
// boundary triangles with the reference of their face (1..6).
MeshData3 cube_mesh(int n) {
  MeshData3 d;
  auto id = [n](int i, int j, int k) { return static_cast<std::uint32_t>((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        d.vertices.push_back({double(i) / n, double(j) / n, double(k) / n});
        d.vertex_refs.push_back(0);
      }
  // Kuhn: the 6 paths from corner 000 to 111 through the permutations of the axes.
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& p : perms) {
          int c[3] = {i, j, k};
          std::array<std::uint32_t, 4> t{};
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[p[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          const Sign o = orient3d(d.vertices[t[0]], d.vertices[t[1]], d.vertices[t[2]], d.vertices[t[3]]);
          if (o == Sign::Negative) std::swap(t[2], t[3]);
          d.tetrahedra.push_back(t);
          d.tetrahedron_refs.push_back(1);
        }
  // Boundary: each tetrahedron facet lying in a cube face.
  for (const auto& t : d.tetrahedra)
    for (int f = 0; f < 4; ++f) {
      std::array<std::uint32_t, 3> tri{};
      int m = 0;
      for (int v = 0; v < 4; ++v)
        if (v != f) tri[m++] = t[v];
      for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
          bool on = true;
          for (const auto v : tri) on = on && comp(d.vertices[v], axis) == double(side);
          if (on) {
            d.triangles.push_back(tri);
            d.triangle_refs.push_back(1 + axis * 2 + side);
          }
        }
    }
  return d;
}

long double volume(const Mesh3& mesh) {
  const MeshData3 d = mesh.domain();
  long double v = 0;
  for (const auto& t : d.tetrahedra) {
    const Vec3 &a = d.vertices[t[0]], &b = d.vertices[t[1]], &c = d.vertices[t[2]], &e = d.vertices[t[3]];
    const long double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
    const long double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
    const long double wx = e.x - a.x, wy = e.y - a.y, wz = e.z - a.z;
    v += (ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)) / 6.0L;
  }
  return v;
}

// The constrained facets with their references, as sorted vertex positions.
std::multiset<std::pair<std::array<double, 9>, int>> boundary(const Mesh3& mesh) {
  const MeshData3 d = mesh.domain();
  std::multiset<std::pair<std::array<double, 9>, int>> s;
  for (std::size_t i = 0; i < d.triangles.size(); ++i) {
    std::array<Vec3, 3> p{d.vertices[d.triangles[i][0]], d.vertices[d.triangles[i][1]], d.vertices[d.triangles[i][2]]};
    std::sort(p.begin(), p.end());
    std::array<double, 9> key{};
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) key[a * 3 + c] = comp(p[a], c);
    s.insert({key, d.triangle_refs[i]});
  }
  return s;
}

ControlSpace3 uniform_space(const Metric3& m) { return ControlSpace3::uniform(m, {-1, -1, -1}, {2, 2, 2}); }

TEST(Adapt3d, IsotropicFinerMetricRefinesInteriorKeepsBoundaryAndVolume) {
  const MeshData3 input = cube_mesh(3);
  Mesh3 mesh = mesh3_from_data(input);
  const auto boundary_before = boundary(mesh);
  const long double volume_before = volume(mesh);
  // h = 0.2 in a cube meshed at 1/3: the interior must refine.
  const Adapt3dStats s = adapt3d(mesh, uniform_space(Metric3::isotropic(0.2)));
  mesh.check();
  EXPECT_GT(s.splits, 0u);
  EXPECT_GT(s.after.elements, s.before.elements);
  EXPECT_LE(s.rounds, Adapt3dOptions{}.max_rounds);
  EXPECT_TRUE(s.stopped_by == "converged" || s.stopped_by == "max_rounds") << s.stopped_by;
  EXPECT_GT(s.boundary_splits, 0u);
  // Every boundary facet keeps its face's reference, lies exactly in that face (midpoints of
  // edges in a plane x_i = 0 or 1 keep x_i), and each face keeps its area.
  std::map<int, long double> area;
  const MeshData3 out = mesh.domain();
  for (std::size_t i = 0; i < out.triangles.size(); ++i) {
    const int r = out.triangle_refs[i];
    ASSERT_GE(r, 1);
    ASSERT_LE(r, 6);
    const int axis = (r - 1) / 2, side = (r - 1) % 2;
    for (const auto v : out.triangles[i]) EXPECT_EQ(comp(out.vertices[v], axis), double(side)) << "facet " << i + 1;
    const Vec3 &p = out.vertices[out.triangles[i][0]], &q = out.vertices[out.triangles[i][1]],
               &t = out.vertices[out.triangles[i][2]];
    const long double ux = q.x - p.x, uy = q.y - p.y, uz = q.z - p.z, vx = t.x - p.x, vy = t.y - p.y, vz = t.z - p.z;
    const long double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    area[r] += std::sqrt(cx * cx + cy * cy + cz * cz) / 2.0L;
  }
  ASSERT_EQ(area.size(), 6u);
  for (const auto& [r, a] : area) EXPECT_NEAR(static_cast<double>(a), 1.0, 1e-12) << "face " << r;
  EXPECT_GT(boundary(mesh).size(), boundary_before.size());
  EXPECT_NEAR(static_cast<double>(volume(mesh) / volume_before), 1.0, 1e-12);
  EXPECT_EQ(s.after.inverted, 0u);
  EXPECT_EQ(s.after.flat, 0u);
  EXPECT_GT(s.after.unit_edge_share, s.before.unit_edge_share);
  EXPECT_GT(s.seconds, 0.0);
  EXPECT_GT(s.tetrahedra_per_second, 0.0);
}

TEST(Adapt3d, ConstantAnisotropicMetricConvergesInTheInterior) {
  const MeshData3 input = cube_mesh(4);
  Mesh3 mesh = mesh3_from_data(input);
  // Sizes 0.5 along x, 0.25 along y and z: the boundary (edges 1/4 and their diagonals) is
  // kept, so only the interior edges can reach unit length.
  const Metric3 aniso = Metric3::from_sizes({1, 0, 0}, {0, 1, 0}, 0.5, 0.25, 0.25);
  const Adapt3dStats s = adapt3d(mesh, uniform_space(aniso));
  mesh.check();
  // Measured: 0.728 -> 0.855 unit edges in 11 rounds. The floor 0.8 leaves room for the
  // boundary, kept as it is: its face diagonals (up to sqrt2 in the metric on the x = const faces,
  // its x edges 0.5 long in the metric) cannot change until the boundary operators exist.
  EXPECT_GT(s.after.unit_edge_share, s.before.unit_edge_share);
  EXPECT_GT(s.after.unit_edge_share, 0.8);
  std::cout << "anisotropic cube: unit edges " << s.before.unit_edge_share << " -> " << s.after.unit_edge_share
            << ", worst mean ratio " << s.after.mean_ratio_worst << ", rounds " << s.rounds << " (" << s.stopped_by << ")\n";
  EXPECT_EQ(s.after.inverted, 0u);
  // Deterministic: the same run gives the same mesh.
  Mesh3 again = mesh3_from_data(input);
  const Adapt3dStats s2 = adapt3d(again, uniform_space(aniso));
  EXPECT_EQ(s2.after.elements, s.after.elements);
  EXPECT_EQ(quality_json(s2.after), quality_json(s.after));
}

// The wall's largest distance from the cylinder r = 0.5 over the boundary vertices off the caps.
double wall_error(const Mesh3& mesh) {
  double worst = 0.0;
  const MeshData3 out = mesh.domain();
  for (const auto& t : out.triangles)
    for (const auto v : t) {
      const Vec3& p = out.vertices[v];
      if (p.z > 0.0 && p.z < 1.0) worst = std::max(worst, std::abs(std::hypot(p.x, p.y) - 0.5));
    }
  return worst;
}

TEST(Adapt3d, CylinderWallStaysRoundOnTheSurfaceSupport) {
  // A cylinder of radius 0.5 with 32 vertices a circle: the facets' sagitta is 2.4e-3; refined to
  // h = 0.06, new wall vertices at the facets' midpoints are that far off, on the support within
  // the 2.5e-4 issue 44 asks (measured 1.0e-5 for the support itself).
  const gen::Surface3 surface = gen::capped_cylinder(0.5, 32, 10);
  Mesh3dInput input;
  input.points = surface.points;
  input.triangles = surface.triangles;
  const Mesh3 start = mesh3d(input).mesh;
  const ControlSpace3 size = uniform_space(Metric3::isotropic(0.06));
  Mesh3 on_support = start, on_facets = start;
  const Adapt3dStats s = adapt3d(on_support, size);
  Adapt3dOptions flat;
  flat.surface_support = false;
  adapt3d(on_facets, size, flat);
  on_support.check();
  EXPECT_GT(s.boundary_splits, 200u);
  EXPECT_EQ(s.after.inverted, 0u);
  const double curved = wall_error(on_support), chords = wall_error(on_facets);
  std::cout << "cylinder wall at h = 0.06: " << chords << " off r = 0.5 on the facets, " << curved << " on the support\n";
  EXPECT_GT(chords, 1e-3);
  EXPECT_LT(curved, 2.5e-4);
}

TEST(Adapt3d, RoundsAreBounded) {
  Mesh3 mesh = mesh3_from_data(cube_mesh(2));
  Adapt3dOptions o;
  o.max_rounds = 1;
  const Adapt3dStats s = adapt3d(mesh, uniform_space(Metric3::isotropic(0.1)), o);
  EXPECT_EQ(s.rounds, 1u);
  mesh.check();
}

// --- run_adapt3 --------------------------------------------------------------------------------

struct Files {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("dtlab_adapt3d_" + std::to_string(::getpid()));
  Files() { std::filesystem::create_directories(dir); }
  ~Files() { std::filesystem::remove_all(dir); }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

TEST(RunAdapt3, AdaptsAFileAndKeepsReferences) {
  Files f;
  const MeshData3 input = cube_mesh(3);
  write_mesh3(f.path("cube.mesh"), input);
  std::vector<Metric3> metrics(input.vertices.size(), Metric3::isotropic(0.2));
  write_medit_sol(f.path("cube.sol"), sol_from_metrics(metrics));
  cli::AdaptRequest r;
  r.mesh = f.path("cube.mesh");
  r.metric = f.path("cube.sol");
  r.output = f.path("out.mesh");
  r.stats = true;
  testing::internal::CaptureStdout();
  EXPECT_EQ(cli::run_adapt3(r), 0);
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_NE(out.find("\"stopped_by\":"), std::string::npos);
  const MeshData3 result = read_mesh3(r.output);
  EXPECT_GT(result.tetrahedra.size(), input.tetrahedra.size());
  std::set<int> refs_in(input.triangle_refs.begin(), input.triangle_refs.end());
  std::set<int> refs_out(result.triangle_refs.begin(), result.triangle_refs.end());
  EXPECT_GT(result.triangles.size(), input.triangles.size());  // boundary edges split
  EXPECT_EQ(refs_in, refs_out);
}

TEST(RunAdapt3, BoundaryOptionsActOrAreRefused) {
  Files f;
  const MeshData3 input = cube_mesh(3);
  write_mesh3(f.path("cube.mesh"), input);
  write_medit_sol(f.path("cube.sol"), sol_from_metrics(std::vector<Metric3>(input.vertices.size(), Metric3::isotropic(0.2))));
  cli::AdaptRequest r;
  r.mesh = f.path("cube.mesh");
  r.metric = f.path("cube.sol");
  r.output = f.path("out.mesh");
  r.output_metric = f.path("out.sol");
  r.keep_boundary = true;
  EXPECT_EQ(cli::run_adapt3(r), 0);
  const MeshData3 kept = read_mesh3(r.output);
  EXPECT_EQ(kept.triangles.size(), input.triangles.size());  // no boundary split
  EXPECT_GT(kept.tetrahedra.size(), input.tetrahedra.size());
  EXPECT_EQ(read_metrics<Metric3>(r.output_metric, kept.vertices.size()).size(), kept.vertices.size());
  r.keep_boundary = false;
  r.boundary_deviation = 1e-3;
  try {
    cli::run_adapt3(r);
    FAIL() << "--hausd accepted in 3D, where no boundary vertex is removed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--hausd"), std::string::npos) << e.what();
  }
}

TEST(RunAdapt3, BadInputNamed) {
  Files f;
  const MeshData3 input = cube_mesh(2);
  write_mesh3(f.path("cube.mesh"), input);
  std::vector<Metric3> few(input.vertices.size() - 1, Metric3::isotropic(0.2));
  write_medit_sol(f.path("few.sol"), sol_from_metrics(few));
  cli::AdaptRequest r;
  r.mesh = f.path("cube.mesh");
  r.metric = f.path("few.sol");
  r.output = f.path("out.mesh");
  try {
    cli::run_adapt3(r);
    FAIL() << "a .sol with one value too few was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("few.sol"), std::string::npos) << e.what();
  }
  r.metric = f.path("missing.sol");
  try {
    cli::run_adapt3(r);
    FAIL() << "a missing .sol was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("missing.sol"), std::string::npos) << e.what();
  }
  std::vector<Metric3> ok(input.vertices.size(), Metric3::isotropic(0.2));
  write_medit_sol(f.path("ok.sol"), sol_from_metrics(ok));
  r.metric = f.path("ok.sol");
  r.method = "reconstruct";
  try {
    cli::run_adapt3(r);
    FAIL() << "reconstruct accepted in 3D";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("2D only"), std::string::npos) << e.what();
  }
  r.method = "local";
  r.hgrad = 0.5;
  EXPECT_THROW(cli::run_adapt3(r), InputError);
  r.hgrad.reset();
  r.max_rounds = 0;
  EXPECT_THROW(cli::run_adapt3(r), InputError);
  EXPECT_FALSE(std::filesystem::exists(r.output));
}

}  // namespace
}  // namespace dtlab

namespace dtlab {
namespace {

TEST(Adapt3d, BoundaryRelocationImprovesTheWorstAndKeepsTheFaces) {
  // The anisotropic cube of ConstantAnisotropicMetricConvergesInTheInterior with and without the
  // boundary vertices moved on the support (measured: worst Q_K 2.17 -> 2.05, unit edges 0.855 ->
  // 0.851, 592 moves): the worst is lower, the share of unit edges within a hundredth, every
  // boundary facet still exactly in its face, the volume kept. And the cylinder of
  // CylinderWallStaysRoundOnTheSurfaceSupport, adapted with it to an axial metric: the wall
  // within 2.5e-4 of r = 0.5.
  const Metric3 aniso = Metric3::from_sizes({1, 0, 0}, {0, 1, 0}, 0.5, 0.25, 0.25);
  Adapt3dStats with, without;
  for (const bool relocate : {false, true}) {
    Mesh3 mesh = mesh3_from_data(cube_mesh(4));
    Adapt3dOptions o;
    o.boundary_relocation = relocate;
    const Adapt3dStats s = adapt3d(mesh, uniform_space(aniso), o);
    mesh.check();
    (relocate ? with : without) = s;
    const MeshData3 out = mesh.domain();
    for (std::size_t i = 0; i < out.triangles.size(); ++i) {
      const int r = out.triangle_refs[i], axis = (r - 1) / 2, side = (r - 1) % 2;
      for (const auto v : out.triangles[i]) ASSERT_EQ(comp(out.vertices[v], axis), double(side)) << "facet " << i + 1;
    }
    EXPECT_NEAR(static_cast<double>(volume(mesh)), 1.0, 1e-12);
  }
  EXPECT_EQ(without.boundary_relocations, 0u);
  EXPECT_GT(with.boundary_relocations, 0u);
  EXPECT_LT(with.after.quality_worst, without.after.quality_worst);
  EXPECT_GT(with.after.unit_edge_share, without.after.unit_edge_share - 0.01);

  const gen::Surface3 surface = gen::capped_cylinder(0.5, 32, 10);
  Mesh3dInput input;
  input.points = surface.points;
  input.triangles = surface.triangles;
  Mesh3 cylinder = mesh3d(input).mesh;
  Adapt3dOptions o;
  o.boundary_relocation = true;
  // Sizes 0.15 across the axis and 0.05 along it: the wall's vertices have somewhere to go.
  const Adapt3dStats s = adapt3d(cylinder, uniform_space(Metric3::from_sizes({1, 0, 0}, {0, 1, 0}, 0.15, 0.15, 0.05)), o);
  cylinder.check();
  EXPECT_GT(s.boundary_relocations, 0u);
  EXPECT_LT(wall_error(cylinder), 2.5e-4);
  std::cout << "cylinder, axial metric: " << s.boundary_relocations << " boundary relocations, wall "
            << wall_error(cylinder) << " off r = 0.5\n";
}

}  // namespace
}  // namespace dtlab
