// PatchSurface3: the charts and seams of each kind of surface (patch_surface3.hpp).
#include "algorithms/surface/patch_surface3.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kernel/error.hpp"

namespace dtlab {
namespace {

constexpr double kPi = std::numbers::pi;

void check_positive(double x, const std::string& what, const std::string& patch) {
  if (!(std::isfinite(x) && x > 0.0))
    throw InputError("degenerate patch: " + patch + " " + what + " = " + std::to_string(x) + " (want a positive, finite value)");
}

void check_finite(const Vec3& p, const std::string& what, const std::string& patch) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    throw InputError(patch + ": " + what + " is not finite");
}

// A unit axis and two unit vectors completing it to a right-handed frame (e1 x e2 = axis).
struct Frame {
  Vec3 e1, e2, axis;
};
Frame frame(const Vec3& axis, const std::string& patch) {
  check_finite(axis, "axis", patch);
  const double n = norm(axis);
  if (!(n > 0.0)) throw InputError("degenerate patch: " + patch + " axis is the zero vector");
  const Vec3 a = (1.0 / n) * axis;
  const Vec3 helper = std::abs(a.x) <= std::abs(a.y) && std::abs(a.x) <= std::abs(a.z) ? Vec3{1, 0, 0}
                      : std::abs(a.y) <= std::abs(a.z)                                ? Vec3{0, 1, 0}
                                                                                       : Vec3{0, 0, 1};
  Vec3 e1 = cross(helper, a);
  e1 = (1.0 / norm(e1)) * e1;
  return {e1, cross(a, e1), a};
}

PatchChart3 rectangle(Patch3 patch, const Vec2& lo, const Vec2& hi) {
  return PatchChart3{std::move(patch), false, lo, hi};
}

// Three charts a period (never two): two charts then share one seam at most, so no two of their
// edges can join the same pair of vertices (with two charts, a coarse size joins the same two
// corners in both). A surface periodic in u: charts u in [2 pi i / 3, 2 pi (i + 1) / 3], v in
// [v0, v1], side 1 of chart i against side 3 of chart i + 1 (mod 3).
constexpr std::uint32_t kChartsPerPeriod = 3;
double period_cut(std::uint32_t i) { return i == kChartsPerPeriod ? 2.0 * kPi : 2.0 * kPi * i / kChartsPerPeriod; }

void split_in_u(const Patch3& patch, double v0, double v1, std::vector<PatchChart3>& charts,
                std::vector<PatchSeam3>& seams) {
  const auto first = static_cast<std::uint32_t>(charts.size());
  for (std::uint32_t i = 0; i < kChartsPerPeriod; ++i) charts.push_back(rectangle(patch, {period_cut(i), v0}, {period_cut(i + 1), v1}));
  for (std::uint32_t i = 0; i < kChartsPerPeriod; ++i) seams.push_back({first + i, 1, first + (i + 1) % kChartsPerPeriod, 3});
}

}  // namespace

Vec2 PatchChart3::side_point(std::uint32_t k, double s) const {
  if (disc) {
    const Vec2 c = 0.5 * (lo + hi);
    const double r = 0.5 * (hi.x - lo.x), a = 2.0 * std::numbers::pi * s;
    return {c.x + r * std::cos(a), c.y + r * std::sin(a)};
  }
  const Vec2 corners[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
  const Vec2 a = corners[k], b = corners[(k + 1) % 4];
  if (s == 1.0) return b;  // the corner itself, bit for bit
  return a + s * (b - a);
}

Vec2 PatchChart3::side_derivative(std::uint32_t k, double s) const {
  if (disc) {
    const double r = 0.5 * (hi.x - lo.x), w = 2.0 * std::numbers::pi, a = w * s;
    return {-r * w * std::sin(a), r * w * std::cos(a)};
  }
  const Vec2 corners[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
  return corners[(k + 1) % 4] - corners[k];
}

PatchSurface3 PatchSurface3::plane(const Vec3& origin, const Vec3& e1, const Vec3& e2, const Vec2& lo, const Vec2& hi) {
  PatchSurface3 s;
  s.name_ = "plane";
  check_finite(origin, "origin", s.name_);
  check_finite(e1, "e1", s.name_);
  check_finite(e2, "e2", s.name_);
  check_positive(hi.x - lo.x, "width (u1 - u0)", s.name_);
  check_positive(hi.y - lo.y, "height (v1 - v0)", s.name_);
  s.charts_.push_back(rectangle(Patch3::plane(origin, e1, e2), lo, hi));
  s.check_regular();
  return s;
}

PatchSurface3 PatchSurface3::sphere(const Vec3& centre, double radius) {
  PatchSurface3 s;
  s.name_ = "sphere";
  check_finite(centre, "centre", s.name_);
  check_positive(radius, "radius", s.name_);
  for (std::uint32_t f = 0; f < 6; ++f) s.charts_.push_back(rectangle(Patch3::sphere_face(centre, radius, f), {-1, -1}, {1, 1}));
  // The cube's edges: for every pair of faces that meet, the side of each on the other's plane.
  // Face f has n, a, b (patch3.cpp); its side 0 lies at v = -1 (on the face -b), 1 at u = 1 (+a),
  // 2 at v = 1 (+b), 3 at u = -1 (-a). Found from the axes, each pair once.
  auto side_towards = [](std::uint32_t f, std::uint32_t g) -> std::uint32_t {
    // axes of f: k = f / 2, a = axis (k + 1) % 3, b = sign * axis (k + 2) % 3.
    const std::uint32_t k = f / 2, kg = g / 2;
    const double sf = f % 2 == 0 ? 1.0 : -1.0, sg = g % 2 == 0 ? 1.0 : -1.0;
    if (kg == (k + 1) % 3) return sg > 0 ? 1u : 3u;            // +a or -a
    return (sg * sf) > 0 ? 2u : 0u;                              // +b or -b (b = sf axis)
  };
  for (std::uint32_t f = 0; f < 6; ++f)
    for (std::uint32_t g = f + 1; g < 6; ++g)
      if (f / 2 != g / 2) s.seams_.push_back({f, side_towards(f, g), g, side_towards(g, f)});
  s.check_regular();
  return s;
}

PatchSurface3 PatchSurface3::cylinder(const Vec3& centre, const Vec3& axis, double radius, double height) {
  PatchSurface3 s = cone(centre, axis, radius, radius, height);
  s.name_ = "cylinder";
  return s;
}

PatchSurface3 PatchSurface3::cone(const Vec3& centre, const Vec3& axis, double r0, double r1, double height) {
  PatchSurface3 s;
  s.name_ = r0 == r1 ? "cylinder" : "cone";
  check_finite(centre, "centre", s.name_);
  const Frame f = frame(axis, s.name_);
  check_positive(height, "height", s.name_);
  // A cone through its apex is singular there (sigma_u = 0): refused by name.
  check_positive(r0, "radius at v = 0 (an apex is a singular parametrization)", s.name_);
  check_positive(r1, "radius at v = height (an apex is a singular parametrization)", s.name_);
  split_in_u(Patch3::cone(centre, f.e1, f.e2, r0, r1, height), 0.0, height, s.charts_, s.seams_);
  s.check_regular();
  return s;
}

PatchSurface3 PatchSurface3::torus(const Vec3& centre, const Vec3& axis, double major, double minor) {
  PatchSurface3 s;
  s.name_ = "torus";
  check_finite(centre, "centre", s.name_);
  const Frame f = frame(axis, s.name_);
  check_positive(major, "major radius", s.name_);
  check_positive(minor, "minor radius", s.name_);
  if (!(minor < major))
    throw InputError("degenerate patch: torus minor radius " + std::to_string(minor) + " not below its major radius " +
                     std::to_string(major) + " (the surface meets itself)");
  const Patch3 p = Patch3::torus(centre, f.e1, f.e2, major, minor);
  // Chart (i, j) = 3 j + i: u in the i-th third of the period, v in the j-th.
  constexpr std::uint32_t n = kChartsPerPeriod;
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) s.charts_.push_back(rectangle(p, {period_cut(i), period_cut(j)}, {period_cut(i + 1), period_cut(j + 1)}));
  for (std::uint32_t j = 0; j < n; ++j) {
    for (std::uint32_t i = 0; i < n; ++i) {
      s.seams_.push_back({n * j + i, 1, n * j + (i + 1) % n, 3});  // across u
      s.seams_.push_back({n * j + i, 2, n * ((j + 1) % n) + i, 0});  // across v
    }
  }
  s.check_regular();
  return s;
}

PatchSurface3 PatchSurface3::sine_graph(double amplitude, double frequency_x, double frequency_y, double radius) {
  PatchSurface3 s;
  s.name_ = "sine_graph";
  if (!std::isfinite(amplitude) || !std::isfinite(frequency_x) || !std::isfinite(frequency_y))
    throw InputError("sine_graph: amplitude and frequencies must be finite");
  check_positive(radius, "radius", s.name_);
  s.charts_.push_back(PatchChart3{Patch3::sine_graph(amplitude, frequency_x, frequency_y), true, {-radius, -radius},
                                  {radius, radius}});
  s.check_regular();
  return s;
}

PatchSurface3 PatchSurface3::bspline(Patch3 patch, const Vec2& lo, const Vec2& hi) {
  PatchSurface3 s;
  s.name_ = "bspline";
  s.charts_.push_back(rectangle(std::move(patch), lo, hi));
  s.check_regular();
  return s;
}

double PatchSurface3::extent() const {
  constexpr int kSamples = 17;
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const PatchChart3& chart : charts_) {
    for (int i = 0; i < kSamples; ++i) {
      for (int j = 0; j < kSamples; ++j) {
        const Vec3 p = chart.patch.point({chart.lo.x + (chart.hi.x - chart.lo.x) * i / (kSamples - 1),
                                          chart.lo.y + (chart.hi.y - chart.lo.y) * j / (kSamples - 1)});
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
      }
    }
  }
  return norm(hi - lo);
}

void PatchSurface3::check_regular() const {
  constexpr int kSamples = 17;
  for (std::size_t c = 0; c < charts_.size(); ++c) {
    const PatchChart3& chart = charts_[c];
    for (int i = 0; i < kSamples; ++i) {
      for (int j = 0; j < kSamples; ++j) {
        Vec2 uv{chart.lo.x + (chart.hi.x - chart.lo.x) * i / (kSamples - 1),
                chart.lo.y + (chart.hi.y - chart.lo.y) * j / (kSamples - 1)};
        if (chart.disc) {  // inside the disc: the square's sample pulled in radially
          const Vec2 c0 = 0.5 * (chart.lo + chart.hi), d = uv - c0;
          const double n = std::max(std::abs(d.x), std::abs(d.y));
          if (n > 0.0) uv = c0 + (n / norm(d)) * d;
        }
        const PatchDerivatives d = chart.patch.evaluate(uv);
        const double area = norm(cross(d.du, d.dv)), scale = norm(d.du) * norm(d.dv);
        if (!std::isfinite(area) || !(area > 1e-12 * scale) || !(scale > 0.0)) {
          throw InputError("degenerate patch: " + name_ + " has a singular parametrization at (u, v) = (" +
                           std::to_string(uv.x) + ", " + std::to_string(uv.y) + ") of chart " + std::to_string(c) +
                           " (sigma_u x sigma_v = 0)");
        }
      }
    }
  }
}

}  // namespace dtlab
