// Rational: an exact rational number, a small RAII value over GMP's mpq_t (C API only).
// Exact constructions (rounding.hpp) compute with it: every finite double converts exactly, and
// +, -, *, / never round. Always canonical (mpq_canonicalize after construction from parts),
// so == compares values and to_string prints "num/den" in lowest terms ("num" if integral).
#pragma once

#include <gmp.h>

#include <compare>
#include <cstdint>
#include <string>
#include <utility>

#include "kernel/sign.hpp"

namespace dtlab {

class Rational {
 public:
  Rational() noexcept { mpq_init(q_); }
  // Exact; throws InputError for NaN or infinity (they are not rationals).
  explicit Rational(double v);
  explicit Rational(std::int64_t v) noexcept;
  explicit Rational(int v) noexcept : Rational(static_cast<std::int64_t>(v)) {}
  // num / den, exact; throws InputError if den == 0.
  Rational(std::int64_t num, std::int64_t den);
  // The dyadic rational m * 2^e.
  static Rational dyadic(std::int64_t m, long e);

  Rational(const Rational& other) noexcept {
    mpq_init(q_);
    mpq_set(q_, other.q_);
  }
  // A moved-from Rational is zero, still valid.
  Rational(Rational&& other) noexcept {
    mpq_init(q_);
    mpq_swap(q_, other.q_);
  }
  Rational& operator=(const Rational& other) noexcept {
    if (this != &other) mpq_set(q_, other.q_);
    return *this;
  }
  Rational& operator=(Rational&& other) noexcept {
    mpq_swap(q_, other.q_);
    return *this;
  }
  ~Rational() { mpq_clear(q_); }

  Rational& operator+=(const Rational& o) noexcept {
    mpq_add(q_, q_, o.q_);
    return *this;
  }
  Rational& operator-=(const Rational& o) noexcept {
    mpq_sub(q_, q_, o.q_);
    return *this;
  }
  Rational& operator*=(const Rational& o) noexcept {
    mpq_mul(q_, q_, o.q_);
    return *this;
  }
  // Throws InputError on division by zero (GMP itself would trap).
  Rational& operator/=(const Rational& o);

  friend Rational operator+(Rational a, const Rational& b) noexcept { return a += b; }
  friend Rational operator-(Rational a, const Rational& b) noexcept { return a -= b; }
  friend Rational operator*(Rational a, const Rational& b) noexcept { return a *= b; }
  friend Rational operator/(Rational a, const Rational& b) { return a /= b; }
  friend Rational operator-(Rational a) noexcept {
    mpq_neg(a.q_, a.q_);
    return a;
  }

  friend bool operator==(const Rational& a, const Rational& b) noexcept {
    return mpq_equal(a.q_, b.q_) != 0;
  }
  friend std::strong_ordering operator<=>(const Rational& a, const Rational& b) noexcept {
    const int c = mpq_cmp(a.q_, b.q_);
    return c < 0 ? std::strong_ordering::less
                 : (c > 0 ? std::strong_ordering::greater : std::strong_ordering::equal);
  }

  Sign sign() const noexcept {
    const int s = mpq_sgn(q_);
    return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero);
  }
  bool is_zero() const noexcept { return mpq_sgn(q_) == 0; }
  Rational abs() const noexcept {
    Rational r(*this);
    mpq_abs(r.q_, r.q_);
    return r;
  }
  // "num/den" in lowest terms, or "num" when the denominator is 1; base 10.
  std::string to_string() const;

  // The underlying GMP value, for code that calls GMP or MPFR directly.
  mpq_srcptr get() const noexcept { return q_; }
  mpq_ptr get() noexcept { return q_; }

 private:
  mpq_t q_;
};

}  // namespace dtlab
