// Properties of the 3D mesher (algorithms/mesh3d) over random closed surfaces and size fields:
//  - surfaces: ellipsoids (icospheres with random axes: convex), star-shaped polyhedra (an
//    icosphere whose vertices take random radii), boxes with a box hole (random sides and hole
//    placement, faces cut into random grids), each randomly rotated and translated;
//  - sizes: the classical case, uniform sizes (bounded below so that a run stays small), and a
//    graded isotropic field given on a background tetrahedron (a size per corner, interpolated);
// each run: check_mesh3d passes exactly (validity, conformity, the boundary as recovered, region
// volumes), Mesh3::check passes, and a second run on 2 to 4 threads gives the same output bit for
// bit (with 1 to 8 insertion regions). The vertex cap
// (Mesh3dOptions::max_vertices) raises its named InputError. DTLAB_LONG=1 runs more cases with
// finer sizes.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/mesh3d/mesh3d.hpp"
#include "kernel/error.hpp"
#include "kernel/metric.hpp"
#include "kernel/predicates.hpp"
#include "mesh/io/medit3.hpp"
#include "verify/checks_mesh3d.hpp"
#include "verify/tests/box_surface.hpp"

namespace dtlab {
namespace {

bool long_runs() {
  const char* v = std::getenv("DTLAB_LONG");
  return v != nullptr && std::string(v) == "1";
}

// --- RapidCheck plumbing (as mesh2d_property_test) ----------------------------------------------

template <class Testable>
void check_property(const std::string& name, int cases, Testable&& testable) {
  rc::detail::TestParams params = rc::detail::configuration().testParams;
  params.maxSuccess = cases;
  const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info();
  rc::detail::TestMetadata metadata;
  metadata.id = std::string(info->test_suite_name()) + "/" + info->name() + "/" + name;
  metadata.description = name;
  const rc::detail::TestResult result = rc::detail::checkTestable(std::forward<Testable>(testable), metadata, params);
  if (!result.template is<rc::detail::SuccessResult>()) {
    std::ostringstream s;
    rc::detail::printResultMessage(result, s);
    ADD_FAILURE() << name << ": " << s.str();
  }
}

int int_in(int lo, int hi) { return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(lo, hi + 1)); }
double real_in(double lo, double hi) { return lo + (hi - lo) * int_in(0, 1 << 20) / static_cast<double>(1 << 20); }
double log_in(double lo, double hi) { return std::exp(real_in(std::log(lo), std::log(hi))); }

// --- Surfaces -----------------------------------------------------------------------------------

struct Surface : test::SurfaceData {
  double scale = 1.0;  // a typical length: the size of the bounding box
};

// A random rotation (unit quaternion) and translation applied to every point and hole.
void place_randomly(Surface& s) {
  std::array<double, 4> q{real_in(-1, 1), real_in(-1, 1), real_in(-1, 1), real_in(-1, 1)};
  double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (n < 1e-3) q = {1, 0, 0, 0}, n = 1;
  for (double& c : q) c /= n;
  // Named copies, not a structured binding: clang 14 cannot capture bindings in a lambda.
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const Vec3 shift{real_in(-10, 10), real_in(-10, 10), real_in(-10, 10)};
  const auto move = [&](const Vec3& p) {
    return Vec3{(1 - 2 * (y * y + z * z)) * p.x + 2 * (x * y - w * z) * p.y + 2 * (x * z + w * y) * p.z,
                2 * (x * y + w * z) * p.x + (1 - 2 * (x * x + z * z)) * p.y + 2 * (y * z - w * x) * p.z,
                2 * (x * z - w * y) * p.x + 2 * (y * z + w * x) * p.y + (1 - 2 * (x * x + y * y)) * p.z} +
           shift;
  };
  for (Vec3& p : s.points) p = move(p);
  for (Vec3& h : s.holes) h = move(h);
}

// The unit icosphere: the icosahedron's faces cut in four `levels` times, projected on the sphere;
// faces oriented outward.
void icosphere(int levels, std::vector<Vec3>& p, std::vector<std::array<std::uint32_t, 3>>& f) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
       {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9},  {5, 11, 4},
       {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6},  {3, 6, 8},
       {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
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
  for (Vec3& q : p) q = (1.0 / norm(q)) * q;
}

// An ellipsoid with random half-axes (convex).
Surface random_ellipsoid() {
  Surface s;
  icosphere(int_in(1, 2), s.points, s.triangles);
  const Vec3 axes{log_in(0.3, 2.0), log_in(0.3, 2.0), log_in(0.3, 2.0)};
  for (Vec3& p : s.points) p = {axes.x * p.x, axes.y * p.y, axes.z * p.z};
  s.refs.assign(s.triangles.size(), 1);
  s.scale = 2.0 * std::max({axes.x, axes.y, axes.z});
  return s;
}

// A star-shaped polyhedron: each icosphere vertex at a random radius in [0.5, 1.5]. Every face is
// seen from the centre as on the unit sphere (the same orient3d sign), so the central projection makes the surface a
// sphere's: closed and embedded. A radius that would break this is taken back to 1.
Surface random_star() {
  Surface s;
  icosphere(int_in(1, 2), s.points, s.triangles);
  std::vector<Vec3> unit = s.points;
  for (Vec3& p : s.points) p = real_in(0.5, 1.5) * p;
  const Vec3 o{0, 0, 0};
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [a, b, c] : s.triangles)
      if (orient3d(o, s.points[a], s.points[b], s.points[c]) != orient3d(o, unit[a], unit[b], unit[c]))
        for (std::uint32_t v : {a, b, c})
          if (!(s.points[v] == unit[v])) s.points[v] = unit[v], changed = true;
  }
  s.refs.assign(s.triangles.size(), 1);
  s.scale = 3.0;
  return s;
}

using test::add_box;

// A box with a box hole strictly inside it (a hole point marks the hole; or remove_cavities).
Surface random_box_with_hole(bool& by_hole_point) {
  Surface s;
  const Vec3 size{log_in(0.5, 2.0), log_in(0.5, 2.0), log_in(0.5, 2.0)};
  const std::array<int, 3> n{int_in(1, 4), int_in(1, 4), int_in(1, 4)};
  add_box(s, {0, 0, 0}, size, n, 1);
  // The hole: each side a share in [0.2, 0.6] of the box's, placed with a margin of 0.1 sides.
  Vec3 hole_lo{}, hole_size{};
  double* lo[3] = {&hole_lo.x, &hole_lo.y, &hole_lo.z};
  double* hs[3] = {&hole_size.x, &hole_size.y, &hole_size.z};
  const double sides[3] = {size.x, size.y, size.z};
  for (int k = 0; k < 3; ++k) {
    *hs[k] = real_in(0.2, 0.6) * sides[k];
    *lo[k] = real_in(0.1 * sides[k], 0.9 * sides[k] - *hs[k]);
  }
  add_box(s, hole_lo, hole_size, {int_in(1, 2), int_in(1, 2), int_in(1, 2)}, 10);
  by_hole_point = int_in(0, 1) == 1;
  if (by_hole_point) s.holes.push_back(hole_lo + 0.5 * hole_size);
  s.scale = std::max({size.x, size.y, size.z});
  return s;
}

// --- Size fields --------------------------------------------------------------------------------

struct SizeField {
  std::optional<ControlSpace3> control;  // none: the classical case
  std::string name = "classical";
};

Vec3 lower_corner(const Surface& s) {
  Vec3 lo = s.points.front();
  for (const Vec3& p : s.points) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
  return lo;
}
Vec3 upper_corner(const Surface& s) {
  Vec3 hi = s.points.front();
  for (const Vec3& p : s.points) hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  return hi;
}

// Sizes bounded below by scale / fine, so that a run stays small.
SizeField random_size_field(const Surface& s, double fine) {
  SizeField f;
  const Vec3 lo = lower_corner(s), hi = upper_corner(s);
  const double scale = norm(hi - lo);
  switch (int_in(0, 2)) {
    case 0:
      break;
    case 1: {
      const double h = real_in(scale / fine, scale / 3.0);
      f.control.emplace(ControlSpace3::uniform(Metric3::isotropic(h), lo - Vec3{1, 1, 1}, hi + Vec3{1, 1, 1}));
      f.name = "uniform " + std::to_string(h);
      break;
    }
    default: {
      // A background tetrahedron holding the bounding box, a size at each corner: graded linearly.
      const Vec3 c = 0.5 * (lo + hi);
      const double r = 4.0 * scale + 1.0;
      MeshData3 background;
      background.vertices = {c + Vec3{-r, -r, -r}, c + Vec3{3 * r, -r, -r}, c + Vec3{-r, 3 * r, -r},
                             c + Vec3{-r, -r, 3 * r}};
      background.tetrahedra = {{0, 1, 2, 3}};
      background.tetrahedron_refs = {0};
      std::vector<Metric3> metrics;
      f.name = "graded";
      for (int k = 0; k < 4; ++k) {
        const double h = log_in(scale / fine, scale / 2.0);
        metrics.push_back(Metric3::isotropic(h));
        f.name += " " + std::to_string(h);
      }
      f.control.emplace(background, std::move(metrics));
      break;
    }
  }
  return f;
}

// --- The property -------------------------------------------------------------------------------

std::string medit_bytes(const MeshData3& m) {
  std::ostringstream out;
  write_medit3(out, m);
  return out.str();
}

void mesh_and_check(const Surface& s, const SizeField& f, bool remove_cavities) {
  Mesh3dOptions options;
  options.control = f.control ? &*f.control : nullptr;
  options.remove_cavities = remove_cavities;
  options.optimize = int_in(0, 3) != 0;
  options.max_vertices = 200'000;
  // Field points by 1 to 8 regions of at least 32 points (field_point_regions.hpp).
  options.insertion_regions = static_cast<std::uint32_t>(int_in(1, 8));
  options.insertion_region_points = 32;
  RC_TAG(f.name.substr(0, f.name.find(' ')));
  const Mesh3dResult a = mesh3d(s.input(), options);
  const MeshCheckReport3 report = check_mesh3d(s.input(), recover_domain(s.input(), remove_cavities), a.output,
                                                 a.output_metrics, {.remove_cavities = remove_cavities});
  RC_LOG() << f.name << (options.optimize ? ", optimized" : ", not optimized") << ": " << a.output.tetrahedra.size()
           << " tetrahedra\n";
  if (!report.ok) RC_FAIL(to_text(report));
  a.mesh.check();
  // Again on several threads (field_point_regions.hpp): the same bytes.
  options.threads = static_cast<unsigned>(int_in(2, 4));
  const Mesh3dResult b = mesh3d(s.input(), options);
  RC_ASSERT(medit_bytes(a.output) == medit_bytes(b.output));
}

int cases(int normal, int longer) { return long_runs() ? longer : normal; }
double fine() { return long_runs() ? 40.0 : 20.0; }

TEST(Mesh3dProperty, Ellipsoids) {
  check_property("ellipsoid", cases(25, 100), [] {
    Surface s = random_ellipsoid();
    place_randomly(s);
    mesh_and_check(s, random_size_field(s, fine()), false);
  });
}

TEST(Mesh3dProperty, StarShapedPolyhedra) {
  check_property("star", cases(25, 100), [] {
    Surface s = random_star();
    place_randomly(s);
    mesh_and_check(s, random_size_field(s, fine()), false);
  });
}

TEST(Mesh3dProperty, BoxesWithABoxHole) {
  check_property("box with hole", cases(25, 100), [] {
    bool by_hole_point = false;
    Surface s = random_box_with_hole(by_hole_point);
    if (int_in(0, 1) == 1) place_randomly(s);
    mesh_and_check(s, random_size_field(s, fine()), !by_hole_point);
  });
}

TEST(Mesh3dProperty, VertexCapIsNamed) {
  check_property("vertex cap", cases(3, 10), [] {
    Surface s = random_ellipsoid();
    place_randomly(s);
    const Vec3 lo = lower_corner(s), hi = upper_corner(s);
    const ControlSpace3 control =
        ControlSpace3::uniform(Metric3::isotropic(norm(hi - lo) / 20.0), lo - Vec3{1, 1, 1}, hi + Vec3{1, 1, 1});
    Mesh3dOptions options;
    options.control = &control;
    options.max_vertices = static_cast<std::uint64_t>(s.points.size()) + int_in(1, 50);
    try {
      (void)mesh3d(s.input(), options);
      RC_FAIL("no error at a vertex cap of " + std::to_string(options.max_vertices));
    } catch (const InputError& e) {
      RC_ASSERT(std::string(e.what()).find("max_vertices") != std::string::npos);
    }
  });
}

}  // namespace
}  // namespace dtlab
