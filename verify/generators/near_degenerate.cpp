// Adversarial predicate inputs (see near_degenerate.hpp). The exactly degenerate sets are
// integer points, so that degeneracy survives the conversion to double; the near-degenerate
// sets are rounded real constructions moved by a few ulps.
#include "verify/generators/near_degenerate.hpp"

#include <bit>
#include <cmath>
#include <numbers>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"

namespace dtlab::gen {

double unit(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

double uniform(Rng& rng, double lo, double hi) { return lo + (hi - lo) * unit(rng); }

std::int64_t integer(Rng& rng, std::int64_t lo, std::int64_t hi) {
  DTLAB_ASSERT(lo <= hi);
  const std::uint64_t span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo) + 1;
  // span == 0 means the whole 64-bit range; the modulo bias is below 2^-40 for our spans.
  const std::uint64_t r = span == 0 ? rng() : rng() % span;
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(lo) + r);
}

double clamp_to_range(double v) {
  if (std::isnan(v)) return 0.0;
  const double m = std::fabs(v);
  if (m == 0.0 || coordinate_in_range(v)) return v;
  return std::copysign(m > kMaxCoordinateMagnitude ? kMaxCoordinateMagnitude : kMinCoordinateMagnitude, v);
}

double nudge(double v, int steps) {
  for (int i = 0; i < steps; ++i) v = std::nextafter(v, HUGE_VAL);
  for (int i = 0; i > steps; --i) v = std::nextafter(v, -HUGE_VAL);
  return clamp_to_range(v);
}

namespace {
int steps(Rng& rng, int max_steps) { return static_cast<int>(integer(rng, -max_steps, max_steps)); }
}  // namespace

Vec2 nudge(Rng& rng, const Vec2& p, int max_steps) {
  const double x = nudge(p.x, steps(rng, max_steps));
  return {x, nudge(p.y, steps(rng, max_steps))};
}

Vec3 nudge(Rng& rng, const Vec3& p, int max_steps) {
  const double x = nudge(p.x, steps(rng, max_steps));
  const double y = nudge(p.y, steps(rng, max_steps));
  return {x, y, nudge(p.z, steps(rng, max_steps))};
}

double coordinate_from_bits(std::uint64_t bits) {
  constexpr std::uint64_t kExponentMask = 0x7ffULL << 52;
  double v = std::bit_cast<double>(bits);
  if (!std::isfinite(v)) v = std::bit_cast<double>((bits & ~kExponentMask) | (1023ULL << 52));
  if (v == 0.0) return v;
  const int e = std::ilogb(v);
  if (e >= kMinCoordinateExponent && e < kMaxCoordinateExponent) return v;
  const int period = kMaxCoordinateExponent - kMinCoordinateExponent;  // 284 exponents
  const int folded = kMinCoordinateExponent + ((e - kMinCoordinateExponent) % period + period) % period;
  return std::scalbn(v, folded - e);  // exact: only the exponent changes, even from a subnormal
}

// --- point sets ------------------------------------------------------------------------------

std::vector<Vec2> uniform_box(Rng& rng, std::size_t n, const Vec2& lo, const Vec2& hi) {
  std::vector<Vec2> out(n);
  for (Vec2& p : out) {
    p.x = clamp_to_range(uniform(rng, lo.x, hi.x));
    p.y = clamp_to_range(uniform(rng, lo.y, hi.y));
  }
  return out;
}

std::vector<Vec3> uniform_box(Rng& rng, std::size_t n, const Vec3& lo, const Vec3& hi) {
  std::vector<Vec3> out(n);
  for (Vec3& p : out) {
    p.x = clamp_to_range(uniform(rng, lo.x, hi.x));
    p.y = clamp_to_range(uniform(rng, lo.y, hi.y));
    p.z = clamp_to_range(uniform(rng, lo.z, hi.z));
  }
  return out;
}

namespace {
double int_coord(Rng& rng, std::int64_t bound) { return static_cast<double>(integer(rng, -bound, bound)); }

Vec2 int_vec2(Rng& rng, std::int64_t bound, bool nonzero) {
  for (;;) {
    const Vec2 v{int_coord(rng, bound), int_coord(rng, bound)};
    if (!nonzero || v != Vec2{}) return v;
  }
}

Vec3 int_vec3(Rng& rng, std::int64_t bound, bool nonzero) {
  for (;;) {
    const Vec3 v{int_coord(rng, bound), int_coord(rng, bound), int_coord(rng, bound)};
    if (!nonzero || v != Vec3{}) return v;
  }
}

// The first n entries of a random permutation of `all` (partial Fisher-Yates, our own integer()).
template <class P>
std::vector<P> sample(Rng& rng, std::vector<P> all, std::size_t n) {
  DTLAB_ASSERT(n <= all.size());
  for (std::size_t i = 0; i < n; ++i) {
    const auto j = static_cast<std::size_t>(integer(rng, static_cast<std::int64_t>(i),
                                                    static_cast<std::int64_t>(all.size() - 1)));
    std::swap(all[i], all[j]);
  }
  all.resize(n);
  return all;
}

const std::vector<Vec2>& circle_lattice() {
  static const std::vector<Vec2> points = [] {
    constexpr std::int64_t r = 5LL * 13 * 17 * 29 * 37;
    std::vector<Vec2> out;
    for (std::int64_t x = -r; x <= r; ++x) {
      const std::int64_t y2 = r * r - x * x;
      const auto y = static_cast<std::int64_t>(std::llround(std::sqrt(static_cast<double>(y2))));
      if (y * y != y2) continue;
      out.push_back({double(x), double(y)});
      if (y != 0) out.push_back({double(x), double(-y)});
    }
    return out;
  }();
  return points;
}

const std::vector<Vec3>& sphere_lattice() {
  static const std::vector<Vec3> points = [] {
    constexpr std::int64_t r = 45;
    std::vector<Vec3> out;
    for (std::int64_t x = -r; x <= r; ++x) {
      for (std::int64_t y = -r; y <= r; ++y) {
        const std::int64_t z2 = r * r - x * x - y * y;
        if (z2 < 0) continue;
        const auto z = static_cast<std::int64_t>(std::llround(std::sqrt(static_cast<double>(z2))));
        if (z * z != z2) continue;
        out.push_back({double(x), double(y), double(z)});
        if (z != 0) out.push_back({double(x), double(y), double(-z)});
      }
    }
    return out;
  }();
  return points;
}
}  // namespace

std::vector<Vec2> exact_collinear2(Rng& rng, std::size_t n) {
  const Vec2 a = int_vec2(rng, (1 << 20) - 1, false);
  const Vec2 d = int_vec2(rng, 1 << 10, true);
  std::vector<Vec2> out(n);
  for (Vec2& p : out) p = a + int_coord(rng, 1 << 20) * d;
  return out;
}

std::vector<Vec3> exact_collinear3(Rng& rng, std::size_t n) {
  const Vec3 a = int_vec3(rng, (1 << 20) - 1, false);
  const Vec3 d = int_vec3(rng, 1 << 10, true);
  std::vector<Vec3> out(n);
  for (Vec3& p : out) p = a + int_coord(rng, 1 << 20) * d;
  return out;
}

std::vector<Vec3> exact_coplanar3(Rng& rng, std::size_t n) {
  const Vec3 a = int_vec3(rng, (1 << 20) - 1, false);
  const Vec3 u = int_vec3(rng, 1 << 8, true);
  Vec3 v;
  do v = int_vec3(rng, 1 << 8, true);
  while (cross(u, v) == Vec3{});  // a plane, not a line
  std::vector<Vec3> out(n);
  for (Vec3& p : out) {
    const double s = int_coord(rng, 1 << 12);
    p = a + s * u + int_coord(rng, 1 << 12) * v;
  }
  return out;
}

std::vector<Vec2> exact_cocircular2(Rng& rng, std::size_t n) {
  const Vec2 c = int_vec2(rng, (1 << 20) - 1, false);
  std::vector<Vec2> out = sample(rng, circle_lattice(), n);
  for (Vec2& p : out) p = p + c;
  return out;
}

std::vector<Vec3> exact_cospherical3(Rng& rng, std::size_t n) {
  const Vec3 c = int_vec3(rng, (1 << 20) - 1, false);
  std::vector<Vec3> out = sample(rng, sphere_lattice(), n);
  for (Vec3& p : out) p = p + c;
  return out;
}

std::vector<Vec2> near_collinear2(Rng& rng, std::size_t n, int max_steps) {
  const Vec2 a{uniform(rng, -1, 1), uniform(rng, -1, 1)};
  const Vec2 b{uniform(rng, -1, 1), uniform(rng, -1, 1)};
  std::vector<Vec2> out(n);
  for (Vec2& p : out) {
    const double t = uniform(rng, -2, 3);
    p = nudge(rng, Vec2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}, max_steps);
  }
  return out;
}

std::vector<Vec2> near_cocircular2(Rng& rng, std::size_t n, int max_steps) {
  const Vec2 c{uniform(rng, -1, 1), uniform(rng, -1, 1)};
  const double r = uniform(rng, 0.1, 2);
  std::vector<Vec2> out(n);
  for (Vec2& p : out) {
    const double t = uniform(rng, 0, 2 * std::numbers::pi);
    p = nudge(rng, Vec2{c.x + r * std::cos(t), c.y + r * std::sin(t)}, max_steps);
  }
  return out;
}

std::vector<Vec3> near_coplanar3(Rng& rng, std::size_t n, int max_steps) {
  const Vec3 a{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
  const Vec3 u{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
  const Vec3 v{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
  std::vector<Vec3> out(n);
  for (Vec3& p : out) {
    const double s = uniform(rng, -1, 1);
    const double t = uniform(rng, -1, 1);
    p = nudge(rng, a + s * u + t * v, max_steps);
  }
  return out;
}

std::vector<Vec3> near_cospherical3(Rng& rng, std::size_t n, int max_steps) {
  const Vec3 c{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
  const double r = uniform(rng, 0.1, 2);
  std::vector<Vec3> out(n);
  for (Vec3& p : out) {
    Vec3 dir;
    double len;
    do {  // a direction uniform on the sphere: rejection from the cube
      dir = {uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
      len = norm(dir);
    } while (len > 1.0 || len < 0.1);
    p = nudge(rng, c + (r / len) * dir, max_steps);
  }
  return out;
}

// --- transformations -------------------------------------------------------------------------

std::vector<Vec2> scaled(std::span<const Vec2> points, int exponent) {
  std::vector<Vec2> out;
  out.reserve(points.size());
  for (const Vec2& p : points)
    out.push_back({clamp_to_range(std::ldexp(p.x, exponent)), clamp_to_range(std::ldexp(p.y, exponent))});
  return out;
}

std::vector<Vec3> scaled(std::span<const Vec3> points, int exponent) {
  std::vector<Vec3> out;
  out.reserve(points.size());
  for (const Vec3& p : points)
    out.push_back({clamp_to_range(std::ldexp(p.x, exponent)), clamp_to_range(std::ldexp(p.y, exponent)),
                   clamp_to_range(std::ldexp(p.z, exponent))});
  return out;
}

std::vector<Vec2> translated(std::span<const Vec2> points, const Vec2& offset) {
  std::vector<Vec2> out;
  out.reserve(points.size());
  for (const Vec2& p : points) out.push_back({clamp_to_range(p.x + offset.x), clamp_to_range(p.y + offset.y)});
  return out;
}

std::vector<Vec3> translated(std::span<const Vec3> points, const Vec3& offset) {
  std::vector<Vec3> out;
  out.reserve(points.size());
  for (const Vec3& p : points)
    out.push_back({clamp_to_range(p.x + offset.x), clamp_to_range(p.y + offset.y), clamp_to_range(p.z + offset.z)});
  return out;
}

// --- named families --------------------------------------------------------------------------

const char* to_string(Family f) noexcept {
  switch (f) {
    case Family::Uniform: return "uniform";
    case Family::Exact: return "exact";
    case Family::Near: return "near";
    case Family::SmallGrid: return "small-grid";
    case Family::ExactLarge: return "exact-large";
    case Family::ExactSmall: return "exact-small";
    case Family::NearLarge: return "near-large";
    case Family::NearSmall: return "near-small";
    case Family::ExactFar: return "exact-far";
    case Family::NearFar: return "near-far";
    case Family::Bits: return "bits";
  }
  return "unknown";
}

namespace {
constexpr int kNearSteps = 3;
constexpr int kNearLargeExponent = 138;
constexpr int kNearSmallExponent = -120;

std::vector<Vec2> exact2(Rng& rng, Shape s, std::size_t n) {
  return s == Shape::Flat ? exact_collinear2(rng, n) : exact_cocircular2(rng, n);
}
std::vector<Vec3> exact3(Rng& rng, Shape s, std::size_t n) {
  return s == Shape::Flat ? exact_coplanar3(rng, n) : exact_cospherical3(rng, n);
}
std::vector<Vec2> near2(Rng& rng, Shape s, std::size_t n) {
  return s == Shape::Flat ? near_collinear2(rng, n, kNearSteps) : near_cocircular2(rng, n, kNearSteps);
}
std::vector<Vec3> near3(Rng& rng, Shape s, std::size_t n) {
  return s == Shape::Flat ? near_coplanar3(rng, n, kNearSteps) : near_cospherical3(rng, n, kNearSteps);
}
}  // namespace

std::vector<Vec2> family_points2(Rng& rng, Family f, Shape s, std::size_t n) {
  switch (f) {
    case Family::Uniform: return uniform_box(rng, n, Vec2{-1, -1}, Vec2{1, 1});
    case Family::Exact: return exact2(rng, s, n);
    case Family::Near: return near2(rng, s, n);
    case Family::SmallGrid: {
      std::vector<Vec2> out(n);
      for (Vec2& p : out) p = int_vec2(rng, 3, false);
      return out;
    }
    case Family::ExactLarge: return scaled(exact2(rng, s, n), kLargeExponent);
    case Family::ExactSmall: return scaled(exact2(rng, s, n), kSmallExponent);
    case Family::NearLarge: return scaled(near2(rng, s, n), kNearLargeExponent);
    case Family::NearSmall: return scaled(near2(rng, s, n), kNearSmallExponent);
    case Family::ExactFar: return translated(exact2(rng, s, n), Vec2{kFarOffset, kFarOffset});
    case Family::NearFar: return translated(near2(rng, s, n), Vec2{kFarOffset, kFarOffset});
    case Family::Bits: {
      std::vector<Vec2> out(n);
      for (Vec2& p : out) {
        const double x = coordinate_from_bits(rng());
        p = {x, coordinate_from_bits(rng())};
      }
      return out;
    }
  }
  DTLAB_ASSERT(false && "unknown family");
  return {};
}

std::vector<Vec3> family_points3(Rng& rng, Family f, Shape s, std::size_t n) {
  switch (f) {
    case Family::Uniform: return uniform_box(rng, n, Vec3{-1, -1, -1}, Vec3{1, 1, 1});
    case Family::Exact: return exact3(rng, s, n);
    case Family::Near: return near3(rng, s, n);
    case Family::SmallGrid: {
      std::vector<Vec3> out(n);
      for (Vec3& p : out) p = int_vec3(rng, 3, false);
      return out;
    }
    case Family::ExactLarge: return scaled(exact3(rng, s, n), kLargeExponent);
    case Family::ExactSmall: return scaled(exact3(rng, s, n), kSmallExponent);
    case Family::NearLarge: return scaled(near3(rng, s, n), kNearLargeExponent);
    case Family::NearSmall: return scaled(near3(rng, s, n), kNearSmallExponent);
    case Family::ExactFar: return translated(exact3(rng, s, n), Vec3{kFarOffset, kFarOffset, kFarOffset});
    case Family::NearFar: return translated(near3(rng, s, n), Vec3{kFarOffset, kFarOffset, kFarOffset});
    case Family::Bits: {
      std::vector<Vec3> out(n);
      for (Vec3& p : out) {
        const double x = coordinate_from_bits(rng());
        const double y = coordinate_from_bits(rng());
        p = {x, y, coordinate_from_bits(rng())};
      }
      return out;
    }
  }
  DTLAB_ASSERT(false && "unknown family");
  return {};
}

}  // namespace dtlab::gen
