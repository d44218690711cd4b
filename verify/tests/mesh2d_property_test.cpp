// Properties of the 2D mesher (algorithms/mesh2d) on the inputs the issue names and mesh2d_test /
// mesh2d_front_test leave out, with both field point methods (edge and front):
//  - small input angles: a spike of random apex angle in [1°, 30°], optionally a notch of another
//    such angle, rotated, translated and scaled (10^-3 .. 10^3);
//  - thin strips, aspect up to 1000:1, with classical, uniform and (aligned or not) anisotropic sizes;
//  - random analytic metric fields given on a background mesh (ControlSpace2 from a grid and its
//    vertex metrics): stretching up to 1000:1, directions rotating with position (linearly, around
//    a centre, across a boundary layer), sizes bounded below so that a run stays small;
// each run: check_mesh2d passes exactly, Mesh2::check passes, the vertex count is bounded by the
// metric area and perimeter of the domain (so no runaway refinement), and a second run gives the
// same output bit for bit. The vertex cap (Mesh2dOptions::max_vertices) raises its named
// InputError, and so does the pass bound. DTLAB_LONG=1 runs more cases with finer fields.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/mesh2d/mesh2d.hpp"
#include "kernel/error.hpp"
#include "kernel/metric.hpp"
#include "verify/checks_mesh2d.hpp"
#include "verify/generators/domains2d.hpp"

namespace dtlab {
namespace {

using Domain = gen::Domain2;
constexpr double kPi = std::numbers::pi;

bool long_runs() {
  const char* v = std::getenv("DTLAB_LONG");
  return v != nullptr && std::string(v) == "1";
}

// --- RapidCheck plumbing ------------------------------------------------------------------------

// Runs a property `cases` times (seed from RC_PARAMS) and reports rapidcheck's minimised
// counterexample as a GoogleTest failure.
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

// Uniform whatever rapidcheck's current size (inRange scales its range with the size).
int int_in(int lo, int hi) { return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(lo, hi + 1)); }
double real_in(double lo, double hi) { return lo + (hi - lo) * int_in(0, 1 << 20) / static_cast<double>(1 << 20); }
double log_in(double lo, double hi) { return std::exp(real_in(std::log(lo), std::log(hi))); }
double degrees(double d) { return d * kPi / 180.0; }

// --- Domains ------------------------------------------------------------------------------------

// Appends the closed polygon `loop`, each side cut into about side / spacing pieces (at most
// max_pieces), with `marker`.
void add_cut_loop(Domain& d, const std::vector<Vec2>& loop, double spacing, int max_pieces, int marker) {
  std::vector<Vec2> cut;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2 a = loop[i], b = loop[(i + 1) % loop.size()];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const int n = std::clamp(static_cast<int>(std::ceil(len / spacing)), 1, max_pieces);
    for (int k = 0; k < n; ++k) {
      const double t = static_cast<double>(k) / n;
      cut.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
  }
  gen::add_loop(d, cut, marker);
}

// p rotated by `angle`, scaled by `scale`, moved by `shift`.
struct Placement {
  double angle = 0, scale = 1;
  Vec2 shift{0, 0};
  Vec2 operator()(const Vec2& p) const {
    const double c = std::cos(angle), s = std::sin(angle);
    return {shift.x + scale * (c * p.x - s * p.y), shift.y + scale * (s * p.x + c * p.y)};
  }
  Vec2 direction(const Vec2& v) const {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
  }
};

// The description printed with a failing case.
struct Case {
  Domain domain;
  std::string text;
};

std::string describe_points(const Domain& d) {
  std::ostringstream s;
  s.precision(17);
  s << d.points.size() << " points:";
  for (const Vec2& p : d.points) s << " (" << p.x << ", " << p.y << ")";
  s << "; " << d.segments.size() << " segments; " << d.holes.size() << " holes";
  return s.str();
}

// --- Checking one run ---------------------------------------------------------------------------

// The metric area of the output, sum over triangles of area * sqrt(det M) at its vertices (mean):
// a mesh of unit triangles has about 2.3 triangles and 1.15 vertices per unit of it, whatever
// the mesh, so it bounds the vertex count independently of the generator's choices.
double metric_area(const Mesh2dResult& r) {
  double total = 0;
  for (const auto& t : r.output.triangles) {
    const Vec2 a = r.output.vertices[t[0]], b = r.output.vertices[t[1]], c = r.output.vertices[t[2]];
    const double area = 0.5 * std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    double density = 0;
    for (std::uint32_t v : t) density += std::sqrt(std::max(0.0, r.output_metrics[v].determinant())) / 3;
    total += area * density;
  }
  return total;
}

// The metric length of the output's boundary edges: a domain thinner than its cells (a strip
// narrower than a tilted anisotropic cell) needs its vertices along the boundary, about one per
// unit of it, whatever its metric area.
double metric_perimeter(const Mesh2dResult& r) {
  double total = 0;
  for (const auto& e : r.output.edges) {
    total += edge_length(r.output.vertices[e[0]], r.output_metrics[e[0]], r.output.vertices[e[1]], r.output_metrics[e[1]]);
  }
  return total;
}

bool same_bits(const MeshData2& a, const MeshData2& b) {
  if (!(a == b)) return false;
  return a.vertices.size() == b.vertices.size() &&
         (a.vertices.empty() || std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vec2)) == 0);
}

// Meshes the case twice with `options`; RC_FAILs with the case on any problem. Returns the first run.
Mesh2dResult mesh_and_check_once(const Case& c, const Mesh2dOptions& options) {
  const std::string where = "method " + options.method + (options.optimize ? ", optimized, " : ", not optimized, ") + c.text +
                            "\n  " + describe_points(c.domain);
  Mesh2dResult r;
  try {
    r = mesh2d(c.domain.input(), options);
  } catch (const std::exception& e) {
    RC_FAIL(std::string("mesh2d threw: ") + e.what() + "\n  " + where);
  }
  if (std::getenv("DTLAB_TRACE") != nullptr) {  // to find a slow case
    std::fprintf(stderr, "%.3f s, %zu triangles: %s\n", r.stats.seconds, r.output.triangles.size(), where.c_str());
  }
  try {
    r.mesh.check();
  } catch (const std::exception& e) {
    RC_FAIL(std::string("Mesh2::check: ") + e.what() + "\n  " + where);
  }
  const MeshCheckReport2 report = check_mesh2d(c.domain.input(), constrained2d(c.domain.input()), r.output);
  if (!report.ok) RC_FAIL("check_mesh2d: " + to_text(report) + "\n  " + where);
  if (r.output.triangles.empty()) RC_FAIL("no triangles\n  " + where);
  const double units = metric_area(r), perimeter = metric_perimeter(r);
  const double bound = 8 * units + 2 * perimeter + 4.0 * (c.domain.points.size() + r.stats.boundary_points) + 100;
  if (static_cast<double>(r.output.vertices.size()) > bound) {
    RC_FAIL(std::to_string(r.output.vertices.size()) + " vertices for a metric area of " + std::to_string(units) +
            " and a metric perimeter of " + std::to_string(perimeter) + " (bound " + std::to_string(bound) + ")\n  " +
            where);
  }
  const Mesh2dResult again = mesh2d(c.domain.input(), options);
  if (!same_bits(r.output, again.output) || !(r.output_metrics == again.output_metrics)) {
    RC_FAIL("a second run gave another mesh (" + std::to_string(again.output.vertices.size()) + " vertices, not " +
            std::to_string(r.output.vertices.size()) + ")\n  " + where);
  }
  return r;
}

// The optimizer (step 5) costs about a hundred times the field points per triangle, so every case
// runs without it and the small ones (this many triangles or fewer) with it as well.
std::size_t optimize_below() { return long_runs() ? 4000 : 300; }

// The case without optimization, then, if small, with it (the mesher's default); returns the first.
Mesh2dResult mesh_and_check(const Case& c, Mesh2dOptions options) {
  options.optimize = false;
  Mesh2dResult r = mesh_and_check_once(c, options);
  RC_TAG(options.method);
  if (r.output.triangles.size() <= optimize_below()) {
    options.optimize = true;
    mesh_and_check_once(c, options);
    RC_TAG("optimized");
  }
  return r;
}

std::string method_in() { return *rc::gen::element(std::string("edge"), std::string("front")); }

// --- Small input angles -------------------------------------------------------------------------

// A disc-like polygon (radius 1) whose rightmost part is a spike: apex angle alpha at distance
// d beyond the chord between its base points; optionally, on the left, a notch cutting into
// the disc with an opening angle beta at its tip.
struct Spike {
  double alpha, d, beta;
  bool notch;
  int body;
};

std::vector<Vec2> spike_polygon(const Spike& s) {
  const double t = std::tan(s.alpha / 2);
  const double phi = std::asin(std::min(0.5, s.d * t));  // base points at angles +-phi
  std::vector<Vec2> loop{{std::cos(phi) + std::sin(phi) / t, 0}};  // the apex: alpha at it (in reals)
  const double psi = s.notch ? std::asin(0.5 * std::tan(s.beta / 2)) : 0;  // notch mouth at pi +- psi
  bool notched = !s.notch;
  for (int k = 0; k <= s.body; ++k) {
    const double a = phi + k * (2 * kPi - 2 * phi) / s.body;
    if (!notched && a > kPi - psi) {
      // Mouth, tip (beta at it, in reals), mouth; the body points near them left out.
      loop.push_back({-std::cos(psi), std::sin(psi)});
      loop.push_back({-std::cos(psi) + std::sin(psi) / std::tan(s.beta / 2), 0});
      loop.push_back({-std::cos(psi), -std::sin(psi)});
      notched = true;
    }
    if (s.notch && std::fabs(a - kPi) <= 1.5 * psi) continue;
    loop.push_back({std::cos(a), std::sin(a)});
  }
  return loop;
}

void small_angle_case(const std::string& method) {
  Spike s;
  s.alpha = degrees(real_in(1, 30));
  s.d = real_in(0.3, std::min(2.0, 0.5 / std::tan(s.alpha / 2)));
  s.notch = *rc::gen::arbitrary<bool>();
  s.beta = degrees(real_in(1, 30));
  s.body = int_in(5, 16);
  Placement place;
  place.angle = real_in(0, 2 * kPi);
  place.scale = log_in(1e-3, 1e3);
  place.shift = {real_in(-10, 10) * place.scale, real_in(-10, 10) * place.scale};
  const int sizing = int_in(0, 2);  // 0 classical, 1 uniform, 2 uniform anisotropic
  const double h = real_in(0.04, 0.3);
  Case c;
  std::vector<Vec2> loop = spike_polygon(s);
  for (Vec2& p : loop) p = place(p);
  add_cut_loop(c.domain, loop, h * place.scale * real_in(0.7, 2.0), 40, 1);
  std::ostringstream text;
  text.precision(17);
  text << "spike alpha " << s.alpha * 180 / kPi << " deg, d " << s.d << ", notch " << s.notch << " beta "
       << s.beta * 180 / kPi << " deg, body " << s.body << ", placement angle " << place.angle << " scale " << place.scale
       << ", sizing " << sizing << " h " << h;
  c.text = text.str();
  Mesh2dOptions options;
  options.method = method;
  const Vec2 lo{place.shift.x - 4 * place.scale, place.shift.y - 4 * place.scale};
  const Vec2 hi{place.shift.x + 4 * place.scale, place.shift.y + 4 * place.scale};
  ControlSpace2 control = ControlSpace2::uniform(Metric2::isotropic(h * place.scale), lo, hi);
  if (sizing == 2) {
    const double a = real_in(0, kPi);
    control = ControlSpace2::uniform(Metric2::from_sizes(place.direction({std::cos(a), std::sin(a)}), h * place.scale,
                                                         h * place.scale / real_in(1, 8)),
                                     lo, hi);
  }
  if (sizing > 0) options.control = &control;
  mesh_and_check(c, options);
}

TEST(Mesh2dProperty, SmallInputAnglesMeshValidly) {
  const int cases = long_runs() ? 500 : 30;
  for (const char* method : {"edge", "front"}) {
    check_property(method, cases, [method] { small_angle_case(method); });
  }
}

// The smallest case of each family, fixed, so that a regression shows without rapidcheck.
TEST(Mesh2dProperty, OneDegreeSpike) {
  Case c;
  add_cut_loop(c.domain, spike_polygon({degrees(1), 2.0, degrees(1), true, 8}), 0.1, 40, 1);
  c.text = "1 degree spike and notch";
  for (const char* method : {"edge", "front"}) {
    Mesh2dOptions options;
    options.method = method;
    const ControlSpace2 control = ControlSpace2::uniform(Metric2::isotropic(0.1), {-4, -4}, {4, 4});
    options.control = &control;
    const MeshCheckReport2 report = [&] {
      const Mesh2dResult r = mesh2d(c.domain.input(), options);
      r.mesh.check();
      return check_mesh2d(c.domain.input(), constrained2d(c.domain.input()), r.output);
    }();
    EXPECT_TRUE(report.ok) << method << ": " << to_text(report);
  }
}

// --- Thin strips ---------------------------------------------------------------------------------

void thin_strip_case(const std::string& method) {
  const double aspect = log_in(1, 1000);
  const double w = 1 / aspect;
  // With classical sizes, the spacing ratio between the long sides (1 / n) and the short ones
  // (w / m) grades the sizes along the strip; beyond about 50 the edge method slows down sharply
  // (a 240:1 strip, long sides uncut, short ones in 4: 6 s for 5,700 triangles, 90 candidates
  // filtered per point inserted, against 0.2 s for the front method), so that is for DTLAB_LONG.
  const int m = int_in(1, 4);
  const int n_min = std::max(1, static_cast<int>(std::ceil(m * aspect / (long_runs() ? 1000.0 : 50.0))));
  const int n = int_in(n_min, std::max(n_min, 60));
  Placement place;
  place.angle = real_in(0, 2 * kPi);
  place.shift = {real_in(-2, 2), real_in(-2, 2)};
  std::vector<Vec2> loop;
  for (int i = 0; i < n; ++i) loop.push_back(place({static_cast<double>(i) / n, 0}));
  for (int i = 0; i < m; ++i) loop.push_back(place({1, w * i / m}));
  for (int i = n; i > 0; --i) loop.push_back(place({static_cast<double>(i) / n, w}));
  for (int i = m; i > 0; --i) loop.push_back(place({0, w * i / m}));
  Case c;
  gen::add_loop(c.domain, loop, 1);
  const int sizing = int_in(0, 3);  // classical, uniform, anisotropic along the strip, anisotropic at an angle
  const double along = log_in(std::min(w, 0.3), 0.3);
  const double across = sizing == 1 ? along : w / real_in(1, 3);
  const double tilt = sizing == 3 ? real_in(0, kPi) : 0;
  const bool resample = sizing > 0 && *rc::gen::arbitrary<bool>();
  std::ostringstream text;
  text.precision(17);
  text << "strip aspect " << aspect << ", " << n << " x " << m << " pieces, angle " << place.angle << ", sizing "
       << sizing << " along " << along << " across " << across << " tilt " << tilt << ", resample " << resample;
  c.text = text.str();
  Mesh2dOptions options;
  options.method = method;
  options.keep_boundary = !resample;
  const ControlSpace2 control = ControlSpace2::uniform(
      Metric2::from_sizes(place.direction({std::cos(tilt), std::sin(tilt)}), along, across), {-5, -5}, {5, 5});
  if (sizing > 0) options.control = &control;
  mesh_and_check(c, options);
}

TEST(Mesh2dProperty, ThinStripsMeshValidly) {
  const int cases = long_runs() ? 500 : 30;
  for (const char* method : {"edge", "front"}) {
    check_property(method, cases, [method] { thin_strip_case(method); });
  }
}

// --- Analytic metric fields on a background mesh ---------------------------------------------------

// A metric field: sizes h_long along a direction that rotates with position and h_long / s(p)
// across it, s(p) = s_max^g(p) with g in [0, 1] smooth; or a boundary layer across a line.
struct Field {
  int kind = 0;  // 0 direction rotating linearly, 1 around a centre, 2 a boundary layer
  double theta0 = 0, omega = 0, beta = 0, h_long = 0.1, s_max = 1, h_min = 1e-3, wave = 1, phase = 0;
  Vec2 centre{0.5, 0.5};

  Metric2 at(const Vec2& p) const {
    const Vec2 q{p.x - centre.x, p.y - centre.y};
    const Vec2 n{std::cos(beta), std::sin(beta)};
    if (kind == 2) {
      // Sizes h_long along the layer, h_min at it growing linearly to h_long at distance 1/2 across.
      const double dist = std::fabs(q.x * n.x + q.y * n.y);
      const double across = std::min(h_long, h_min + 2 * (h_long - h_min) * dist);
      const double bend = omega * (q.x * -n.y + q.y * n.x);  // the layer's normal turns along it
      return Metric2::from_sizes({std::cos(beta + bend), std::sin(beta + bend)}, across, h_long);
    }
    const double theta = kind == 0 ? theta0 + omega * (q.x * n.x + q.y * n.y) : theta0 + std::atan2(q.y, q.x);
    const double g = 0.5 + 0.5 * std::sin(wave * p.x + phase) * std::cos(wave * p.y);
    const double across = std::max(h_min, h_long / std::pow(s_max, g));
    return Metric2::from_sizes({std::cos(theta), std::sin(theta)}, h_long, across);
  }
};

std::string describe(const Field& f) {
  std::ostringstream s;
  s.precision(17);
  s << "field kind " << f.kind << " theta0 " << f.theta0 << " omega " << f.omega << " beta " << f.beta << " h_long "
    << f.h_long << " s_max " << f.s_max << " h_min " << f.h_min << " wave " << f.wave << " phase " << f.phase
    << " centre (" << f.centre.x << ", " << f.centre.y << ")";
  return s.str();
}

// The field on a k x k grid over [lo, hi]^2.
ControlSpace2 grid_control(const Field& f, int k, double lo, double hi, MetricInterpolation mode) {
  MeshData2 bg;
  for (int j = 0; j <= k; ++j) {
    for (int i = 0; i <= k; ++i) bg.vertices.push_back({lo + (hi - lo) * i / k, lo + (hi - lo) * j / k});
  }
  for (int j = 0; j < k; ++j) {
    for (int i = 0; i < k; ++i) {
      const auto a = static_cast<std::uint32_t>(j * (k + 1) + i), b = a + 1, c = a + k + 2, e = a + k + 1;
      bg.triangles.push_back({a, b, c});
      bg.triangles.push_back({a, c, e});
    }
  }
  std::vector<Metric2> metrics;
  for (const Vec2& p : bg.vertices) metrics.push_back(f.at(p));
  return ControlSpace2(bg, std::move(metrics), mode);
}

void metric_field_case(const std::string& method) {
  // Cells no smaller than this in metric-unit area h_long * h_across (1000:1 needs h_long >= 0.7).
  const double cell = long_runs() ? 1e-4 : 5e-4;
  Field f;
  f.kind = int_in(0, 2);
  f.theta0 = real_in(0, kPi);
  f.omega = real_in(-2 * kPi, 2 * kPi);
  f.beta = real_in(0, kPi);
  f.centre = {real_in(-0.5, 1.5), real_in(-0.5, 1.5)};
  f.wave = real_in(0, 8);
  f.phase = real_in(0, 2 * kPi);
  f.s_max = log_in(1, 1000);
  f.h_long = real_in(std::max(0.05, std::sqrt(cell * f.s_max)), 1.0);
  f.h_min = std::max(cell / f.h_long, f.kind == 2 ? log_in(1e-3, 0.05) : 1e-3);
  Case c;
  const bool square = *rc::gen::arbitrary<bool>();
  if (square) {
    add_cut_loop(c.domain, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 1.0 / int_in(1, 12), 12, 1);
  } else {
    const int n = int_in(3, 16);
    std::vector<Vec2> outer;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * kPi * i / n, r = real_in(0.25, 0.5);
      outer.push_back({0.5 + r * std::cos(a), 0.5 + r * std::sin(a)});
    }
    add_cut_loop(c.domain, outer, 0.1, 8, 1);
    if (*rc::gen::arbitrary<bool>()) {
      gen::add_loop(c.domain, gen::circle_polygon({0.5, 0.5}, 0.1, int_in(3, 12)), 2);
      c.domain.holes.push_back({0.5, 0.5});
    }
  }
  const int k = int_in(4, 24);
  const MetricInterpolation mode = *rc::gen::element(MetricInterpolation::Sizes, MetricInterpolation::LogEuclidean);
  const ControlSpace2 control = grid_control(f, k, -0.25, 1.25, mode);
  Mesh2dOptions options;
  options.method = method;
  options.control = &control;
  options.keep_boundary = *rc::gen::arbitrary<bool>();
  std::ostringstream text;
  text.precision(17);
  text << describe(f) << "; background " << k << " x " << k << ", log-euclidean " << (mode == MetricInterpolation::LogEuclidean)
       << ", square " << square << ", keep boundary " << options.keep_boundary;
  c.text = text.str();
  mesh_and_check(c, options);
}

TEST(Mesh2dProperty, AnalyticMetricFieldsMeshValidly) {
  const int cases = long_runs() ? 400 : 25;
  for (const char* method : {"edge", "front"}) {
    check_property(method, cases, [method] { metric_field_case(method); });
  }
}

// --- Bounds ------------------------------------------------------------------------------------------

// A cap below what the mesh needs raises the named error, wherever it falls (optimization off,
// so that the insertion count is the run's: the optimizer's splits come after the cap's check).
void vertex_cap_case() {
  const std::string method = method_in();
  Case c;
  const int n = int_in(3, 12);
  std::vector<Vec2> outer;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * kPi * i / n, r = real_in(0.4, 1.0);
    outer.push_back({r * std::cos(a), r * std::sin(a)});
  }
  add_cut_loop(c.domain, outer, 0.2, 8, 1);
  const double h = real_in(0.03, 0.1);
  c.text = "star " + std::to_string(n) + ", h " + std::to_string(h);
  const ControlSpace2 control = ControlSpace2::uniform(Metric2::from_sizes({1, 0}, h, h / real_in(1, 4)), {-2, -2}, {2, 2});
  Mesh2dOptions options;
  options.method = method;
  options.control = &control;
  options.optimize = false;
  const Mesh2dResult full = mesh_and_check_once(c, options);
  const std::uint64_t live = full.mesh.live_vertex_count();
  const std::uint64_t first = live - full.stats.field_points;  // before the first field point
  RC_PRE(full.stats.field_points > 0);
  options.max_vertices = *rc::gen::inRange<std::uint64_t>(first, live);
  try {
    mesh2d(c.domain.input(), options);
    RC_FAIL("a cap of " + std::to_string(options.max_vertices) + " for " + std::to_string(live) + " vertices was not reached\n  " +
            c.text + ", method " + method);
  } catch (const InputError& e) {
    const std::string what = e.what();
    RC_ASSERT(what.find("vertex bound of " + std::to_string(options.max_vertices)) != std::string::npos);
  }
}

TEST(Mesh2dProperty, VertexCapRaisesItsNamedError) { check_property("cap", long_runs() ? 300 : 20, vertex_cap_case); }

TEST(Mesh2dBounds, CapOnAFineSizeStopsEarly) {
  // h = 10^-4 on the unit square would need ~10^8 vertices: the cap stops it at once, by name.
  Domain d;
  add_cut_loop(d, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.25, 4, 1);
  const ControlSpace2 control = ControlSpace2::uniform(Metric2::isotropic(1e-4), {-1, -1}, {2, 2});
  for (const char* method : {"edge", "front"}) {
    Mesh2dOptions options;
    options.method = method;
    options.control = &control;
    options.max_vertices = 2000;
    options.max_elements = std::uint64_t{1} << 40;  // past the estimate: the run's own bound acts
    options.keep_boundary = true;
    try {
      mesh2d(d.input(), options);
      ADD_FAILURE() << method << ": no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("vertex bound of 2000"), std::string::npos) << e.what();
    }
  }
  // With the boundary cut in the size, the boundary alone needs 40,000 points: refused before any is made.
  Mesh2dOptions options;
  options.control = &control;
  options.max_vertices = 2000;
  options.max_elements = std::uint64_t{1} << 40;
  try {
    mesh2d(d.input(), options);
    ADD_FAILURE() << "resample: no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex bound of 2000"), std::string::npos) << e.what();
  }
}

TEST(Mesh2dBounds, ElementEstimateRefusesBeforeAnyWork) {
  // h = 10^-4 on the unit square: about 2.3 10^8 triangles (1 / (h^2 sqrt 3 / 4)). Under a limit
  // of 10^8 it is refused with the estimate; above it the estimate passes (the run is then bounded
  // by the vertex bound, as above).
  Domain d;
  add_cut_loop(d, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.25, 4, 1);
  const ControlSpace2 control = ControlSpace2::uniform(Metric2::isotropic(1e-4), {-1, -1}, {2, 2});
  Mesh2dOptions options;
  options.control = &control;
  options.max_elements = 100'000'000;
  try {
    mesh2d(d.input(), options);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("asks for about 2.31e+08 triangles"), std::string::npos) << what;
    EXPECT_NE(what.find("limit of 100000000"), std::string::npos) << what;
  }
  options.max_elements = 300'000'000;
  options.max_vertices = 2000;
  try {
    mesh2d(d.input(), options);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex bound of 2000"), std::string::npos) << e.what();
  }
  // A metric of 10^300 I: its complexity overflows, refused all the same.
  const ControlSpace2 huge = ControlSpace2::uniform(Metric2{{1e300, 0, 1e300}}, {-1, -1}, {2, 2});
  options.control = &huge;
  EXPECT_THROW(mesh2d(d.input(), options), InputError);
}

TEST(Mesh2dBounds, PassBoundRaisesItsNamedError) {
  Domain d;
  add_cut_loop(d, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.25, 4, 1);
  const ControlSpace2 control = ControlSpace2::uniform(Metric2::isotropic(0.01), {-1, -1}, {2, 2});
  Mesh2dOptions options;
  options.control = &control;
  options.max_passes = 2;
  try {
    mesh2d(d.input(), options);
    ADD_FAILURE() << "edge: no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did not saturate within 2 passes"), std::string::npos) << e.what();
  }
  options.method = "front";
  try {
    mesh2d(d.input(), options);
    ADD_FAILURE() << "front: no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("within 2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dtlab
