#include "verify/generators/points2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <utility>

#include "kernel/error.hpp"
#include "verify/generators/portable_random.hpp"

namespace dtlab {

namespace {

using portable::below;
using portable::normal_pair;
using portable::Rng;
using portable::shuffle;
using portable::unit;

// --- distributions ------------------------------------------------------------------------------

std::vector<Vec2> uniform(std::size_t n, Rng& rng) {
  std::vector<Vec2> p(n);
  for (Vec2& q : p) {
    q.x = unit(rng);
    q.y = unit(rng);
  }
  return p;
}

std::vector<Vec2> normal(std::size_t n, Rng& rng) {
  std::vector<Vec2> p(n);
  for (Vec2& q : p) q = normal_pair(rng);
  return p;
}

std::vector<Vec2> grid(std::size_t n, Rng& rng) {
  std::size_t k = 0;
  while (k * k < n) ++k;
  std::vector<Vec2> p(n);
  for (std::size_t i = 0; i < n; ++i) p[i] = {static_cast<double>(i % k), static_cast<double>(i / k)};
  shuffle(p, rng);
  return p;
}

std::vector<Vec2> circle(std::size_t n, Rng& rng) {
  std::vector<Vec2> p(n);
  for (Vec2& q : p) q = portable::unit_circle(unit(rng));
  return p;
}

// Points of x^2 + y^2 = R^2 for R = p_1 ... p_k, p_i = 1 mod 4 prime: with p = pi conj(pi) in
// the Gaussian integers, every choice of pi^2, p or conj(pi)^2 per prime, times a unit, gives
// a distinct lattice point (unique factorization): 4 * 3^k of them. R stays below 2^53.
std::vector<Vec2> exact_circle_base(std::size_t want) {
  struct Gaussian {
    std::int64_t re, im;
  };
  static constexpr std::array<Gaussian, 10> kPrimes = {
      {{2, 1}, {3, 2}, {4, 1}, {5, 2}, {6, 1}, {5, 4}, {7, 2}, {6, 5}, {8, 3}, {8, 5}}};  // 5 13 17 ... 89
  const auto mul = [](Gaussian a, Gaussian b) { return Gaussian{a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; };
  std::vector<Gaussian> set = {{1, 0}};
  std::size_t count = 4;
  for (std::size_t i = 0; i < kPrimes.size() && count < want; ++i, count *= 3) {
    const Gaussian pi = kPrimes[i];
    const Gaussian conj{pi.re, -pi.im};
    const Gaussian norm{pi.re * pi.re + pi.im * pi.im, 0};
    std::vector<Gaussian> next;
    for (const Gaussian& z : set) {
      for (const Gaussian& f : {mul(pi, pi), norm, mul(conj, conj)}) next.push_back(mul(z, f));
    }
    set = std::move(next);
  }
  std::vector<Vec2> p;
  for (const Gaussian& z : set) {
    for (const Gaussian& unit_factor : {Gaussian{1, 0}, Gaussian{0, 1}, Gaussian{-1, 0}, Gaussian{0, -1}}) {
      const Gaussian w = mul(z, unit_factor);
      p.push_back({static_cast<double>(w.re), static_cast<double>(w.im)});
    }
  }
  return p;
}

std::vector<Vec2> exact_circle(std::size_t n, Rng& rng) {
  std::vector<Vec2> base = exact_circle_base(n);
  std::vector<Vec2> p;
  p.reserve(n);
  // Circle j is the base circle scaled by 2^-j: exact, and still cocircular.
  for (int j = 0; p.size() < n; ++j) {
    shuffle(base, rng);
    for (std::size_t i = 0; i < base.size() && p.size() < n; ++i) p.push_back(std::ldexp(1.0, -j) * base[i]);
  }
  shuffle(p, rng);
  return p;
}

std::vector<Vec2> clustered(std::size_t n, Rng& rng) {
  const std::size_t c = std::min<std::size_t>(1000, std::max<std::size_t>(1, n / 1000));
  const double sigma = 0.05 / std::sqrt(static_cast<double>(c));
  std::vector<Vec2> centers = uniform(c, rng);
  std::vector<Vec2> p(n);
  for (Vec2& q : p) {
    const Vec2 center = centers[below(rng, c)];
    q = center + sigma * normal_pair(rng);
  }
  return p;
}

std::vector<Vec2> collinear(std::size_t n, Rng& rng) {
  std::size_t run = 2;
  while ((run + 1) * (run + 1) <= n) ++run;
  std::vector<Vec2> p;
  p.reserve(n);
  while (p.size() < n) {
    const auto origin_x = static_cast<std::int64_t>(below(rng, std::uint64_t{1} << 26));
    const auto origin_y = static_cast<std::int64_t>(below(rng, std::uint64_t{1} << 26));
    std::int64_t dx = 0, dy = 0;
    while (dx == 0 && dy == 0) {
      dx = static_cast<std::int64_t>(below(rng, 33)) - 16;
      dy = static_cast<std::int64_t>(below(rng, 33)) - 16;
    }
    for (std::int64_t t = 0; t < static_cast<std::int64_t>(run) && p.size() < n; ++t) {
      p.push_back({static_cast<double>(origin_x + t * dx), static_cast<double>(origin_y + t * dy)});
    }
  }
  shuffle(p, rng);
  return p;
}

std::vector<Vec2> duplicates(std::size_t n, Rng& rng) {
  const std::size_t copies = n >= 10 ? n / 10 : (n >= 2 ? 1 : 0);
  std::vector<Vec2> p = uniform(n - copies, rng);
  const std::size_t originals = p.size();
  for (std::size_t i = 0; i < copies; ++i) p.push_back(p[below(rng, originals)]);
  shuffle(p, rng);
  return p;
}

std::vector<Vec2> scaled(std::size_t n, Rng& rng, double scale) {
  std::vector<Vec2> p = uniform(n, rng);
  for (Vec2& q : p) q = scale * q;
  return p;
}

std::vector<Vec2> multiscale(std::size_t n, Rng& rng) {
  static constexpr std::array<double, 19> kScales = {1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0,
                                                     1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9};
  std::vector<Vec2> p = uniform(n, rng);
  for (Vec2& q : p) q = kScales[below(rng, kScales.size())] * q;
  return p;
}

std::vector<Vec2> translated(std::size_t n, Rng& rng) {
  std::vector<Vec2> p = uniform(n, rng);
  for (Vec2& q : p) q = q + Vec2{1e9, 1e9};
  return p;
}

struct Distribution {
  std::string_view name;
  std::string_view description;
  std::vector<Vec2> (*generate)(std::size_t, Rng&);
};

constexpr std::array<Distribution, 12> kDistributions = {{
    {"uniform", "unit square [0,1)^2", uniform},
    {"normal", "standard normal in each coordinate", normal},
    {"grid", "integer lattice ceil(sqrt n) x ceil(sqrt n), shuffled: cocircular 4-tuples everywhere", grid},
    {"circle", "random angles on the unit circle, rounded (not exactly cocircular)", circle},
    {"exact_circle", "integer points exactly on x^2+y^2=R^2 (Gaussian integers); past 236196, circles R/2, R/4, ...",
     exact_circle},
    {"clustered", "Gaussian clusters in the unit square", clustered},
    {"collinear", "runs of about sqrt(n) exactly collinear integer points on random lines", collinear},
    {"duplicates", "uniform with 10% exact copies", duplicates},
    {"scaled_small", "unit square scaled by 1e-9", [](std::size_t n, Rng& r) { return scaled(n, r, 1e-9); }},
    {"scaled_large", "unit square scaled by 1e9", [](std::size_t n, Rng& r) { return scaled(n, r, 1e9); }},
    {"multiscale", "unit square, each point scaled by 10^k, k in -9..9", multiscale},
    {"translated", "unit square translated by (1e9, 1e9)", translated},
}};

}  // namespace

std::vector<Vec2> generate_points2d(std::string_view distribution, std::size_t n, std::uint64_t seed) {
  for (const Distribution& d : kDistributions) {
    if (d.name != distribution) continue;
    Rng rng(seed);
    return d.generate(n, rng);
  }
  std::string known;
  for (const Distribution& d : kDistributions) known += (known.empty() ? "" : ", ") + std::string(d.name);
  throw InputError("unknown 2D point distribution '" + std::string(distribution) + "' (known: " + known + ")");
}

std::vector<std::string> distribution_names2d() {
  std::vector<std::string> names;
  for (const Distribution& d : kDistributions) names.emplace_back(d.name);
  return names;
}

std::string_view distribution_description2d(std::string_view distribution) {
  for (const Distribution& d : kDistributions) {
    if (d.name == distribution) return d.description;
  }
  return "";
}

}  // namespace dtlab
