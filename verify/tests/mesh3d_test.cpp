// The 3D mesher (algorithms/mesh3d): every output passes the exact checks (verify/checks_mesh3d),
// on a cube, a cube minus a ball (by a hole point and by remove_cavities), two cubes sharing an
// internal face; classical, uniform, size-map and anisotropic control spaces; the output is the
// same bytes twice; bad input and bounds are refused by name.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/mesh3d/mesh3d.hpp"
#include "kernel/error.hpp"
#include "kernel/interrupt.hpp"
#include "mesh/io/medit3.hpp"
#include "verify/checks_mesh3d.hpp"
#include "verify/tests/box_surface.hpp"
#include "verify/tests/interrupt_stops.hpp"

namespace dtlab {
namespace {

using test::add_box;
using Surface = test::SurfaceData;

// An icosphere: the icosahedron's faces cut in four `levels` times, projected on the sphere.
void add_sphere(Surface& s, const Vec3& c, double r, int levels, int ref) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> p{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> f{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                              {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                              {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                              {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    const auto middle = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto [it, fresh] = mid.try_emplace({key.first, key.second}, static_cast<std::uint32_t>(p.size()));
      if (fresh) p.push_back(0.5 * (p[a] + p[b]));
      return it->second;
    };
    std::vector<std::array<std::uint32_t, 3>> g;
    for (const auto& [a, b, d] : f) {
      const std::uint32_t ab = middle(a, b), bd = middle(b, d), da = middle(d, a);
      g.push_back({a, ab, da});
      g.push_back({b, bd, ab});
      g.push_back({d, da, bd});
      g.push_back({ab, bd, da});
    }
    f = std::move(g);
  }
  const std::uint32_t base = static_cast<std::uint32_t>(s.points.size());
  for (const Vec3& q : p) s.points.push_back(c + (r / norm(q)) * q);
  for (const auto& [a, b, d] : f) {
    s.triangles.push_back({base + a, base + b, base + d});
    s.refs.push_back(ref);
  }
}

Surface cube(int n) {
  Surface s;
  add_box(s, {0, 0, 0}, 1.0, n, 1);
  return s;
}

Surface cube_minus_ball(int n, int levels, bool hole) {
  Surface s = cube(n);
  add_sphere(s, {0.5, 0.5, 0.5}, 0.25, levels, 10);
  if (hole) s.holes.push_back({0.5, 0.5, 0.5});
  return s;
}

MeshCheckReport3 expect_valid(const Mesh3dInput& input, const Mesh3dResult& r, bool remove_cavities = false) {
  const MeshCheckReport3 c = check_mesh3d(input, recover_domain(input, remove_cavities), r.output, r.output_metrics,
                                              {.remove_cavities = remove_cavities});
  EXPECT_TRUE(c.ok) << to_text(c);
  EXPECT_EQ(c.vertices, r.output.vertices.size());
  EXPECT_EQ(c.tetrahedra, r.output.tetrahedra.size());
  r.mesh.check();
  return c;
}

std::string medit_bytes(const MeshData3& m) {
  std::ostringstream out;
  write_medit3(out, m);
  return out.str();
}

TEST(Mesh3d, CubeClassical) {
  const Surface s = cube(5);
  const Mesh3dResult r = mesh3d(s.input(), {});
  const MeshCheckReport3 c = expect_valid(s.input(), r);
  EXPECT_GT(r.stats.field_points, 10u);
  EXPECT_NEAR(c.volume, 1.0, 1e-12);
  // The faces' grids are cospherical: recovery puts Steiner points on some of them.
  EXPECT_EQ(c.identical_triangles + c.piece_triangles, r.output.triangles.size());
  EXPECT_GT(c.identical_triangles, s.triangles.size() / 2);
  EXPECT_EQ(c.regions, 1u);
  // Classical sizes on a uniform surface grid of h = 0.2: the mesh is near-unit.
  EXPECT_GT(c.quality.unit_edge_share, 0.85);
  EXPECT_LT(c.quality.quality_worst, 10.0);
}

TEST(Mesh3d, CubeUniformSizeWithAndWithoutOptimization) {
  const Surface s = cube(8);
  const ControlSpace3 control = ControlSpace3::uniform(Metric3::isotropic(0.125), {-1, -1, -1}, {2, 2, 2});
  Mesh3dOptions options;
  options.control = &control;
  options.optimize = false;
  const Mesh3dResult raw = mesh3d(s.input(), options);
  const MeshCheckReport3 c0 = expect_valid(s.input(), raw);
  options.optimize = true;
  const Mesh3dResult opt = mesh3d(s.input(), options);
  const MeshCheckReport3 c1 = expect_valid(s.input(), opt);
  EXPECT_GT(c1.quality.unit_edge_share, 0.9);
  EXPECT_LE(c1.quality.quality_worst, c0.quality.quality_worst);
  EXPECT_LT(c1.quality.quality_worst, 5.0);
  EXPECT_GT(c1.quality.angle_min, 10.0);
}

TEST(Mesh3d, CubeMinusBallByHoleAndByRemovedCavity) {
  const Surface holed = cube_minus_ball(6, 2, true);
  Mesh3dOptions options;
  options.optimize = false;
  const Mesh3dResult a = mesh3d(holed.input(), options);
  const MeshCheckReport3 ca = expect_valid(holed.input(), a);
  EXPECT_EQ(ca.regions, 1u);
  EXPECT_LT(ca.volume, 1.0 - 0.05);  // the ball (volume ~0.065) is out
  EXPECT_GE(a.output.triangles.size(), holed.triangles.size());

  const Surface nested = cube_minus_ball(6, 2, false);
  options.remove_cavities = true;
  const Mesh3dResult b = mesh3d(nested.input(), options);
  const MeshCheckReport3 cb = expect_valid(nested.input(), b, true);
  EXPECT_EQ(cb.regions, 1u);
  EXPECT_NEAR(cb.volume, ca.volume, 1e-12);

  // Kept, the ball is a second region with its own reference.
  options.remove_cavities = false;
  const Mesh3dResult both = mesh3d(nested.input(), options);
  const MeshCheckReport3 cc = expect_valid(nested.input(), both);
  EXPECT_EQ(cc.regions, 2u);
  EXPECT_NEAR(cc.volume, 1.0, 1e-12);
}

TEST(Mesh3d, TwoRegionsKeepTheirInternalFace) {
  Surface s;
  add_box(s, {0, 0, 0}, 1.0, 3, 1);
  add_box(s, {1, 0, 0}, 1.0, 3, 11, /*skip_face=*/0);  // shares the face x = 1 of the first box
  const Mesh3dResult r = mesh3d(s.input(), {{.optimize = false}});
  const MeshCheckReport3 c = expect_valid(s.input(), r);
  EXPECT_EQ(c.regions, 2u);
  EXPECT_NEAR(c.volume, 2.0, 1e-12);
  // The internal face's triangles (or their pieces) are output triangles too.
  EXPECT_EQ(c.identical_triangles + c.piece_triangles, r.output.triangles.size());
  EXPECT_GE(r.output.triangles.size(), s.triangles.size());
}

TEST(Mesh3d, SizeMapOnABackgroundMesh) {
  const Surface s = cube(6);
  // The uniform box's six tetrahedra carry sizes 0.08 at the origin's corner, 0.3 elsewhere: the
  // size-map path of the CLI (one metric per background vertex).
  const ControlSpace3 box = ControlSpace3::uniform(Metric3::isotropic(1.0), {0, 0, 0}, {1, 1, 1});
  MeshData3 background;
  background.vertices.assign(box.background().points().begin(), box.background().points().end());
  background.vertex_refs.assign(background.vertices.size(), 0);
  // Kuhn's six tetrahedra around the diagonal, as uniform() makes them.
  const std::array<std::array<std::uint32_t, 3>, 6> orders{{{1, 2, 4}, {1, 4, 2}, {2, 1, 4}, {2, 4, 1}, {4, 1, 2}, {4, 2, 1}}};
  for (const auto& o : orders) {
    std::array<std::uint32_t, 4> t{0, o[0], o[0] | o[1], 7};
    const Vec3 &a = background.vertices[t[0]], &b = background.vertices[t[1]], &c = background.vertices[t[2]],
               &d = background.vertices[t[3]];
    if (dot(b - a, cross(c - a, d - a)) < 0) std::swap(t[1], t[2]);
    background.tetrahedra.push_back(t);
  }
  std::vector<Metric3> metrics(8, Metric3::isotropic(0.3));
  metrics[0] = Metric3::isotropic(0.08);
  const ControlSpace3 control(background, metrics);
  Mesh3dOptions options;
  options.control = &control;
  options.optimize = false;
  const Mesh3dResult r = mesh3d(s.input(), options);
  const MeshCheckReport3 c = expect_valid(s.input(), r);
  // Shorter edges near the origin than far from it.
  double near = 0, far = 0;
  int nn = 0, nf = 0;
  for (const auto& t : r.output.tetrahedra) {
    const Vec3 g = 0.25 * (r.output.vertices[t[0]] + r.output.vertices[t[1]] + r.output.vertices[t[2]] + r.output.vertices[t[3]]);
    const double l = norm(r.output.vertices[t[1]] - r.output.vertices[t[0]]);
    if (g.x + g.y + g.z < 0.9) near += l, ++nn;
    if (g.x + g.y + g.z > 2.1) far += l, ++nf;
  }
  ASSERT_GT(nn, 0);
  ASSERT_GT(nf, 0);
  EXPECT_LT(near / nn, 0.75 * (far / nf));
  EXPECT_GT(c.quality.unit_edge_share, 0.6);
}

TEST(Mesh3d, AnisotropicUniformMetric) {
  const Surface s = cube(6);
  // Sizes 0.08 along x, 0.25 along y and z.
  const Metric3 m = Metric3::from_sizes({1, 0, 0}, {0, 1, 0}, 0.08, 0.25, 0.25);
  const ControlSpace3 control = ControlSpace3::uniform(m, {-1, -1, -1}, {2, 2, 2});
  Mesh3dOptions options;
  options.control = &control;
  options.optimize = false;
  const Mesh3dResult r = mesh3d(s.input(), options);
  const MeshCheckReport3 c = expect_valid(s.input(), r);
  EXPECT_TRUE(c.quality.has_metric);
  // The surface keeps its isotropic grid (h = 1/6): its edges along x are not unit.
  EXPECT_GT(c.quality.unit_edge_share, 0.65);
  EXPECT_GT(c.quality.metric_length_mean, 0.8);
  EXPECT_LT(c.quality.metric_length_mean, 1.3);
  // Euclidean lengths follow the metric: edges along x are shorter than along y.
  double along_x = 0, along_y = 0;
  int nx = 0, ny = 0;
  for (const auto& t : r.output.tetrahedra)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const Vec3 e = r.output.vertices[t[j]] - r.output.vertices[t[i]];
        const double l = norm(e);
        if (std::fabs(e.x) > 0.9 * l) along_x += l, ++nx;
        if (std::fabs(e.y) > 0.9 * l) along_y += l, ++ny;
      }
  ASSERT_GT(nx, 0);
  ASSERT_GT(ny, 0);
  EXPECT_LT(along_x / nx, 0.7 * (along_y / ny));
}

TEST(Mesh3d, Deterministic) {
  const Surface s = cube_minus_ball(5, 2, true);
  const ControlSpace3 control = ControlSpace3::uniform(Metric3::isotropic(0.15), {-1, -1, -1}, {2, 2, 2});
  Mesh3dOptions options;
  options.control = &control;
  const std::string first = medit_bytes(mesh3d(s.input(), options).output);
  const std::string second = medit_bytes(mesh3d(s.input(), options).output);
  EXPECT_EQ(first, second);
  EXPECT_GT(first.size(), 1000u);
  // The field points' filter grid holds its cells in an array (here about a thousand) or, past a
  // bound, in a hash table: the same bytes whichever holds them.
  options.filter_dense_cells = 0;
  EXPECT_EQ(medit_bytes(mesh3d(s.input(), options).output), first);
}

// The field points by regions (field_point_regions.hpp): the same bytes on 1, 2, 3 and 4 threads
// (capped at the cores), with enough points for many regions, some points left to the later
// rounds and to the sequential insertion; every run valid. One region (the default) leaves none,
// and gives another mesh, as valid.
TEST(Mesh3d, SameMeshForEveryThreadCount) {
  const Surface s = cube_minus_ball(6, 2, true);
  const ControlSpace3 control = ControlSpace3::uniform(Metric3::isotropic(0.05), {-1, -1, -1}, {2, 2, 2});
  Mesh3dOptions options;
  options.control = &control;
  options.optimize = false;
  options.insertion_regions = 16;
  options.insertion_region_points = 256;
  const Mesh3dResult one = mesh3d(s.input(), options);
  expect_valid(s.input(), one);
  one.mesh.check();
  const std::string bytes = medit_bytes(one.output);
  EXPECT_GT(one.stats.field_points, 16u * 256u / 4u);
  EXPECT_GT(one.stats.insertion_deferred, 0u);
  for (const unsigned threads : {2u, 3u, 4u}) {
    options.threads = threads;
    const Mesh3dResult r = mesh3d(s.input(), options);
    EXPECT_EQ(medit_bytes(r.output), bytes) << threads << " threads";
    EXPECT_EQ(r.stats.insertion_deferred, one.stats.insertion_deferred) << threads << " threads";
    EXPECT_EQ(r.stats.filtered, one.stats.filtered) << threads << " threads";
  }
  options.threads = 2;
  options.insertion_regions = 1;
  const Mesh3dResult single = mesh3d(s.input(), options);
  expect_valid(s.input(), single);
  EXPECT_EQ(single.stats.insertion_deferred, 0u);
  EXPECT_NE(medit_bytes(single.output), bytes);
  options.threads = 0;
  EXPECT_THROW((void)mesh3d(s.input(), options), InputError);
}

TEST(Mesh3d, OpenSurfaceIsRefusedByName) {
  Surface s;
  add_box(s, {0, 0, 0}, 1.0, 2, 1, /*skip_face=*/3);
  try {
    (void)mesh3d(s.input(), {});
    FAIL() << "an open surface was meshed";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_TRUE(what.find("open") != std::string::npos || what.find("no tetrahedron") != std::string::npos) << what;
  }
}

TEST(Mesh3d, VertexBoundIsANamedError) {
  const Surface s = cube(2);
  const ControlSpace3 control = ControlSpace3::uniform(Metric3::isotropic(0.01), {-1, -1, -1}, {2, 2, 2});
  Mesh3dOptions options;
  options.control = &control;
  options.max_vertices = 500;
  try {
    (void)mesh3d(s.input(), options);
    FAIL() << "the vertex bound was not enforced";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("max_vertices"), std::string::npos) << e.what();
  }
}

TEST(Mesh3d, UnknownAndUnimplementedMethodsAreRefused) {
  const Surface s = cube(2);
  EXPECT_THROW((void)mesh3d(s.input(), {{.method = "front"}}), InputError);
  EXPECT_THROW((void)mesh3d(s.input(), {{.method = "octree"}}), InputError);
}

TEST(ControlSpace3, InterpolatesOnTheBackgroundAndRefusesBadMetrics) {
  MeshData3 bg;
  bg.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  bg.tetrahedra = {{0, 1, 2, 3}};
  std::vector<Metric3> m(4, Metric3::isotropic(1.0));
  m[0] = Metric3::isotropic(0.5);
  const ControlSpace3 c(bg, m);
  std::uint32_t hint = ControlSpace3::kNoHint;
  EXPECT_NEAR(sizes(c.metric_at({0, 0, 0}, hint))[0], 0.5, 1e-12);
  const double h = sizes(c.metric_at({0.25, 0.25, 0.25}, hint))[0];
  EXPECT_GT(h, 0.5);
  EXPECT_LT(h, 1.0);
  // Outside: the nearest point's metric, up to clamping.
  EXPECT_NEAR(sizes(c.metric_at({5, 0, 0}, hint))[2], 1.0, 1e-12);
  m[2].m = {1, 2, 1, 0, 0, 1};  // not positive definite
  EXPECT_THROW(ControlSpace3(bg, m), InputError);
  std::swap(bg.tetrahedra[0][0], bg.tetrahedra[0][1]);  // negative
  EXPECT_THROW(ControlSpace3(bg, std::vector<Metric3>(4)), InputError);
}

// As in 2D: the check is asked between the phases, at each field point pass and in each
// optimization round; a yes stops the run there by Interrupted; a no changes nothing.
TEST(Mesh3d, InterruptCheckStopsTheRunWhereItIsAsked) {
  const Surface s = cube(4);
  std::uint32_t asked = 0;
  Mesh3dOptions options;
  options.interrupt = [&asked] {
    ++asked;
    return false;
  };
  const Mesh3dResult whole = mesh3d(s.input(), options);
  EXPECT_EQ(medit_bytes(whole.output), medit_bytes(mesh3d(s.input(), {}).output));
  ASSERT_GE(asked, 5u);
  const std::vector<std::pair<std::uint32_t, std::string>> stops{
      {1, "after the empty mesh"}, {2, "after the control space"}, {3, "field points"}, {asked, "optimize3d"}};
  const auto run = [&](InterruptCheck check) {
    options.interrupt = std::move(check);
    (void)mesh3d(s.input(), options);
  };
  for (const auto& stop : stops) test::expect_interrupted_at(run, stop.first, stop.second);
}

}  // namespace
}  // namespace dtlab
