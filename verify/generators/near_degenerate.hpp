// Adversarial inputs for the predicates: random, exactly degenerate, a few ulps off degenerate,
// extreme magnitudes and far translations, for tests, fuzzers and benchmarks alike.
//
// Reproducibility: every generator draws from a caller-owned std::mt19937_64 (seed it with
// kDefaultSeed or your own) and turns its raw 64-bit output into numbers with the helpers below,
// never with <random>'s distributions, whose output differs between standard libraries. The
// same seed gives the same points on every platform.
//
// Every coordinate produced here is in the supported range (coordinate_range.hpp): values that
// would leave it are clamped by clamp_to_range.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab::gen {

using Rng = std::mt19937_64;
inline constexpr std::uint64_t kDefaultSeed = 0x6b65726e656cULL;  // "kernel"

// --- numbers ---------------------------------------------------------------------------------

double unit(Rng& rng);                                 // uniform in [0, 1), 53 random bits
double uniform(Rng& rng, double lo, double hi);        // lo + (hi - lo) * unit(rng), rounded
std::int64_t integer(Rng& rng, std::int64_t lo, std::int64_t hi);  // uniform in [lo, hi]

// The nearest value to v in the supported range: 0 stays 0, a non-zero magnitude below 2^-142
// becomes +-2^-142, above 2^142 becomes +-2^142, NaN becomes 0 and +-inf +-2^142.
double clamp_to_range(double v);

// v moved by `steps` nextafter steps (towards +inf if positive), then clamped.
double nudge(double v, int steps);
// Each coordinate moved by its own number of steps, uniform in [-max_steps, max_steps].
Vec2 nudge(Rng& rng, const Vec2& p, int max_steps);
Vec3 nudge(Rng& rng, const Vec3& p, int max_steps);

// A double from 64 arbitrary bits (a fuzzer's input), deterministically mapped into the
// supported range: the bits are read as a double; NaN and infinities keep their sign and
// mantissa with exponent 0; a finite value whose binary exponent lies outside [-142, 141] keeps
// its sign and mantissa and has its exponent folded into that interval (modulo 284).
double coordinate_from_bits(std::uint64_t bits);

// --- point sets ------------------------------------------------------------------------------
// "Exact" sets below are exactly collinear / cocircular / coplanar / cospherical in doubles:
// they consist of integers below 2^32 in magnitude, so the sets stay exact under scaling by a
// power of two and under translation by an integer vector below 2^52 - 2^32.

std::vector<Vec2> uniform_box(Rng& rng, std::size_t n, const Vec2& lo, const Vec2& hi);
std::vector<Vec3> uniform_box(Rng& rng, std::size_t n, const Vec3& lo, const Vec3& hi);

// Points a + t d on a random integer line (|a| < 2^20, |d| <= 2^10, |t| <= 2^20).
std::vector<Vec2> exact_collinear2(Rng& rng, std::size_t n);
std::vector<Vec3> exact_collinear3(Rng& rng, std::size_t n);
// Points a + s u + t v on a random integer plane (|a| < 2^20, |u|, |v| <= 2^8, |s|, |t| <= 2^12).
std::vector<Vec3> exact_coplanar3(Rng& rng, std::size_t n);
// Distinct integer points of a circle of radius 1185665 = 5*13*17*29*37 (which has 972 integer
// points) around a random integer centre (|c| < 2^20); n <= 972.
std::vector<Vec2> exact_cocircular2(Rng& rng, std::size_t n);
// Distinct integer points of a sphere of radius 45 (which has 510 integer points) around a
// random integer centre (|c| < 2^20); n <= 510.
std::vector<Vec3> exact_cospherical3(Rng& rng, std::size_t n);

// Points on a line / circle / plane / sphere through or around random real points, rounded to
// doubles, then each coordinate nudged by up to max_steps ulps: a few ulps off degenerate.
std::vector<Vec2> near_collinear2(Rng& rng, std::size_t n, int max_steps);
std::vector<Vec2> near_cocircular2(Rng& rng, std::size_t n, int max_steps);
std::vector<Vec3> near_coplanar3(Rng& rng, std::size_t n, int max_steps);
std::vector<Vec3> near_cospherical3(Rng& rng, std::size_t n, int max_steps);

// --- transformations -------------------------------------------------------------------------

// Multiply by 2^exponent (exact while in range; clamped otherwise).
std::vector<Vec2> scaled(std::span<const Vec2> points, int exponent);
std::vector<Vec3> scaled(std::span<const Vec3> points, int exponent);
// Add an offset, rounding each sum to double (exact for integer sets and integer offsets).
std::vector<Vec2> translated(std::span<const Vec2> points, const Vec2& offset);
std::vector<Vec3> translated(std::span<const Vec3> points, const Vec3& offset);

// The scale exponents the tests use for "very large" and "very small" inputs: sets of integers
// below 2^32 scaled by these stay inside [2^-142, 2^142] (nonzero integers are >= 1).
inline constexpr int kLargeExponent = 142 - 32;  // magnitudes up to 2^142
inline constexpr int kSmallExponent = -142;      // magnitudes from 2^-142
// A far translation: 1e9 in every coordinate (an integer, so exact sets stay exact).
inline constexpr double kFarOffset = 1e9;

// --- named families, for property tests and fuzzers --------------------------------------------

// What a family's degenerate sets lie on: a line (plane in 3D) or a circle (sphere in 3D).
enum class Shape { Flat, Round };

enum class Family {
  Uniform,     // uniform in [-1, 1)^d
  Exact,       // exactly collinear/coplanar or cocircular/cospherical integers (see above)
  Near,        // the near_* sets with up to 3 ulps of noise
  SmallGrid,   // integers in [-3, 3]^d: full of collinear, cocircular and duplicate points
  ExactLarge,  // Exact scaled by 2^kLargeExponent
  ExactSmall,  // Exact scaled by 2^kSmallExponent
  NearLarge,   // Near scaled by 2^138 (magnitudes near 2^140, clamped at 2^142)
  NearSmall,   // Near scaled by 2^-120 (magnitudes near 2^-120, clamped at 2^-142)
  ExactFar,    // Exact translated by kFarOffset (still exact)
  NearFar,     // Near translated by kFarOffset (rounded)
  Bits,        // coordinate_from_bits of raw 64-bit draws: every binade of the range
};
inline constexpr int kFamilyCount = 11;
const char* to_string(Family f) noexcept;

// n points of family f (n <= 510 for Exact* with Shape::Round in 3D, 972 in 2D).
std::vector<Vec2> family_points2(Rng& rng, Family f, Shape s, std::size_t n);
std::vector<Vec3> family_points3(Rng& rng, Family f, Shape s, std::size_t n);

// --- Kettner et al.'s grid -------------------------------------------------------------------
// The orientation experiment of Kettner, Mehlhorn, Pion, Schirra and Yap, "Classroom examples
// of robustness problems in geometric computations" (CGTA 40(1), 2008), Fig. 2: the sign of
// orient2d(p, q, r) for p = (0.5 + i u, 0.5 + j u), 0 <= i, j < 256, u = 2^-53 (the ulp of 0.5),
// q = (12, 12), r = (24, 24). p = (0.5, 0.5) is exactly on the line qr; a plain double
// evaluation misclassifies many grid points.
struct KettnerGrid {
  static constexpr int kSize = 256;
  static constexpr double kUlp = 0x1p-53;
  Vec2 base{0.5, 0.5};
  Vec2 q{12.0, 12.0};
  Vec2 r{24.0, 24.0};
  Vec2 p(int i, int j) const { return {base.x + i * kUlp, base.y + j * kUlp}; }
};

// Its in-circle analogue: a grid of the same size and step centred on the corner (0.5, 0.5) of
// the square (0.5, 0.5), (23.5, 0.5), (23.5, 23.5), (0.5, 23.5), whose corners are exactly
// cocircular (centre (12, 12)): p = (0.5 + (i - 128) u, 0.5 + (j - 128) u), all exact doubles.
// The test is incircle(a, b, c, p) with a, b, c the other corners, counter-clockwise; the circle
// crosses the grid through p(128, 128) along its tangent direction (1, -1).
struct KettnerCircleGrid {
  static constexpr int kSize = 256;
  static constexpr double kUlp = 0x1p-53;
  Vec2 corner{0.5, 0.5};
  Vec2 a{23.5, 0.5};
  Vec2 b{23.5, 23.5};
  Vec2 c{0.5, 23.5};
  Vec2 p(int i, int j) const {
    return {corner.x + (i - kSize / 2) * kUlp, corner.y + (j - kSize / 2) * kUlp};
  }
};

}  // namespace dtlab::gen
