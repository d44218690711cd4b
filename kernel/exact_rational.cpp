// Rational over GMP's mpq_t: the parts that can fail or allocate a string.
#include "kernel/exact_rational.hpp"

#include <cmath>

#include "kernel/error.hpp"

namespace dtlab {

// GMP's *_si functions take a long; dtlab targets LP64, where long holds every int64_t.
static_assert(sizeof(long) >= sizeof(std::int64_t), "Rational needs a 64-bit long");

Rational::Rational(double v) {
  mpq_init(q_);
  if (!std::isfinite(v)) {
    mpq_clear(q_);
    throw InputError(std::string("Rational: cannot represent ") + (std::isnan(v) ? "NaN" : "infinity"));
  }
  // mpq_set_d is exact: a finite double is a dyadic rational.
  mpq_set_d(q_, v);
}

Rational::Rational(std::int64_t v) noexcept {
  mpq_init(q_);
  mpq_set_si(q_, static_cast<long>(v), 1);
}

Rational::Rational(std::int64_t num, std::int64_t den) {
  if (den == 0) throw InputError("Rational: zero denominator");
  mpq_init(q_);
  mpz_set_si(mpq_numref(q_), static_cast<long>(num));
  mpz_set_si(mpq_denref(q_), static_cast<long>(den));
  mpq_canonicalize(q_);
}

Rational Rational::dyadic(std::int64_t m, long e) {
  Rational r(m);
  if (e >= 0) {
    mpq_mul_2exp(r.q_, r.q_, static_cast<mp_bitcnt_t>(e));
  } else {
    mpq_div_2exp(r.q_, r.q_, static_cast<mp_bitcnt_t>(-e));
  }
  return r;
}

Rational& Rational::operator/=(const Rational& o) {
  if (o.is_zero()) throw InputError("Rational: division by zero");
  mpq_div(q_, q_, o.q_);
  return *this;
}

std::string Rational::to_string() const {
  // mpq_get_str with a null buffer allocates with GMP's allocator; free it with GMP's free.
  void (*gmp_free)(void*, std::size_t) = nullptr;
  mp_get_memory_functions(nullptr, nullptr, &gmp_free);
  char* s = mpq_get_str(nullptr, 10, q_);
  std::string out(s);
  gmp_free(s, out.size() + 1);
  return out;
}

}  // namespace dtlab
