// Stage 2 of the predicates: the determinant evaluated from the coordinate differences in
// integers (small_integers.hpp) or floating-point expansions (expansion.hpp), or estimated in
// double-word arithmetic, certified against the estimate's own error. The exact evaluation of the rounded differences and its use
// follow Shewchuk 1997 (DCG 18, §4); the double-word estimate on exact differences is ours.
//
// Derivation. Let the predicate be D = P(d), P a homogeneous polynomial of degree k in the
// coordinate differences d (orient2d k = 2, orient3d 3, incircle 4, insphere 5), written as the
// evaluation tree of semistatic.hpp. Each difference is computed as d~ = fl(p - q) with exact tail
// t = d - d~ (two_diff), so d = d~ + t exactly, |t| <= u |d~|, u = 2^-53.
//  * If every tail is zero, d~ = d and the exact expansion of P(d~) is D: its sign is the exact
//    sign, Zero included. This is the common case on grids and for nearby coordinates (Sterbenz).
//    When moreover all differences are small multiples of one power of two (integer lattices,
//    scaled or not), D is evaluated in 64/128-bit integers instead (small_integers.hpp): exact,
//    and an order of magnitude cheaper than the expansions.
//  * Perm = P's tree evaluated on |d~| with products and additions only, the sum of the absolute
//    values of P's monomials at d~. Computed in doubles (at most 16 roundings of nonnegative
//    values, no underflow) Perm <= Perm_fp (1 + 2^-40). If Perm is zero, every monomial vanishes
//    at d~, hence at d (d = 0 iff d~ = 0): D = 0.
//
// Evaluating D exactly, as an expansion: its largest component `top` and the rest satisfy
// |D| >= |top| - sum|rest| (triangle inequality), with sum|rest| < |top| for a nonoverlapping
// expansion; the sum is computed in doubles and padded by (1 + 2^-39) (at most 1152 terms). If
// |top| (1 - 2^-50) > sum|rest| (1 + 2^-50), sign(D) = sign(top).
// Expansions are short when the differences have few significant bits (grids: every product is
// exact), but reach dozens of components for full 53-bit mantissas, where they cost microseconds.
// So, unless the differences are exact and all fit in 26 bits, D is first estimated in double-word
// arithmetic (hi + lo, Joldes, Muller and Popescu, ACM TOMS 2017: their AccurateDWPlusDW, relative
// error <= 3u^2, and products whose error, neglected lo*lo term included, is <= 8u^2 |x| |y|),
// with the exact differences as leaves: d~ itself when no tail is nonzero, else the double words
// (d~, t). By induction on the tree, a node whose |.|-tree value is V carries an error <= c u^2 V,
// c growing by at most 8 (products: plus the operands' c) per operation; no path has more than 12
// operations and c stays below 2^7 (56 for insphere with double-word leaves), and V at |d| is at
// most (1 + u)^5 times V at |d~|, so |D~ - D| <= eta Perm with eta = 2^-90 a wide margin. It
// also absorbs underflow in the lo parts (at most 2^-1074 per operation, a few hundred
// operations) provided Perm >= 2^-900; below that (only for tiny coordinates with long mantissas)
// the estimate is skipped. The estimate D~ = hi + lo is normalised (|lo| <= u |hi|), so the stage
// returns sign(hi) when |hi| (1 - 2^-50) > eta Perm_fp (1 + 2^-30): rounded differences cost
// nothing in certainty, only the double-word leaves' few extra operations. When that fails, exact
// differences fall back to the exact expansion (which decides, Zero included), rounded ones defer
// (std::nullopt) to stage 3 (exact_expansion.cpp): |D| <= 2^-89 Perm, in practice D = 0.
#include <cmath>

#include "kernel/predicates.hpp"
#include "kernel/predicates/expansion.hpp"
#include "kernel/predicates/small_integers.hpp"

namespace dtlab::stage {
namespace {

using expansion::cross_difference;
using expansion::difference;
using expansion::Expansion;
using expansion::fast_two_sum;
using expansion::product;
using expansion::scale;
using expansion::square;
using expansion::sum;
using expansion::two_product;
using expansion::two_sum;

constexpr double kEstimateError = 0x1p-90;  // eta: the double-word estimate's error / Perm

// Coordinate differences d~ = fl(p - q) and their tails t = (p - q) - d~, remembering whether any
// was rounded and whether all fit in 26 significant bits (then every product of two is exact and
// the expansions stay short). N differences, taken in order.
template <int N>
class Differences {
 public:
  double operator()(double p, double q) noexcept {
    double x, hi, lo;
    expansion::two_diff(p, q, x, tails_[count_++]);
    expansion::split(x, hi, lo);
    rounded_ = rounded_ || tails_[count_ - 1] != 0.0;
    short_ = short_ && lo == 0.0;
    return x;
  }
  bool rounded() const noexcept { return rounded_; }
  bool exact_and_short() const noexcept { return !rounded_ && short_; }
  double tail(int i) const noexcept { return tails_[i]; }

 private:
  double tails_[N];
  int count_ = 0;
  bool rounded_ = false;
  bool short_ = true;
};

// ---- the exact evaluation

// The sign of an exactly evaluated E = D, or nullopt if the expansion were not nonoverlapping.
template <int N>
FilteredSign exact_sign(const Expansion<N>& det) noexcept {
  if (det.size == 0) return Sign::Zero;
  const double top = std::fabs(det.top());
  const double rest = det.rest_magnitude() * (1.0 + 0x1p-39);
  if (top * (1.0 - 0x1p-50) > rest * (1.0 + 0x1p-50)) return sign_of(det.top());
  return std::nullopt;
}

// The 3x3 determinant |x0 ., x1 ., x2 .| expanded along its first column, from the exact 2x2
// minors m12, m02, m01 of the other two columns (rows 1-2, 0-2, 0-1).
Expansion<24> first_column_expansion(double x0, double x1, double x2, const Expansion<4>& m12,
                                     const Expansion<4>& m02, const Expansion<4>& m01) noexcept {
  return sum(difference(scale(m12, x0), scale(m02, x1)), scale(m01, x2));
}

FilteredSign orient2d_exact_differences(double d1x, double d1y, double d2x, double d2y) noexcept {
  return exact_sign(cross_difference(d1x, d2y, d1y, d2x));
}

FilteredSign orient3d_exact_differences(const double (&r)[9]) noexcept {
  return exact_sign(first_column_expansion(r[0], r[3], r[6], cross_difference(r[4], r[8], r[5], r[7]),
                                           cross_difference(r[1], r[8], r[2], r[7]),
                                           cross_difference(r[1], r[5], r[2], r[4])));
}

FilteredSign incircle_exact_differences(const double (&r)[6]) noexcept {
  const double ax = r[0], ay = r[1], bx = r[2], by = r[3], cx = r[4], cy = r[5];
  const Expansion<4> la = sum(square(ax), square(ay));
  const Expansion<4> lb = sum(square(bx), square(by));
  const Expansion<4> lc = sum(square(cx), square(cy));
  const Expansion<4> mbc = cross_difference(bx, cy, by, cx);
  const Expansion<4> mac = cross_difference(ax, cy, ay, cx);
  const Expansion<4> mab = cross_difference(ax, by, ay, bx);
  return exact_sign(sum(difference(product(la, mbc), product(lb, mac)), product(lc, mab)));
}

FilteredSign insphere_exact_differences(const double (&r)[12]) noexcept {
  const double ax = r[0], ay = r[1], az = r[2], bx = r[3], by = r[4], bz = r[5];
  const double cx = r[6], cy = r[7], cz = r[8], dx = r[9], dy = r[10], dz = r[11];
  // 2x2 minors of the (y, z) columns, shared by the four 3x3 minors.
  const Expansion<4> ab = cross_difference(ay, bz, az, by), ac = cross_difference(ay, cz, az, cy);
  const Expansion<4> ad = cross_difference(ay, dz, az, dy), bc = cross_difference(by, cz, bz, cy);
  const Expansion<4> bd = cross_difference(by, dz, bz, dy), cd = cross_difference(cy, dz, cz, dy);
  const Expansion<24> mbcd = first_column_expansion(bx, cx, dx, cd, bd, bc);
  const Expansion<24> macd = first_column_expansion(ax, cx, dx, cd, ad, ac);
  const Expansion<24> mabd = first_column_expansion(ax, bx, dx, bd, ad, ab);
  const Expansion<24> mabc = first_column_expansion(ax, bx, cx, bc, ac, ab);
  const Expansion<6> la = sum(sum(square(ax), square(ay)), square(az));
  const Expansion<6> lb = sum(sum(square(bx), square(by)), square(bz));
  const Expansion<6> lc = sum(sum(square(cx), square(cy)), square(cz));
  const Expansion<6> ld = sum(sum(square(dx), square(dy)), square(dz));
  return exact_sign(difference(
      sum(difference(product(la, mbcd), product(lb, macd)), product(lc, mabd)), product(ld, mabc)));
}

// ---- the double-word estimate

struct DoubleWord {
  double hi = 0.0, lo = 0.0;
};

DoubleWord exact_product(double a, double b) noexcept {
  DoubleWord r;
  two_product(a, b, r.hi, r.lo);
  return r;
}

// AccurateDWPlusDW (Joldes, Muller, Popescu 2017, Algorithm 6).
DoubleWord operator+(const DoubleWord& x, const DoubleWord& y) noexcept {
  double sh, sl, th, tl, vh, vl;
  two_sum(x.hi, y.hi, sh, sl);
  two_sum(x.lo, y.lo, th, tl);
  fast_two_sum(sh, sl + th, vh, vl);
  DoubleWord r;
  fast_two_sum(vh, vl + tl, r.hi, r.lo);
  return r;
}

DoubleWord operator-(const DoubleWord& x) noexcept { return {-x.hi, -x.lo}; }
DoubleWord operator-(const DoubleWord& x, const DoubleWord& y) noexcept { return x + -y; }

// Double-word times double word; x.lo * y.lo is dropped.
DoubleWord operator*(const DoubleWord& x, const DoubleWord& y) noexcept {
  double ch, cl;
  two_product(x.hi, y.hi, ch, cl);
  DoubleWord r;
  fast_two_sum(ch, cl + (x.hi * y.lo + x.lo * y.hi), r.hi, r.lo);
  return r;
}

DoubleWord operator*(const DoubleWord& x, double b) noexcept {
  double ch, cl;
  two_product(x.hi, b, ch, cl);
  DoubleWord r;
  fast_two_sum(ch, cl + x.lo * b, r.hi, r.lo);
  return r;
}

// The exact product of two leaves, or a node times a leaf. A leaf is a double (the difference
// was exact) or a DoubleWord (difference and tail).
DoubleWord times(double a, double b) noexcept { return exact_product(a, b); }
DoubleWord times(const DoubleWord& x, const DoubleWord& y) noexcept { return x * y; }
DoubleWord times(const DoubleWord& x, double b) noexcept { return x * b; }

template <class Leaf>
DoubleWord cross_estimate(const Leaf& a, const Leaf& b, const Leaf& c, const Leaf& d) noexcept {
  return times(a, b) - times(c, d);
}

// The estimates of D, the trees of semistatic.hpp on the leaves r (rows as in the stage below).
template <class Leaf>
DoubleWord orient2d_estimate(const Leaf (&r)[4]) noexcept {
  return cross_estimate(r[0], r[3], r[1], r[2]);
}

template <class Leaf>
DoubleWord orient3d_estimate(const Leaf (&r)[9]) noexcept {
  const DoubleWord m12 = cross_estimate(r[4], r[8], r[5], r[7]);
  const DoubleWord m02 = cross_estimate(r[1], r[8], r[2], r[7]);
  const DoubleWord m01 = cross_estimate(r[1], r[5], r[2], r[4]);
  return (times(m12, r[0]) - times(m02, r[3])) + times(m01, r[6]);
}

template <class Leaf>
DoubleWord incircle_estimate(const Leaf (&r)[6]) noexcept {
  const Leaf &ax = r[0], &ay = r[1], &bx = r[2], &by = r[3], &cx = r[4], &cy = r[5];
  const DoubleWord la = times(ax, ax) + times(ay, ay);
  const DoubleWord lb = times(bx, bx) + times(by, by);
  const DoubleWord lc = times(cx, cx) + times(cy, cy);
  return (la * cross_estimate(bx, cy, by, cx) - lb * cross_estimate(ax, cy, ay, cx)) +
         lc * cross_estimate(ax, by, ay, bx);
}

template <class Leaf>
DoubleWord insphere_estimate(const Leaf (&r)[12]) noexcept {
  const Leaf &ax = r[0], &ay = r[1], &az = r[2], &bx = r[3], &by = r[4], &bz = r[5];
  const Leaf &cx = r[6], &cy = r[7], &cz = r[8], &dx = r[9], &dy = r[10], &dz = r[11];
  const DoubleWord ab = cross_estimate(ay, bz, az, by), ac = cross_estimate(ay, cz, az, cy);
  const DoubleWord ad = cross_estimate(ay, dz, az, dy), bc = cross_estimate(by, cz, bz, cy);
  const DoubleWord bd = cross_estimate(by, dz, bz, dy), cd = cross_estimate(cy, dz, cz, dy);
  const DoubleWord mbcd = (times(cd, bx) - times(bd, cx)) + times(bc, dx);
  const DoubleWord macd = (times(cd, ax) - times(ad, cx)) + times(ac, dx);
  const DoubleWord mabd = (times(bd, ax) - times(ad, bx)) + times(ab, dx);
  const DoubleWord mabc = (times(bc, ax) - times(ac, bx)) + times(ab, cx);
  auto lift = [](const Leaf& x, const Leaf& y, const Leaf& z) noexcept {
    return (times(x, x) + times(y, y)) + times(z, z);
  };
  return ((lift(ax, ay, az) * mbcd - lift(bx, by, bz) * macd) + lift(cx, cy, cz) * mabd) -
         lift(dx, dy, dz) * mabc;
}

// Perm of each tree, on the rounded differences.
double orient2d_perm(const double (&r)[4]) noexcept { return std::fabs(r[0] * r[3]) + std::fabs(r[1] * r[2]); }

double orient3d_perm(const double (&r)[9]) noexcept {
  const double p12 = std::fabs(r[4] * r[8]) + std::fabs(r[5] * r[7]);
  const double p02 = std::fabs(r[1] * r[8]) + std::fabs(r[2] * r[7]);
  const double p01 = std::fabs(r[1] * r[5]) + std::fabs(r[2] * r[4]);
  return (std::fabs(r[0]) * p12 + std::fabs(r[3]) * p02) + std::fabs(r[6]) * p01;
}

double incircle_perm(const double (&r)[6]) noexcept {
  const double ax = r[0], ay = r[1], bx = r[2], by = r[3], cx = r[4], cy = r[5];
  const double pa = ax * ax + ay * ay, pb = bx * bx + by * by, pc = cx * cx + cy * cy;
  const double pbc = std::fabs(bx * cy) + std::fabs(by * cx);
  const double pac = std::fabs(ax * cy) + std::fabs(ay * cx);
  const double pab = std::fabs(ax * by) + std::fabs(ay * bx);
  return (pa * pbc + pb * pac) + pc * pab;
}

double insphere_perm(const double (&r)[12]) noexcept {
  const double ax = r[0], ay = r[1], az = r[2], bx = r[3], by = r[4], bz = r[5];
  const double cx = r[6], cy = r[7], cz = r[8], dx = r[9], dy = r[10], dz = r[11];
  const double pab = std::fabs(ay * bz) + std::fabs(az * by);
  const double pac = std::fabs(ay * cz) + std::fabs(az * cy);
  const double pad = std::fabs(ay * dz) + std::fabs(az * dy);
  const double pbc = std::fabs(by * cz) + std::fabs(bz * cy);
  const double pbd = std::fabs(by * dz) + std::fabs(bz * dy);
  const double pcd = std::fabs(cy * dz) + std::fabs(cz * dy);
  const double pbcd = (std::fabs(bx) * pcd + std::fabs(cx) * pbd) + std::fabs(dx) * pbc;
  const double pacd = (std::fabs(ax) * pcd + std::fabs(cx) * pad) + std::fabs(dx) * pac;
  const double pabd = (std::fabs(ax) * pbd + std::fabs(bx) * pad) + std::fabs(dx) * pab;
  const double pabc = (std::fabs(ax) * pbc + std::fabs(bx) * pac) + std::fabs(cx) * pab;
  const double pa = (ax * ax + ay * ay) + az * az, pb = (bx * bx + by * by) + bz * bz;
  const double pc = (cx * cx + cy * cy) + cz * cz, pd = (dx * dx + dy * dy) + dz * dz;
  return ((pa * pbcd + pb * pacd) + pc * pabd) + pd * pabc;
}

// sign(D) from the estimate, or nullopt; see the derivation at the top.
FilteredSign certify_estimate(const DoubleWord& det, double perm) noexcept {
  if (perm == 0.0) return Sign::Zero;
  if (perm < 0x1p-900) return std::nullopt;  // underflow could exceed eta Perm
  if (std::fabs(det.hi) * (1.0 - 0x1p-50) > kEstimateError * perm * (1.0 + 0x1p-30)) return sign_of(det.hi);
  return std::nullopt;
}

// Stage 2 on the differences r with their tails. Exact differences: in integers when they are
// small multiples of one power of two (small_integers.hpp), else by the exact expansion straight
// away when it is cheap, else the estimate on r and then the exact expansion. Rounded ones: the
// estimate on the double words (r, tail), deferring to stage 3 when it cannot certify.
template <int N, class Integer, class Exact, class Estimate>
FilteredSign decide(const Differences<N>& diff, const double (&r)[N], double (*perm)(const double (&)[N]),
                    int bits, Integer integer, Exact exact, Estimate estimate) noexcept {
  if (!diff.rounded()) {
    std::int64_t n[N];
    if (small_integers::to_integers(r, bits, n)) return integer(n);
    if (diff.exact_and_short()) return exact();
    if (const FilteredSign s = certify_estimate(estimate(r), perm(r))) return s;
    return exact();
  }
  DoubleWord words[N];
  for (int i = 0; i < N; ++i) words[i] = {r[i], diff.tail(i)};
  return certify_estimate(estimate(words), perm(r));
}

}  // namespace

FilteredSign orient2d_adaptive(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  // Three points on a line x or y = const: a column of differences is zero, D = 0 exactly (as
  // orient3d below; the projections of axis-aligned faces are full of them).
  if ((a.x == b.x && a.x == c.x) || (a.y == b.y && a.y == c.y)) return Sign::Zero;
  Differences<4> diff;
  const double r[4] = {diff(b.x, a.x), diff(b.y, a.y), diff(c.x, a.x), diff(c.y, a.y)};
  return decide(
      diff, r, orient2d_perm, small_integers::kOrient2dBits,
      [](const std::int64_t (&n)[4]) noexcept { return small_integers::orient2d(n); },
      [&]() noexcept { return orient2d_exact_differences(r[0], r[1], r[2], r[3]); },
      [](const auto& leaves) noexcept { return orient2d_estimate(leaves); });
}

FilteredSign orient3d_adaptive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  // One coordinate equal in all four points (a plane x, y or z = const: every flat face of an
  // axis-aligned part) makes a column of differences zero exactly: D = 0 with no arithmetic.
  if ((a.x == b.x && a.x == c.x && a.x == d.x) || (a.y == b.y && a.y == c.y && a.y == d.y) ||
      (a.z == b.z && a.z == c.z && a.z == d.z))
    return Sign::Zero;
  Differences<9> diff;
  const double r[9] = {diff(b.x, a.x), diff(b.y, a.y), diff(b.z, a.z),  // rows b - a,
                       diff(c.x, a.x), diff(c.y, a.y), diff(c.z, a.z),  // c - a,
                       diff(d.x, a.x), diff(d.y, a.y), diff(d.z, a.z)}; // d - a
  return decide(
      diff, r, orient3d_perm, small_integers::kOrient3dBits,
      [](const std::int64_t (&n)[9]) noexcept { return small_integers::orient3d(n); },
      [&]() noexcept { return orient3d_exact_differences(r); },
      [](const auto& leaves) noexcept { return orient3d_estimate(leaves); });
}

FilteredSign incircle_adaptive(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept {
  return detail::incircle_adaptive(a, b, c, d, nullptr);
}

FilteredSign insphere_adaptive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                               const Vec3& e) noexcept {
  return detail::insphere_adaptive(a, b, c, d, e, nullptr);
}

}  // namespace dtlab::stage

namespace dtlab::detail {

FilteredSign incircle_adaptive(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d,
                               LiftCofactors* cofactors) noexcept {
  using namespace stage;
  Differences<6> diff;
  const double r[6] = {diff(a.x, d.x), diff(a.y, d.y), diff(b.x, d.x),
                       diff(b.y, d.y), diff(c.x, d.x), diff(c.y, d.y)};
  return decide(
      diff, r, incircle_perm, small_integers::kIncircleBits,
      [&](const std::int64_t (&n)[6]) noexcept {
        const Sign s = small_integers::incircle(n, cofactors ? &cofactors->sign : nullptr);
        if (cofactors) cofactors->known = s == Sign::Zero;
        return s;
      },
      [&]() noexcept { return incircle_exact_differences(r); },
      [](const auto& leaves) noexcept { return incircle_estimate(leaves); });
}

FilteredSign insphere_adaptive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                               LiftCofactors* cofactors) noexcept {
  using namespace stage;
  Differences<12> diff;
  const double r[12] = {diff(a.x, e.x), diff(a.y, e.y), diff(a.z, e.z), diff(b.x, e.x),
                        diff(b.y, e.y), diff(b.z, e.z), diff(c.x, e.x), diff(c.y, e.y),
                        diff(c.z, e.z), diff(d.x, e.x), diff(d.y, e.y), diff(d.z, e.z)};
  return decide(
      diff, r, insphere_perm, small_integers::kInsphereBits,
      [&](const std::int64_t (&n)[12]) noexcept {
        const Sign s = small_integers::insphere(n, cofactors ? &cofactors->sign : nullptr);
        if (cofactors) cofactors->known = s == Sign::Zero;
        return s;
      },
      [&]() noexcept { return insphere_exact_differences(r); },
      [](const auto& leaves) noexcept { return insphere_estimate(leaves); });
}

}  // namespace dtlab::detail
