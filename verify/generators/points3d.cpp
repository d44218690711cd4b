#include "verify/generators/points3d.hpp"

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

// Uniform integer in [lo, hi], as a double.
double integer(Rng& rng, std::int64_t lo, std::int64_t hi) {
  return static_cast<double>(lo + static_cast<std::int64_t>(below(rng, static_cast<std::uint64_t>(hi - lo + 1))));
}

// Three standard normals (a second pair's second value is dropped, keeping draws simple).
Vec3 normal3(Rng& rng) {
  const auto [x, y] = normal_pair(rng);
  const double z = normal_pair(rng).x;
  return {x, y, z};
}

// --- distributions ------------------------------------------------------------------------------

std::vector<Vec3> uniform(std::size_t n, Rng& rng) {
  std::vector<Vec3> p(n);
  for (Vec3& q : p) {
    q.x = unit(rng);
    q.y = unit(rng);
    q.z = unit(rng);
  }
  return p;
}

std::vector<Vec3> normal(std::size_t n, Rng& rng) {
  std::vector<Vec3> p(n);
  for (Vec3& q : p) q = normal3(rng);
  return p;
}

std::vector<Vec3> grid(std::size_t n, Rng& rng) {
  std::size_t k = 0;
  while (k * k * k < n) ++k;
  std::vector<Vec3> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    p[i] = {static_cast<double>(i / (k * k)), static_cast<double>(i / k % k), static_cast<double>(i % k)};
  }
  shuffle(p, rng);
  return p;
}

std::vector<Vec3> sphere(std::size_t n, Rng& rng) {
  std::vector<Vec3> p(n);
  for (Vec3& q : p) {
    // Archimedes: z uniform in [-1, 1] and a uniform angle give a uniform point of the sphere.
    const double z = 2.0 * unit(rng) - 1.0;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const auto [c, s] = portable::unit_circle(unit(rng));
    q = {r * c, r * s, z};
  }
  return p;
}

// Every integer point of x^2 + y^2 + z^2 = R^2: the solutions with x >= y >= z >= 0, then their
// 48 images under coordinate permutations and sign changes (without repeats).
std::vector<Vec3> integer_sphere(std::int64_t R) {
  const std::int64_t R2 = R * R;
  const auto isqrt = [](std::int64_t v) {
    auto s = static_cast<std::int64_t>(std::sqrt(static_cast<double>(v)));
    while (s * s > v) --s;
    while ((s + 1) * (s + 1) <= v) ++s;
    return s;
  };
  std::vector<std::array<std::int64_t, 3>> all;
  for (std::int64_t x = 0; x <= R; ++x) {
    const std::int64_t rest = R2 - x * x;  // y^2 + z^2
    // z <= y <= x: y^2 >= rest / 2 and y <= min(x, sqrt(rest)).
    for (std::int64_t y = std::max<std::int64_t>(0, isqrt(rest / 2) - 1); y <= std::min(x, isqrt(rest)); ++y) {
      const std::int64_t z2 = rest - y * y;
      const std::int64_t z = isqrt(z2);
      if (z * z != z2 || z > y) continue;
      std::array<std::int64_t, 3> c = {z, y, x};  // ascending, for next_permutation
      do {
        for (int signs = 0; signs < 8; ++signs) {
          const std::array<std::int64_t, 3> s = {(signs & 1) ? -c[0] : c[0], (signs & 2) ? -c[1] : c[1],
                                                 (signs & 4) ? -c[2] : c[2]};
          all.push_back(s);
        }
      } while (std::next_permutation(c.begin(), c.end()));
    }
  }
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  std::vector<Vec3> p;
  p.reserve(all.size());
  for (const auto& c : all) p.push_back({static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2])});
  return p;
}

std::vector<Vec3> exact_sphere(std::size_t n, Rng& rng) {
  // Products of small odd primes have many representations as sums of three squares.
  static constexpr std::array<std::int64_t, 9> kRadii = {9, 21, 45, 105, 225, 585, 1155, 3465, 15015};
  std::vector<Vec3> base;
  for (const std::int64_t R : kRadii) {
    base = integer_sphere(R);
    if (base.size() >= n) break;
  }
  std::vector<Vec3> p;
  p.reserve(n);
  // Sphere j is the base sphere scaled by 2^-j: exact, and still cospherical.
  for (int j = 0; p.size() < n; ++j) {
    shuffle(base, rng);
    for (std::size_t i = 0; i < base.size() && p.size() < n; ++i) p.push_back(std::ldexp(1.0, -j) * base[i]);
  }
  shuffle(p, rng);
  return p;
}

std::vector<Vec3> clustered(std::size_t n, Rng& rng) {
  const std::size_t c = std::min<std::size_t>(1000, std::max<std::size_t>(1, n / 1000));
  std::size_t side = 1;  // ceil(cbrt c), without the C library's cbrt
  while (side * side * side < c) ++side;
  const double sigma = 0.05 / static_cast<double>(side);
  const std::vector<Vec3> centers = uniform(c, rng);
  std::vector<Vec3> p(n);
  for (Vec3& q : p) q = centers[below(rng, c)] + sigma * normal3(rng);
  return p;
}

// A random integer vector with coordinates in [-m, m], not zero.
std::array<std::int64_t, 3> small_vector(Rng& rng, std::int64_t m) {
  std::array<std::int64_t, 3> v{};
  while (v[0] == 0 && v[1] == 0 && v[2] == 0)
    for (std::int64_t& c : v) c = static_cast<std::int64_t>(below(rng, static_cast<std::uint64_t>(2 * m + 1))) - m;
  return v;
}

// 10% (at least one for n >= 10) random integer points in [0, 2^bits)^3.
std::vector<Vec3> off_points(std::size_t n, int bits, Rng& rng) {
  std::vector<Vec3> p(n / 10);
  const std::int64_t hi = (std::int64_t{1} << bits) - 1;
  for (Vec3& q : p) q = {integer(rng, 0, hi), integer(rng, 0, hi), integer(rng, 0, hi)};
  return p;
}

std::vector<Vec3> coplanar(std::size_t n, Rng& rng) {
  // Planes c + s u + t v through the middle of [0, 2^20)^3, |u|, |v| <= 8, |s|, |t| <= 2^14: every
  // point stays inside the cube, every coordinate an integer.
  constexpr std::int64_t kCentre = std::int64_t{1} << 19, kSpan = std::int64_t{1} << 14;
  std::vector<Vec3> p = off_points(n, 20, rng);
  const std::size_t on_planes = n - p.size();
  for (std::size_t plane = 0; plane < 4; ++plane) {
    std::array<std::int64_t, 3> u{}, v{};
    while (true) {
      u = small_vector(rng, 8), v = small_vector(rng, 8);
      const std::int64_t cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
      if (cx != 0 || cy != 0 || cz != 0) break;
    }
    std::array<double, 3> c{};
    for (double& x : c) x = integer(rng, kCentre - 4096, kCentre + 4096);
    const std::size_t count = on_planes / 4 + (plane < on_planes % 4 ? 1 : 0);
    for (std::size_t i = 0; i < count; ++i) {
      const double s = integer(rng, -kSpan, kSpan), t = integer(rng, -kSpan, kSpan);
      p.push_back({c[0] + s * static_cast<double>(u[0]) + t * static_cast<double>(v[0]),
                   c[1] + s * static_cast<double>(u[1]) + t * static_cast<double>(v[1]),
                   c[2] + s * static_cast<double>(u[2]) + t * static_cast<double>(v[2])});
    }
  }
  shuffle(p, rng);
  return p;
}

std::vector<Vec3> collinear(std::size_t n, Rng& rng) {
  std::vector<Vec3> p = off_points(n, 26, rng);
  const std::size_t on_lines = n - p.size();
  std::size_t run = 2;
  while ((run + 1) * (run + 1) <= on_lines) ++run;
  std::size_t placed = 0;
  while (placed < on_lines) {
    std::array<double, 3> o{};
    for (double& x : o) x = integer(rng, 0, (std::int64_t{1} << 26) - 1);
    const auto d = small_vector(rng, 16);
    for (std::size_t t = 0; t < run && placed < on_lines; ++t, ++placed) {
      const auto k = static_cast<double>(t);
      p.push_back({o[0] + k * static_cast<double>(d[0]), o[1] + k * static_cast<double>(d[1]),
                   o[2] + k * static_cast<double>(d[2])});
    }
  }
  shuffle(p, rng);
  return p;
}

std::vector<Vec3> duplicates(std::size_t n, Rng& rng) {
  const std::size_t copies = n >= 10 ? n / 10 : (n >= 2 ? 1 : 0);
  std::vector<Vec3> p = uniform(n - copies, rng);
  const std::size_t originals = p.size();
  for (std::size_t i = 0; i < copies; ++i) p.push_back(p[below(rng, originals)]);
  shuffle(p, rng);
  return p;
}

std::vector<Vec3> scaled(std::size_t n, Rng& rng, double scale) {
  std::vector<Vec3> p = uniform(n, rng);
  for (Vec3& q : p) q = scale * q;
  return p;
}

std::vector<Vec3> multiscale(std::size_t n, Rng& rng) {
  static constexpr std::array<double, 19> kScales = {1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0,
                                                     1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9};
  std::vector<Vec3> p = uniform(n, rng);
  for (Vec3& q : p) q = kScales[below(rng, kScales.size())] * q;
  return p;
}

std::vector<Vec3> translated(std::size_t n, Rng& rng) {
  std::vector<Vec3> p = uniform(n, rng);
  for (Vec3& q : p) q = q + Vec3{1e9, 1e9, 1e9};
  return p;
}

struct Distribution {
  std::string_view name;
  std::string_view description;
  std::vector<Vec3> (*generate)(std::size_t, Rng&);
};

constexpr std::array<Distribution, 13> kDistributions = {{
    {"uniform", "unit cube [0,1)^3", uniform},
    {"normal", "standard normal in each coordinate", normal},
    {"grid", "integer lattice k^3, k = ceil(cbrt n), shuffled: cospherical 5-tuples everywhere", grid},
    {"sphere", "random points of the unit sphere, rounded (not exactly cospherical)", sphere},
    {"exact_sphere", "integer points exactly on x^2+y^2+z^2=R^2; past R=15015's, spheres R/2, R/4, ...", exact_sphere},
    {"clustered", "Gaussian clusters in the unit cube", clustered},
    {"coplanar", "90% on four random integer planes (exactly coplanar), 10% random integer points", coplanar},
    {"collinear", "90% in runs of about sqrt(n) exactly collinear integer points, 10% off them", collinear},
    {"duplicates", "uniform with 10% exact copies", duplicates},
    {"scaled_small", "unit cube scaled by 1e-9", [](std::size_t n, Rng& r) { return scaled(n, r, 1e-9); }},
    {"scaled_large", "unit cube scaled by 1e9", [](std::size_t n, Rng& r) { return scaled(n, r, 1e9); }},
    {"multiscale", "unit cube, each point scaled by 10^k, k in -9..9", multiscale},
    {"translated", "unit cube translated by (1e9, 1e9, 1e9)", translated},
}};

}  // namespace

std::vector<Vec3> generate_points3d(std::string_view distribution, std::size_t n, std::uint64_t seed) {
  for (const Distribution& d : kDistributions) {
    if (d.name != distribution) continue;
    Rng rng(seed);
    return d.generate(n, rng);
  }
  std::string known;
  for (const Distribution& d : kDistributions) known += (known.empty() ? "" : ", ") + std::string(d.name);
  throw InputError("unknown 3D point distribution '" + std::string(distribution) + "' (known: " + known + ")");
}

std::vector<std::string> distribution_names3d() {
  std::vector<std::string> names;
  for (const Distribution& d : kDistributions) names.emplace_back(d.name);
  return names;
}

std::string_view distribution_description3d(std::string_view distribution) {
  for (const Distribution& d : kDistributions) {
    if (d.name == distribution) return d.description;
  }
  return "";
}

}  // namespace dtlab
