// Stage 3 of the predicates: the exact sign with GMP integers (C API).
//
// Every double is an integer mantissa times a power of two (frexp), so scaling all the call's
// coordinates by 2^-e_min, e_min the smallest exponent among them, turns them into integers
// without changing any sign: each predicate is homogeneous in the coordinate differences, and the
// scale is positive. The determinants are then the same trees as semistatic.hpp, over Z.
// No state outside the call, so the stage is thread-safe.
#include <gmp.h>

#include <cmath>

#include "kernel/predicates.hpp"

namespace dtlab::stage {
namespace {

// An mpz_t owned for the duration of one call.
class Integer {
 public:
  Integer() noexcept { mpz_init(v_); }
  ~Integer() { mpz_clear(v_); }
  Integer(const Integer&) = delete;
  Integer& operator=(const Integer&) = delete;
  mpz_ptr get() noexcept { return v_; }

 private:
  mpz_t v_;
};

constexpr int kMantissaBits = 53;

// The exponent of the least significant bit an integer mantissa of v may carry.
int low_exponent(double v) noexcept {
  int e = 0;
  std::frexp(v, &e);
  return e - kMantissaBits;
}

// Writes the N coordinates as integers: out[i] = in[i] * 2^-e_min.
template <int N>
void to_integers(const double (&in)[N], Integer (&out)[N]) noexcept {
  int e_min = 0;
  bool any = false;
  for (double v : in) {
    if (v == 0.0) continue;
    const int e = low_exponent(v);
    e_min = any ? (e < e_min ? e : e_min) : e;
    any = true;
  }
  for (int i = 0; i < N; ++i) {
    if (in[i] == 0.0) continue;  // mpz_init already holds 0
    int e = 0;
    const double mantissa = std::ldexp(std::frexp(in[i], &e), kMantissaBits);  // exact integer
    mpz_set_d(out[i].get(), mantissa);
    mpz_mul_2exp(out[i].get(), out[i].get(), static_cast<mp_bitcnt_t>(e - kMantissaBits - e_min));
  }
}

// r = a * d - b * c.
void cross_difference(mpz_ptr r, mpz_srcptr a, mpz_srcptr b, mpz_srcptr c, mpz_srcptr d) noexcept {
  mpz_mul(r, a, d);
  mpz_submul(r, b, c);
}

// r = x0 * m12 - x1 * m02 + x2 * m01: a 3x3 determinant along its first column.
void first_column_expansion(mpz_ptr r, mpz_srcptr x0, mpz_srcptr x1, mpz_srcptr x2, mpz_srcptr m12,
                            mpz_srcptr m02, mpz_srcptr m01) noexcept {
  mpz_mul(r, x0, m12);
  mpz_submul(r, x1, m02);
  mpz_addmul(r, x2, m01);
}

// r = x^2 + y^2 (+ z^2).
void lift(mpz_ptr r, mpz_srcptr x, mpz_srcptr y, mpz_srcptr z = nullptr) noexcept {
  mpz_mul(r, x, x);
  mpz_addmul(r, y, y);
  if (z) mpz_addmul(r, z, z);
}

Sign sign_of_integer(mpz_srcptr v) noexcept { return static_cast<Sign>(mpz_sgn(v)); }

}  // namespace

Sign orient2d_exact(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  const double in[6] = {a.x, a.y, b.x, b.y, c.x, c.y};
  Integer z[6];
  to_integers(in, z);
  Integer d1x, d1y, d2x, d2y, det;
  mpz_sub(d1x.get(), z[2].get(), z[0].get());
  mpz_sub(d1y.get(), z[3].get(), z[1].get());
  mpz_sub(d2x.get(), z[4].get(), z[0].get());
  mpz_sub(d2y.get(), z[5].get(), z[1].get());
  cross_difference(det.get(), d1x.get(), d1y.get(), d2x.get(), d2y.get());
  return sign_of_integer(det.get());
}

Sign orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  const double in[12] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  Integer z[12];
  to_integers(in, z);
  Integer r[9];  // rows b - a, c - a, d - a
  for (int i = 0; i < 9; ++i) mpz_sub(r[i].get(), z[3 + i].get(), z[i % 3].get());
  Integer m12, m02, m01, det;
  cross_difference(m12.get(), r[4].get(), r[5].get(), r[7].get(), r[8].get());
  cross_difference(m02.get(), r[1].get(), r[2].get(), r[7].get(), r[8].get());
  cross_difference(m01.get(), r[1].get(), r[2].get(), r[4].get(), r[5].get());
  first_column_expansion(det.get(), r[0].get(), r[3].get(), r[6].get(), m12.get(), m02.get(),
                         m01.get());
  return sign_of_integer(det.get());
}

Sign incircle_exact(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept {
  const double in[8] = {a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y};
  Integer z[8];
  to_integers(in, z);
  Integer r[6];  // rows a - d, b - d, c - d
  for (int i = 0; i < 6; ++i) mpz_sub(r[i].get(), z[i].get(), z[6 + i % 2].get());
  Integer la, lb, lc, mbc, mac, mab, t, det;
  lift(la.get(), r[0].get(), r[1].get());
  lift(lb.get(), r[2].get(), r[3].get());
  lift(lc.get(), r[4].get(), r[5].get());
  cross_difference(mbc.get(), r[2].get(), r[3].get(), r[4].get(), r[5].get());
  cross_difference(mac.get(), r[0].get(), r[1].get(), r[4].get(), r[5].get());
  cross_difference(mab.get(), r[0].get(), r[1].get(), r[2].get(), r[3].get());
  mpz_mul(det.get(), la.get(), mbc.get());
  mpz_submul(det.get(), lb.get(), mac.get());
  mpz_addmul(det.get(), lc.get(), mab.get());
  return sign_of_integer(det.get());
}

Sign insphere_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) noexcept {
  const double in[15] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z, e.x, e.y, e.z};
  Integer z[15];
  to_integers(in, z);
  Integer r[12];  // rows a - e, b - e, c - e, d - e; r[3i + k] is coordinate k of row i
  for (int i = 0; i < 12; ++i) mpz_sub(r[i].get(), z[i].get(), z[12 + i % 3].get());
  auto y = [&](int row) { return r[3 * row + 1].get(); };
  auto zc = [&](int row) { return r[3 * row + 2].get(); };
  auto x = [&](int row) { return r[3 * row].get(); };
  // 2x2 minors of the (y, z) columns.
  Integer ab, ac, ad, bc, bd, cd;
  cross_difference(ab.get(), y(0), zc(0), y(1), zc(1));
  cross_difference(ac.get(), y(0), zc(0), y(2), zc(2));
  cross_difference(ad.get(), y(0), zc(0), y(3), zc(3));
  cross_difference(bc.get(), y(1), zc(1), y(2), zc(2));
  cross_difference(bd.get(), y(1), zc(1), y(3), zc(3));
  cross_difference(cd.get(), y(2), zc(2), y(3), zc(3));
  Integer mbcd, macd, mabd, mabc;
  first_column_expansion(mbcd.get(), x(1), x(2), x(3), cd.get(), bd.get(), bc.get());
  first_column_expansion(macd.get(), x(0), x(2), x(3), cd.get(), ad.get(), ac.get());
  first_column_expansion(mabd.get(), x(0), x(1), x(3), bd.get(), ad.get(), ab.get());
  first_column_expansion(mabc.get(), x(0), x(1), x(2), bc.get(), ac.get(), ab.get());
  Integer l, det;
  lift(l.get(), x(0), y(0), zc(0));
  mpz_mul(det.get(), l.get(), mbcd.get());
  lift(l.get(), x(1), y(1), zc(1));
  mpz_submul(det.get(), l.get(), macd.get());
  lift(l.get(), x(2), y(2), zc(2));
  mpz_addmul(det.get(), l.get(), mabd.get());
  lift(l.get(), x(3), y(3), zc(3));
  mpz_submul(det.get(), l.get(), mabc.get());
  return sign_of_integer(det.get());
}

}  // namespace dtlab::stage
