// Named 2D point distributions with fixed seeds, for tests, fuzzers, benchmarks and the CLI.
//
// Reproducible everywhere: randomness is std::mt19937_64 (its output is fixed by the C++
// standard) turned into numbers by our own arithmetic (53-bit uniforms, Box-Muller with our own
// log/sin/cos series, modulo for integers, our own Fisher-Yates), never by <random>'s
// distributions or the C library's transcendental functions, whose results differ between
// implementations. Given the IEEE double arithmetic dtlab requires (no contraction), the same
// (distribution, n, seed) gives the same bits on every platform.
//
// Every coordinate is in the supported range (kernel/coordinate_range.hpp). Only "duplicates"
// repeats points on purpose; the random ones may repeat a point by chance (at 53 bits, rarely).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

// n points of the named distribution. Throws InputError for an unknown name, listing the known
// ones.
std::vector<Vec2> generate_points2d(std::string_view distribution, std::size_t n, std::uint64_t seed);

// The known names, in a fixed order:
//   uniform       unit square [0,1)^2
//   normal        standard normal in each coordinate
//   grid          integer lattice ceil(sqrt n) x ceil(sqrt n), first n in row order, shuffled:
//                 exactly cocircular 4-tuples everywhere
//   circle        random angles on the unit circle, each point as close as doubles allow (so
//                 NOT exactly cocircular)
//   exact_circle  integer points exactly on one circle x^2 + y^2 = R^2 (Gaussian integers), up to
//                 236196 points; beyond, further exact circles of radius R/2, R/4, ...
//   clustered     Gaussian clusters (n/1000 of them, at least 1, at most 1000) in the unit square
//   collinear     runs of about sqrt(n) exactly collinear integer points on random lines
//   duplicates    uniform, with 10% of the points (at least one for n >= 2) exact copies of others
//   scaled_small  uniform scaled by 1e-9
//   scaled_large  uniform scaled by 1e9
//   multiscale    uniform, each point scaled by 10^k, k uniform in -9..9
//   translated    uniform translated by (1e9, 1e9): coordinates carry about 23 bits of the square
std::vector<std::string> distribution_names2d();

// The one-line description above, or "" for an unknown name.
std::string_view distribution_description2d(std::string_view distribution);

}  // namespace dtlab
