// Stage 2 of the predicates: the determinant of the rounded coordinate differences, evaluated
// exactly with floating-point expansions (expansion.hpp), certified against the rounding of the
// differences themselves. The idea of an exact evaluation on the computed differences plus a
// bound for their rounding follows Shewchuk 1997 (DCG 18, §4, the "B" estimate and its error).
//
// Derivation. Let the predicate be D = P(d), P a homogeneous polynomial of degree k in the
// coordinate differences d (orient2d k = 2, orient3d 3, incircle 4, insphere 5), written as the
// evaluation tree of semistatic.hpp. Each difference is computed as d~ = fl(p - q) with exact tail
// t = d - d~ (two_diff). E = P(d~) is evaluated exactly as an expansion.
//  * If every tail is zero, d~ = d and E = D: sign(E) is the exact sign, Zero included. This is
//    the common case on grids and for nearby coordinates (Sterbenz).
//  * Otherwise d = d~ (1 + delta) with |delta| <= u = 2^-53 (round to nearest, and no underflow
//    on the supported range). Expanding the tree without cancelling gives D and E as sums of the
//    same signed monomials, each of degree k, evaluated at d and at d~ respectively; a monomial
//    changes by a factor prod(1 + delta_i) of k factors, so
//        |D - E| <= ((1 + u)^k - 1) * Perm,   Perm = sum of |monomial(d~)|,
//    and Perm is the same tree evaluated on |d~| with products and additions only. Computed in
//    doubles (at most 16 roundings of nonnegative values, no underflow) Perm <= Perm_fp (1 + 2^-40),
//    and (1 + u)^k - 1 <= k u (1 + 2^-48) for k <= 5, so err = k u Perm_fp (1 + 2^-30) bounds
//    |D - E| even after the two roundings of that product.
//    E's largest component `top` and the rest satisfy |E| >= |top| - sum|rest| (triangle
//    inequality, whatever the expansion's shape), with sum|rest| < |top| for a nonoverlapping
//    expansion; the sum is computed in doubles and padded by (1 + 2^-39) (at most 1152 terms).
//    If |top| (1 - 2^-50) > (sum|rest| + err)(1 + 2^-50) then |E| > |D - E|, so sign(D) =
//    sign(E) = sign(top). Otherwise the stage defers (std::nullopt) to the exact stage.
//  * If Perm is zero, every monomial vanishes at d~, hence at d (d = 0 iff d~ = 0): D = 0.
// The same test guards the exact case (err = 0), so the stage never relies on the expansion
// being nonoverlapping for its correctness, only for its success.
#include <cmath>

#include "kernel/predicates.hpp"
#include "kernel/predicates/expansion.hpp"

namespace dtlab::stage {
namespace {

using expansion::cross_difference;
using expansion::difference;
using expansion::Expansion;
using expansion::product;
using expansion::scale;
using expansion::square;
using expansion::sum;

constexpr double kUnitRoundoff = 0x1p-53;

// Coordinate differences d~ = fl(p - q), remembering whether any of them was rounded.
class Differences {
 public:
  double operator()(double p, double q) noexcept {
    double x, tail;
    expansion::two_diff(p, q, x, tail);
    rounded_ = rounded_ || tail != 0.0;
    return x;
  }
  bool rounded() const noexcept { return rounded_; }

 private:
  bool rounded_ = false;
};

// The sign of D from E = det; `permanent` computes Perm_fp, only needed when rounded.
template <int N, class Permanent>
FilteredSign certify(const Expansion<N>& det, bool rounded, int degree, Permanent permanent) noexcept {
  if (det.size == 0 && !rounded) return Sign::Zero;
  double err = 0.0;
  if (rounded) {
    const double perm = permanent();
    if (perm == 0.0) return Sign::Zero;
    err = degree * kUnitRoundoff * perm * (1.0 + 0x1p-30);
  }
  const double top = std::fabs(det.top());
  const double rest = det.rest_magnitude() * (1.0 + 0x1p-39);
  if (top * (1.0 - 0x1p-50) > (rest + err) * (1.0 + 0x1p-50)) return sign_of(det.top());
  return std::nullopt;
}

// The 3x3 determinant |x0 ., x1 ., x2 .| expanded along its first column, from the exact 2x2
// minors m12, m02, m01 of the other two columns (rows 1-2, 0-2, 0-1).
inline Expansion<24> first_column_expansion(double x0, double x1, double x2, const Expansion<4>& m12,
                                            const Expansion<4>& m02, const Expansion<4>& m01) noexcept {
  return sum(difference(scale(m12, x0), scale(m02, x1)), scale(m01, x2));
}

}  // namespace

FilteredSign orient2d_adaptive(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  Differences diff;
  const double d1x = diff(b.x, a.x), d1y = diff(b.y, a.y);
  const double d2x = diff(c.x, a.x), d2y = diff(c.y, a.y);
  const Expansion<4> det = cross_difference(d1x, d2y, d1y, d2x);
  return certify(det, diff.rounded(), 2, [&]() noexcept {
    return std::fabs(d1x * d2y) + std::fabs(d1y * d2x);
  });
}

FilteredSign orient3d_adaptive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  Differences diff;
  const double r0x = diff(b.x, a.x), r0y = diff(b.y, a.y), r0z = diff(b.z, a.z);
  const double r1x = diff(c.x, a.x), r1y = diff(c.y, a.y), r1z = diff(c.z, a.z);
  const double r2x = diff(d.x, a.x), r2y = diff(d.y, a.y), r2z = diff(d.z, a.z);
  const Expansion<24> det = first_column_expansion(
      r0x, r1x, r2x, cross_difference(r1y, r2z, r1z, r2y), cross_difference(r0y, r2z, r0z, r2y),
      cross_difference(r0y, r1z, r0z, r1y));
  return certify(det, diff.rounded(), 3, [&]() noexcept {
    const double p12 = std::fabs(r1y * r2z) + std::fabs(r1z * r2y);
    const double p02 = std::fabs(r0y * r2z) + std::fabs(r0z * r2y);
    const double p01 = std::fabs(r0y * r1z) + std::fabs(r0z * r1y);
    return (std::fabs(r0x) * p12 + std::fabs(r1x) * p02) + std::fabs(r2x) * p01;
  });
}

FilteredSign incircle_adaptive(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept {
  Differences diff;
  const double ax = diff(a.x, d.x), ay = diff(a.y, d.y);
  const double bx = diff(b.x, d.x), by = diff(b.y, d.y);
  const double cx = diff(c.x, d.x), cy = diff(c.y, d.y);
  const Expansion<4> la = sum(square(ax), square(ay));
  const Expansion<4> lb = sum(square(bx), square(by));
  const Expansion<4> lc = sum(square(cx), square(cy));
  const Expansion<4> mbc = cross_difference(bx, cy, by, cx);
  const Expansion<4> mac = cross_difference(ax, cy, ay, cx);
  const Expansion<4> mab = cross_difference(ax, by, ay, bx);
  const Expansion<96> det =
      sum(difference(product(la, mbc), product(lb, mac)), product(lc, mab));
  return certify(det, diff.rounded(), 4, [&]() noexcept {
    const double pa = ax * ax + ay * ay, pb = bx * bx + by * by, pc = cx * cx + cy * cy;
    const double pbc = std::fabs(bx * cy) + std::fabs(by * cx);
    const double pac = std::fabs(ax * cy) + std::fabs(ay * cx);
    const double pab = std::fabs(ax * by) + std::fabs(ay * bx);
    return (pa * pbc + pb * pac) + pc * pab;
  });
}

FilteredSign insphere_adaptive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                               const Vec3& e) noexcept {
  Differences diff;
  const double ax = diff(a.x, e.x), ay = diff(a.y, e.y), az = diff(a.z, e.z);
  const double bx = diff(b.x, e.x), by = diff(b.y, e.y), bz = diff(b.z, e.z);
  const double cx = diff(c.x, e.x), cy = diff(c.y, e.y), cz = diff(c.z, e.z);
  const double dx = diff(d.x, e.x), dy = diff(d.y, e.y), dz = diff(d.z, e.z);
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
  const Expansion<1152> det = difference(
      sum(difference(product(la, mbcd), product(lb, macd)), product(lc, mabd)), product(ld, mabc));
  return certify(det, diff.rounded(), 5, [&]() noexcept {
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
  });
}

}  // namespace dtlab::stage
