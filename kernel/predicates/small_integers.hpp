// Stage 2's fast exact path: the determinants in 64- and 128-bit integers, for exact coordinate
// differences that are all small multiples of one power of two (integer grids and lattices,
// points of a sphere with integer coordinates, any of these scaled by 2^k). The arithmetic is
// exact because every intermediate value stays below 2^127 (bounds at each function); the sign
// then needs no error bound, Zero included, and the 3x3 (2x2) minors that insphere (incircle)
// computes on the way are the cofactors the symbolic perturbation asks for (perturbation.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

#include "kernel/sign.hpp"

namespace dtlab::small_integers {

__extension__ typedef __int128 Int128;  // a GCC/Clang extension, hence the keyword for -Wpedantic

template <class T>
constexpr Sign sign_of_integer(T v) noexcept {
  return static_cast<Sign>(int(v > 0) - int(v < 0));
}

// n[i] = r[i] / g for the power of two g = 2^(e - bits), 2^e the power of two just above
// max |r[i]|, when every quotient is an integer (then |n[i]| < 2^bits); false otherwise.
// bits <= 30 and r[i] zero or of magnitude in [2^-194, 2^143] (the supported range's
// differences), so that the scaling by 2^(bits - e) is exact and never underflows.
template <int N>
bool to_integers(const double (&r)[N], int bits, std::int64_t (&n)[N]) noexcept {
  double m = 0.0;
  for (const double v : r) m = std::max(m, std::fabs(v));
  if (m == 0.0) {
    std::fill(n, n + N, std::int64_t{0});
    return true;
  }
  // m = f 2^e, f in [1/2, 1): the biased exponent field of the normal double m is e + 1022.
  const int e = static_cast<int>((std::bit_cast<std::uint64_t>(m) >> 52) & 0x7ff) - 1022;
  const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(1023 + bits - e) << 52);
  for (int i = 0; i < N; ++i) {
    const double v = r[i] * scale;  // a power-of-two scaling: exact
    n[i] = static_cast<std::int64_t>(v);
    if (static_cast<double>(n[i]) != v) return false;
  }
  return true;
}

// The bits to_integers may allow for each predicate.
inline constexpr int kOrient2dBits = 30;  // 2x2 minor < 2^61
inline constexpr int kOrient3dBits = 30;  // minors < 2^61, det < 2^93
inline constexpr int kIncircleBits = 30;  // lifts and minors < 2^61, det < 2^124
inline constexpr int kInsphereBits = 24;  // |det| < 72 (2^24)^5 < 2^127

// Rows as in adaptive.cpp: orient2d (b - a, c - a), orient3d (b - a, c - a, d - a).
inline Sign orient2d(const std::int64_t (&r)[4]) noexcept { return sign_of_integer(r[0] * r[3] - r[1] * r[2]); }

inline Sign orient3d(const std::int64_t (&r)[9]) noexcept {
  const std::int64_t m12 = r[4] * r[8] - r[5] * r[7];
  const std::int64_t m02 = r[1] * r[8] - r[2] * r[7];
  const std::int64_t m01 = r[1] * r[5] - r[2] * r[4];
  return sign_of_integer((Int128{r[0]} * m12 - Int128{r[3]} * m02) + Int128{r[6]} * m01);
}

// incircle on rows (a - d, b - d, c - d). When it is zero and `cofactors` is given, it receives
// the signs of the lifted column's cofactors C_a, C_b, C_c, C_d.
inline Sign incircle(const std::int64_t (&r)[6], std::array<Sign, 5>* cofactors) noexcept {
  const std::int64_t ax = r[0], ay = r[1], bx = r[2], by = r[3], cx = r[4], cy = r[5];
  const std::int64_t mbc = bx * cy - by * cx, mac = ax * cy - ay * cx, mab = ax * by - ay * bx;
  const std::int64_t la = ax * ax + ay * ay, lb = bx * bx + by * by, lc = cx * cx + cy * cy;
  const Sign s = sign_of_integer((Int128{la} * mbc - Int128{lb} * mac) + Int128{lc} * mab);
  if (s == Sign::Zero && cofactors) {
    // C_a = orient2d(b, c, d) = det(b - d, c - d) and so on; C_d = -orient2d(a, b, c) is minus
    // their sum (expand det(b - a, c - a) in rows taken from d).
    *cofactors = {sign_of_integer(mbc), -sign_of_integer(mac), sign_of_integer(mab),
                  -sign_of_integer((Int128{mbc} - mac) + mab), Sign::Zero};
  }
  return s;
}

// insphere on rows (a - e, b - e, c - e, d - e); cofactors C_a .. C_e as for incircle.
inline Sign insphere(const std::int64_t (&r)[12], std::array<Sign, 5>* cofactors) noexcept {
  const std::int64_t ax = r[0], ay = r[1], az = r[2], bx = r[3], by = r[4], bz = r[5];
  const std::int64_t cx = r[6], cy = r[7], cz = r[8], dx = r[9], dy = r[10], dz = r[11];
  // 2x2 minors of the (y, z) columns, < 2^49.
  const std::int64_t ab = ay * bz - az * by, ac = ay * cz - az * cy, ad = ay * dz - az * dy;
  const std::int64_t bc = by * cz - bz * cy, bd = by * dz - bz * dy, cd = cy * dz - cz * dy;
  // 3x3 minors, < 6 (2^24)^3.
  const Int128 mbcd = (Int128{bx} * cd - Int128{cx} * bd) + Int128{dx} * bc;
  const Int128 macd = (Int128{ax} * cd - Int128{cx} * ad) + Int128{dx} * ac;
  const Int128 mabd = (Int128{ax} * bd - Int128{bx} * ad) + Int128{dx} * ab;
  const Int128 mabc = (Int128{ax} * bc - Int128{bx} * ac) + Int128{cx} * ab;
  // Lifts, < 3 (2^24)^2.
  const std::int64_t la = (ax * ax + ay * ay) + az * az, lb = (bx * bx + by * by) + bz * bz;
  const std::int64_t lc = (cx * cx + cy * cy) + cz * cz, ld = (dx * dx + dy * dy) + dz * dz;
  const Sign s = sign_of_integer(((la * mbcd - lb * macd) + lc * mabd) - ld * mabc);
  if (s == Sign::Zero && cofactors) {
    // C_a = -orient3d(b, c, d, e) = det(b - e, c - e, d - e) and so on; C_e = -orient3d(a, b, c, d)
    // is minus their sum.
    *cofactors = {sign_of_integer(mbcd), -sign_of_integer(macd), sign_of_integer(mabd),
                  -sign_of_integer(mabc), -sign_of_integer(((mbcd - macd) + mabd) - mabc)};
  }
  return s;
}

}  // namespace dtlab::small_integers
