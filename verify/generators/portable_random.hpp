// Random numbers that are the same bits on every platform, for the point generators: a
// std::mt19937_64 (its output is fixed by the C++ standard) turned into numbers by our own
// arithmetic, never by <random>'s distributions or the C library's transcendental functions,
// whose results differ between implementations. Given IEEE doubles without contraction, the same
// seed gives the same numbers everywhere.
#pragma once

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab::portable {

using Rng = std::mt19937_64;

// Uniform in [0, 1): the top 53 bits of one draw.
inline double unit(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Uniform in [0, k) for k >= 1 (modulo bias below k / 2^64: irrelevant here, and portable).
inline std::uint64_t below(Rng& rng, std::uint64_t k) { return rng() % k; }

// Natural logarithm of x > 0 (series, see the .cpp).
double log(double x);

// (cos, sin) of 2 pi u for u in [0, 1).
Vec2 unit_circle(double u);

// A standard normal pair by Box-Muller.
Vec2 normal_pair(Rng& rng);

// Fisher-Yates with below().
template <class T>
void shuffle(std::vector<T>& v, Rng& rng) {
  for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[below(rng, i)]);
}

}  // namespace dtlab::portable
