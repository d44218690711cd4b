// Stage 3 of the predicates: the exact sign in floating-point expansions, whatever the coordinates.
// Each coordinate difference is taken exactly as a two-component expansion (two-diff:
// p - q = hi + lo), and the determinant tree of semistatic.hpp is evaluated on these with exact
// expansion sums and products, compressing as it goes (Shewchuk 1997, DCG 18, §2.5-2.8; his
// exact evaluation of §4, here on the exact differences rather than the raw coordinates).
// Stage 2 hands over only what its estimate leaves within its error bound of zero, with rounded
// differences: in practice exact zeros, so this stage is rare, and GMP (stage 4) rarer still.
//
// The expansions live in fixed buffers on the stack. Their length is data dependent; an
// operation whose result might not fit sets a flag instead, and the stage then defers
// (std::nullopt). On the supported coordinate range, compressed values stay a few tens of
// components long at most, far below the capacity (the tests check that it never defers).
#include "kernel/predicates.hpp"
#include "kernel/predicates/expansion.hpp"

namespace dtlab::stage {
namespace {

using expansion::Expansion;

constexpr int kCapacity = 256;
using Value = Expansion<kCapacity>;
using Leaf = Expansion<2>;

// Exact sums and compressed exact products that flag instead of overflowing.
class Evaluator {
 public:
  bool overflowed() const noexcept { return overflow_; }

  // p - q exactly.
  static Leaf difference(double p, double q) noexcept {
    Leaf d;
    double hi, lo;
    expansion::two_diff(p, q, hi, lo);
    if (lo != 0.0) d.c[d.size++] = lo;
    if (hi != 0.0) d.c[d.size++] = hi;
    return d;
  }

  // e + sign * f.
  template <int A, int B>
  Value sum(const Expansion<A>& e, const Expansion<B>& f, double sign = 1.0) noexcept {
    Value h;
    if (e.size + f.size > kCapacity) {
      overflow_ = true;
      return h;
    }
    h.size = expansion::sum_raw(e.c, e.size, f.c, f.size, sign, h.c);
    return h;
  }

  // e * f, compressed.
  template <int A, int B>
  Value product(const Expansion<A>& e, const Expansion<B>& f) noexcept {
    Value h;
    if (e.size <= f.size) {
      h.size = product_raw(e.c, e.size, f.c, f.size, h.c);
    } else {
      h.size = product_raw(f.c, f.size, e.c, e.size, h.c);
    }
    return h;
  }

  // a * d - b * c, compressed. (Results are compressed in place and returned by name: a
  // Value is 2 KiB, and only its first `size` components are ever copied.)
  Value cross(const Leaf& a, const Leaf& b, const Leaf& c, const Leaf& d) noexcept {
    Value v = sum(product(a, d), product(b, c), -1.0);
    v.size = expansion::compress_raw(v.c, v.size);
    return v;
  }

  // x0 * m12 - x1 * m02 + x2 * m01: a 3x3 determinant along its first column, compressed.
  Value first_column(const Leaf& x0, const Leaf& x1, const Leaf& x2, const Value& m12,
                     const Value& m02, const Value& m01) noexcept {
    Value v = sum(sum(product(x0, m12), product(x1, m02), -1.0), product(x2, m01));
    v.size = expansion::compress_raw(v.c, v.size);
    return v;
  }

  // x^2 + y^2, compressed.
  Value lift(const Leaf& x, const Leaf& y) noexcept {
    Value v = sum(product(x, x), product(y, y));
    v.size = expansion::compress_raw(v.c, v.size);
    return v;
  }
  // x^2 + y^2 + z^2, compressed.
  Value lift(const Leaf& x, const Leaf& y, const Leaf& z) noexcept {
    Value v = sum(sum(product(x, x), product(y, y)), product(z, z));
    v.size = expansion::compress_raw(v.c, v.size);
    return v;
  }

  // The sign of an exact value, or nullopt if an operation on the way overflowed.
  FilteredSign sign(const Value& v) const noexcept {
    if (overflow_) return std::nullopt;
    return v.sign();
  }

 private:
  // h = e * f, compressed: f scaled by each component of e (the shorter), each partial product
  // merged into the accumulator, which is compressed whenever the next merge might not fit.
  int product_raw(const double* e, int ne, const double* f, int nf, double* h) noexcept {
    if (ne == 0 || nf == 0) return 0;
    if (2 * nf > kCapacity) {
      overflow_ = true;
      return 0;
    }
    int nh = expansion::scale_raw(f, nf, e[0], h);
    double partial[kCapacity], merged[kCapacity];
    for (int k = 1; k < ne; ++k) {
      const int np = expansion::scale_raw(f, nf, e[k], partial);
      if (nh + np > kCapacity) nh = expansion::compress_raw(h, nh);
      if (nh + np > kCapacity) {
        overflow_ = true;
        return 0;
      }
      const int nm = expansion::sum_raw(h, nh, partial, np, 1.0, merged);
      for (int i = 0; i < nm; ++i) h[i] = merged[i];
      nh = nm;
    }
    return expansion::compress_raw(h, nh);
  }

  bool overflow_ = false;
};

}  // namespace

FilteredSign orient2d_expansion(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  Evaluator ev;
  const Leaf d1x = ev.difference(b.x, a.x), d1y = ev.difference(b.y, a.y);
  const Leaf d2x = ev.difference(c.x, a.x), d2y = ev.difference(c.y, a.y);
  return ev.sign(ev.sum(ev.product(d1x, d2y), ev.product(d1y, d2x), -1.0));
}

FilteredSign orient3d_expansion(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  Evaluator ev;
  // Rows b - a, c - a, d - a.
  const Leaf r0x = ev.difference(b.x, a.x), r0y = ev.difference(b.y, a.y), r0z = ev.difference(b.z, a.z);
  const Leaf r1x = ev.difference(c.x, a.x), r1y = ev.difference(c.y, a.y), r1z = ev.difference(c.z, a.z);
  const Leaf r2x = ev.difference(d.x, a.x), r2y = ev.difference(d.y, a.y), r2z = ev.difference(d.z, a.z);
  const Value m12 = ev.cross(r1y, r1z, r2y, r2z);
  const Value m02 = ev.cross(r0y, r0z, r2y, r2z);
  const Value m01 = ev.cross(r0y, r0z, r1y, r1z);
  return ev.sign(ev.first_column(r0x, r1x, r2x, m12, m02, m01));
}

FilteredSign incircle_expansion(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept {
  Evaluator ev;
  // Rows a - d, b - d, c - d.
  const Leaf ax = ev.difference(a.x, d.x), ay = ev.difference(a.y, d.y);
  const Leaf bx = ev.difference(b.x, d.x), by = ev.difference(b.y, d.y);
  const Leaf cx = ev.difference(c.x, d.x), cy = ev.difference(c.y, d.y);
  const Value mbc = ev.cross(bx, by, cx, cy), mac = ev.cross(ax, ay, cx, cy), mab = ev.cross(ax, ay, bx, by);
  const Value la = ev.lift(ax, ay), lb = ev.lift(bx, by), lc = ev.lift(cx, cy);
  return ev.sign(ev.sum(ev.sum(ev.product(la, mbc), ev.product(lb, mac), -1.0), ev.product(lc, mab)));
}

FilteredSign insphere_expansion(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                                const Vec3& e) noexcept {
  Evaluator ev;
  // Rows a - e, b - e, c - e, d - e.
  const Leaf ax = ev.difference(a.x, e.x), ay = ev.difference(a.y, e.y), az = ev.difference(a.z, e.z);
  const Leaf bx = ev.difference(b.x, e.x), by = ev.difference(b.y, e.y), bz = ev.difference(b.z, e.z);
  const Leaf cx = ev.difference(c.x, e.x), cy = ev.difference(c.y, e.y), cz = ev.difference(c.z, e.z);
  const Leaf dx = ev.difference(d.x, e.x), dy = ev.difference(d.y, e.y), dz = ev.difference(d.z, e.z);
  // 2x2 minors of the (y, z) columns, shared by the four 3x3 minors.
  const Value ab = ev.cross(ay, az, by, bz), ac = ev.cross(ay, az, cy, cz), ad = ev.cross(ay, az, dy, dz);
  const Value bc = ev.cross(by, bz, cy, cz), bd = ev.cross(by, bz, dy, dz), cd = ev.cross(cy, cz, dy, dz);
  const Value mbcd = ev.first_column(bx, cx, dx, cd, bd, bc);
  const Value macd = ev.first_column(ax, cx, dx, cd, ad, ac);
  const Value mabd = ev.first_column(ax, bx, dx, bd, ad, ab);
  const Value mabc = ev.first_column(ax, bx, cx, bc, ac, ab);
  const Value la = ev.lift(ax, ay, az), lb = ev.lift(bx, by, bz);
  const Value lc = ev.lift(cx, cy, cz), ld = ev.lift(dx, dy, dz);
  const Value first = ev.sum(ev.product(la, mbcd), ev.product(lb, macd), -1.0);
  const Value second = ev.sum(ev.product(lc, mabd), ev.product(ld, mabc), -1.0);
  return ev.sign(ev.sum(first, second));
}

}  // namespace dtlab::stage
