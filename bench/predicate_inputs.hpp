// Inputs of bench/predicates_bench: fixed-seed arrays of point tuples, generated once and shared
// by the dtlab and the CGAL translation units, so that every implementation sees the same cases
// and input generation is never timed.
//
// Three named distributions per predicate:
//   random      independent points uniform in [-1, 1)^d;
//   near        points on a line / circle / plane / sphere, rounded to doubles and then moved by
//               up to 3 ulps per coordinate: the semi-static filter mostly cannot decide;
//   degenerate  exactly collinear / cocircular / coplanar / cospherical points of an integer
//               grid: the exact answer is zero.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include "kernel/sign.hpp"
#include "kernel/vec.hpp"

namespace dtlab::bench {

enum class Dist { Random, Near, Degenerate };
inline constexpr std::array<Dist, 3> kDists = {Dist::Random, Dist::Near, Dist::Degenerate};
inline const char* to_string(Dist d) {
  return d == Dist::Random ? "random" : (d == Dist::Near ? "near" : "degenerate");
}

// Cases per distribution, cycled. Many on purpose: a current branch predictor memorises the
// outcomes of a few thousand repeated cases (measured here: with 4096 cases, a predicate that
// branches on the sign of random determinants looked 8x cheaper than with 65536), and a
// predicate's sign in a triangulation does not repeat with a short period. The largest array
// (insphere, 7.5 MiB) streams sequentially, which the hardware prefetcher keeps up with.
inline constexpr std::size_t kCases = std::size_t{1} << 16;

using Orient2dCase = std::array<Vec2, 3>;
using IncircleCase = std::array<Vec2, 4>;
using Orient3dCase = std::array<Vec3, 4>;
using InsphereCase = std::array<Vec3, 5>;

namespace detail {

// A generator whose output does not depend on the standard library's distributions.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }  // [0, 1)
  double symmetric() { return 2.0 * unit() - 1.0; }                        // [-1, 1)
  long integer(long lo, long hi) {                                           // [lo, hi]
    return lo + static_cast<long>(engine_() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  // v moved by k ulps, k uniform in [-3, 3].
  double nudge(double v) {
    const long k = integer(-3, 3);
    for (long i = 0; i < k; ++i) v = std::nextafter(v, HUGE_VAL);
    for (long i = 0; i > k; --i) v = std::nextafter(v, -HUGE_VAL);
    return v;
  }
  Vec2 nudge(const Vec2& p) { return {nudge(p.x), nudge(p.y)}; }
  Vec3 nudge(const Vec3& p) { return {nudge(p.x), nudge(p.y), nudge(p.z)}; }
  Vec2 point2() { return {symmetric(), symmetric()}; }
  Vec3 point3() { return {symmetric(), symmetric(), symmetric()}; }
  Vec2 grid2(long r) { return {double(integer(-r, r)), double(integer(-r, r))}; }
  Vec3 grid3(long r) { return {double(integer(-r, r)), double(integer(-r, r)), double(integer(-r, r))}; }
  long nonzero(long r) {
    for (;;)
      if (const long v = integer(-r, r); v != 0) return v;
  }
  template <class T>
  void shuffle(std::vector<T>& v) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[engine_() % i]);
  }

 private:
  std::mt19937_64 engine_;
};

inline std::uint64_t seed(Dist d, int predicate) {
  return 0x5eed0000u + 16u * static_cast<unsigned>(predicate) + static_cast<unsigned>(d);
}

inline Orient2dCase make_orient2d(Rng& rng, Dist d) {
  switch (d) {
    case Dist::Random: return {rng.point2(), rng.point2(), rng.point2()};
    case Dist::Near: {
      const Vec2 a = rng.point2(), b = rng.point2();
      const Vec2 c = a + rng.unit() * (b - a);
      return {a, b, rng.nudge(c)};
    }
    case Dist::Degenerate: {
      const Vec2 a = rng.grid2(1000);
      const Vec2 u{double(rng.nonzero(20)), double(rng.nonzero(20))};
      return {a, a + double(rng.nonzero(50)) * u, a + double(rng.nonzero(50)) * u};
    }
  }
  return {};
}

inline IncircleCase make_incircle(Rng& rng, Dist d) {
  IncircleCase t;
  switch (d) {
    case Dist::Random:
      for (Vec2& p : t) p = rng.point2();
      break;
    case Dist::Near: {
      const Vec2 c = rng.point2();
      const double r = 0.25 + 0.75 * rng.unit();
      for (Vec2& p : t) {
        const double phi = 2.0 * std::numbers::pi * rng.unit();
        p = rng.nudge(c + r * Vec2{std::cos(phi), std::sin(phi)});
      }
      break;
    }
    case Dist::Degenerate: {
      // The 8 lattice points (+-p, +-q), (+-q, +-p) lie on the circle of radius^2 p^2 + q^2.
      const Vec2 c = rng.grid2(1000);
      const long p = rng.integer(1, 50), q = p + rng.integer(1, 50);
      std::vector<Vec2> on;
      for (const long sx : {-1L, 1L})
        for (const long sy : {-1L, 1L}) {
          on.push_back(c + Vec2{double(sx * p), double(sy * q)});
          on.push_back(c + Vec2{double(sx * q), double(sy * p)});
        }
      rng.shuffle(on);
      for (std::size_t i = 0; i < t.size(); ++i) t[i] = on[i];
      break;
    }
  }
  return t;
}

inline Orient3dCase make_orient3d(Rng& rng, Dist d) {
  switch (d) {
    case Dist::Random: return {rng.point3(), rng.point3(), rng.point3(), rng.point3()};
    case Dist::Near: {
      const Vec3 a = rng.point3(), b = rng.point3(), c = rng.point3();
      const Vec3 p = a + rng.unit() * (b - a) + rng.unit() * (c - a);
      return {a, b, c, rng.nudge(p)};
    }
    case Dist::Degenerate: {
      const Vec3 a = rng.grid3(1000);
      const Vec3 u{double(rng.nonzero(20)), double(rng.nonzero(20)), double(rng.nonzero(20))};
      const Vec3 v{double(rng.nonzero(20)), double(rng.nonzero(20)), double(rng.nonzero(20))};
      auto in_plane = [&] { return a + double(rng.nonzero(30)) * u + double(rng.nonzero(30)) * v; };
      return {a, in_plane(), in_plane(), in_plane()};
    }
  }
  return {};
}

inline InsphereCase make_insphere(Rng& rng, Dist d) {
  InsphereCase t;
  switch (d) {
    case Dist::Random:
      for (Vec3& p : t) p = rng.point3();
      break;
    case Dist::Near: {
      const Vec3 c = rng.point3();
      const double r = 0.25 + 0.75 * rng.unit();
      for (Vec3& p : t) {
        const double z = rng.symmetric(), phi = 2.0 * std::numbers::pi * rng.unit();
        const double s = std::sqrt(1.0 - z * z);
        p = rng.nudge(c + r * Vec3{s * std::cos(phi), s * std::sin(phi), z});
      }
      break;
    }
    case Dist::Degenerate: {
      // The 48 signed permutations of (p, q, r) lie on the sphere of radius^2 p^2 + q^2 + r^2.
      const Vec3 c = rng.grid3(1000);
      const long p = rng.integer(1, 30), q = p + rng.integer(1, 30), r = q + rng.integer(1, 30);
      const std::array<std::array<long, 3>, 6> perms = {
          {{p, q, r}, {p, r, q}, {q, p, r}, {q, r, p}, {r, p, q}, {r, q, p}}};
      std::vector<Vec3> on;
      for (const auto& v : perms)
        for (int s = 0; s < 8; ++s)
          on.push_back(c + Vec3{double(s & 1 ? -v[0] : v[0]), double(s & 2 ? -v[1] : v[1]),
                                double(s & 4 ? -v[2] : v[2])});
      rng.shuffle(on);
      for (std::size_t i = 0; i < t.size(); ++i) t[i] = on[i];
      break;
    }
  }
  return t;
}

template <class Case, class Make>
const std::vector<Case>& cached(Dist d, int predicate, Make make) {
  static std::array<std::vector<Case>, 3> cache;
  std::vector<Case>& v = cache[static_cast<std::size_t>(d)];
  if (v.empty()) {
    Rng rng(seed(d, predicate));
    v.reserve(kCases);
    for (std::size_t i = 0; i < kCases; ++i) v.push_back(make(rng, d));
  }
  return v;
}

}  // namespace detail

inline const std::vector<Orient2dCase>& orient2d_cases(Dist d) {
  return detail::cached<Orient2dCase>(d, 0, detail::make_orient2d);
}
inline const std::vector<IncircleCase>& incircle_cases(Dist d) {
  return detail::cached<IncircleCase>(d, 1, detail::make_incircle);
}
inline const std::vector<Orient3dCase>& orient3d_cases(Dist d) {
  return detail::cached<Orient3dCase>(d, 2, detail::make_orient3d);
}
inline const std::vector<InsphereCase>& insphere_cases(Dist d) {
  return detail::cached<InsphereCase>(d, 3, detail::make_insphere);
}

// What the timed loop does with each sign:
//   Sum     adds it to a checksum: no branch on the sign, so the time is the predicate's own;
//   Branch  branches on it, as a triangulation's walk or cavity search does: each call then
//           pays the misprediction of an unpredictable sign in the caller (once per call, since a
//           predicate that branched on the same sign inside leaves it predictable).
enum class Consumer { Sum, Branch };
inline const char* to_string(Consumer c) { return c == Consumer::Sum ? "sum" : "branch"; }

// The benchmark name every implementation shares:
// "<predicate>/<implementation>/<distribution>/<consumer>".
inline std::string bench_name(const char* predicate, const char* impl, Dist d, Consumer c) {
  return std::string(predicate) + "/" + impl + "/" + to_string(d) + "/" + to_string(c);
}

inline int score(Sign s) { return to_int(s); }
inline int score(FilteredSign s) { return s ? to_int(*s) : 0; }
inline bool undecided(Sign) { return false; }
inline bool undecided(FilteredSign s) { return !s; }

// Runs `predicate` over all cases per iteration. DoNotOptimize on every call keeps the compiler
// from vectorising across cases or hoisting the work (or the stage counters' increments) out of
// the loop, and, in the Branch consumer, from turning the branch into a conditional move.
// Reports items/s, time per call and, from one untimed pass, the sum of the signs (equal for every
// exact implementation) and the share of undecided cases (filter stages alone).
template <class Case, class F>
void run_cases(::benchmark::State& state, const std::vector<Case>& cases, Consumer consumer,
               F predicate) {
  long sum = 0, positive = 0, negative = 0;
  if (consumer == Consumer::Sum) {
    for (auto _ : state)
      for (const Case& c : cases) {
        sum += score(predicate(c));
        ::benchmark::DoNotOptimize(sum);
      }
  } else {
    for (auto _ : state)
      for (const Case& c : cases) {
        const int s = score(predicate(c));
        if (s > 0)
          ::benchmark::DoNotOptimize(++positive);
        else if (s < 0)
          ::benchmark::DoNotOptimize(++negative);
      }
  }
  const double n = static_cast<double>(cases.size());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(cases.size()));
  // Seconds per call, which the console shows with an SI prefix ("9.1n" is 9.1 ns).
  state.counters["time_per_call"] = ::benchmark::Counter(
      n, ::benchmark::Counter::kIsIterationInvariantRate | ::benchmark::Counter::kInvert);
  long pass_sum = 0, pass_undecided = 0;
  for (const Case& c : cases) {
    const auto s = predicate(c);
    pass_sum += score(s);
    pass_undecided += undecided(s);
  }
  state.counters["sign_sum"] = static_cast<double>(pass_sum);
  state.counters["undecided"] = static_cast<double>(pass_undecided) / n;
}

}  // namespace dtlab::bench
