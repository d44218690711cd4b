// Named 3D point distributions with fixed seeds, for tests, fuzzers, benchmarks and the CLI.
//
// Reproducible everywhere, by the rules of points2d.hpp: randomness is std::mt19937_64 (its
// output is fixed by the C++ standard) turned into numbers by our own arithmetic (53-bit
// uniforms, Box-Muller with our own log/sin/cos series, modulo for integers, our own
// Fisher-Yates), never by <random>'s distributions or the C library's transcendental functions;
// only +, -, *, / and sqrt, which IEEE rounds correctly. Given the IEEE double arithmetic dtlab
// requires (no contraction), the same (distribution, n, seed) gives the same bits on every
// platform.
//
// Every coordinate is in the supported range (kernel/coordinate_range.hpp). Only "duplicates"
// repeats points on purpose; the random ones may repeat a point by chance (rarely), the integer
// ones ("coplanar", "collinear") a little more often.
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
std::vector<Vec3> generate_points3d(std::string_view distribution, std::size_t n, std::uint64_t seed);

// The known names, in a fixed order:
//   uniform       unit cube [0,1)^3
//   normal        standard normal in each coordinate
//   grid          integer lattice k x k x k, k = ceil(cbrt n), first n in (x, y, z) order, shuffled:
//                 exactly cospherical 5-tuples (and coplanar 4-tuples) everywhere
//   sphere        random points of the unit sphere, each coordinate rounded (NOT exactly
//                 cospherical)
//   exact_sphere  integer points exactly on x^2 + y^2 + z^2 = R^2, R the first of 9, 21, 45, 105,
//                 225, 585, 1155, 3465, 15015 with n points or more (a random subset); past the
//                 last one's, further exact spheres of radius R/2, R/4, ...
//   clustered     Gaussian clusters (n/1000 of them, at least 1, at most 1000) in the unit cube,
//                 sigma 0.05 / ceil(cbrt(clusters))
//   coplanar      90% on four random integer planes (exactly coplanar), 10% random integer points
//   collinear     90% in runs of about sqrt(n) exactly collinear integer points on random lines,
//                 10% random integer points off them
//   duplicates    uniform, with 10% of the points (at least one for n >= 2) exact copies of others
//   scaled_small  uniform scaled by 1e-9
//   scaled_large  uniform scaled by 1e9
//   multiscale    uniform, each point scaled by 10^k, k uniform in -9..9
//   translated    uniform translated by (1e9, 1e9, 1e9): coordinates carry about 23 bits of the cube
std::vector<std::string> distribution_names3d();

// The one-line description above, or "" for an unknown name.
std::string_view distribution_description3d(std::string_view distribution);

}  // namespace dtlab
