// Floating-point expansion arithmetic: exact sums and products of doubles, each value held as an
// unevaluated sum of nonoverlapping doubles. Error-free transformations after Knuth (TAOCP vol. 2
// §4.2.2, two-sum) and Dekker 1971 (Veltkamp splitting, exact product); expansion sum with zero
// elimination and scaling after Priest 1991 and Shewchuk 1997 (DCG 18, §2.5-2.7, Theorems 13, 19).
//
// Everything assumes IEEE double arithmetic rounded to nearest-even with no fused multiply-add
// (the kernel is built with -ffp-contract=off) and no overflow or underflow, which the supported
// coordinate range guarantees (coordinate_range.hpp). Products use splitting rather than std::fma
// so that every machine computes the same components. Expansions live in fixed-capacity arrays
// on the stack; no operation allocates.
#pragma once

#include <cmath>

#include "kernel/sign.hpp"

namespace dtlab::expansion {

// a + b = x + y exactly, x = fl(a + b) (Knuth's two-sum; no precondition on magnitudes).
inline void two_sum(double a, double b, double& x, double& y) noexcept {
  x = a + b;
  const double b_virtual = x - a;
  const double a_virtual = x - b_virtual;
  y = (a - a_virtual) + (b - b_virtual);
}

// a + b = x + y exactly when |a| >= |b| or a == 0 (Dekker's fast two-sum).
inline void fast_two_sum(double a, double b, double& x, double& y) noexcept {
  x = a + b;
  y = b - (x - a);
}

// a - b = x + y exactly, x = fl(a - b).
inline void two_diff(double a, double b, double& x, double& y) noexcept {
  x = a - b;
  const double b_virtual = a - x;
  const double a_virtual = x + b_virtual;
  y = (a - a_virtual) + (b_virtual - b);
}

// a = hi + lo with hi and lo of at most 26 significant bits each (Veltkamp's splitting).
inline void split(double a, double& hi, double& lo) noexcept {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  const double c = kSplitter * a;
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

// a * b = x + y exactly, x = fl(a * b) (Dekker's product: the four partial products of the
// halves are exact, and subtracting them from x in decreasing order leaves the exact error).
inline void two_product(double a, double b, double& x, double& y) noexcept {
  x = a * b;
  double ahi, alo, bhi, blo;
  split(a, ahi, alo);
  split(b, bhi, blo);
  const double err1 = x - ahi * bhi;
  const double err2 = err1 - alo * bhi;
  const double err3 = err2 - ahi * blo;
  y = alo * blo - err3;
}

// Raw kernels on arrays of components (increasing magnitude, no zeros); each returns the number
// of components written to h, which must not alias the inputs.

// h = e + s*f, s = +1 or -1: merge e and f by magnitude, then sweep one carry Q upward with
// two-sums, emitting the nonzero errors (Shewchuk's Fast-Expansion-Sum with zero elimination;
// nonoverlapping output under round-to-nearest-even).
inline int sum_raw(const double* e, int ne, const double* f, int nf, double s, double* h) noexcept {
  int i = 0, j = 0, nh = 0;
  auto next = [&]() noexcept -> double {
    if (j >= nf || (i < ne && std::fabs(e[i]) < std::fabs(f[j]))) return e[i++];
    return s * f[j++];
  };
  const int total = ne + nf;
  if (total == 0) return 0;
  double q = next();
  if (total == 1) {
    h[0] = q;
    return 1;
  }
  double x, y;
  fast_two_sum(next(), q, x, y);
  q = x;
  if (y != 0.0) h[nh++] = y;
  for (int k = 2; k < total; ++k) {
    two_sum(q, next(), x, y);
    q = x;
    if (y != 0.0) h[nh++] = y;
  }
  if (q != 0.0) h[nh++] = q;
  return nh;
}

// h = b * e (Shewchuk's Scale-Expansion with zero elimination): each component's exact product
// is folded into the running carry with a two-sum and a fast two-sum.
inline int scale_raw(const double* e, int ne, double b, double* h) noexcept {
  if (ne == 0 || b == 0.0) return 0;
  int nh = 0;
  double q, y;
  two_product(e[0], b, q, y);
  if (y != 0.0) h[nh++] = y;
  for (int i = 1; i < ne; ++i) {
    double t_hi, t_lo, sum, sum_err;
    two_product(e[i], b, t_hi, t_lo);
    two_sum(q, t_lo, sum, sum_err);
    if (sum_err != 0.0) h[nh++] = sum_err;
    fast_two_sum(t_hi, sum, q, y);
    if (y != 0.0) h[nh++] = y;
  }
  if (q != 0.0) h[nh++] = q;
  return nh;
}

// e compressed in place (Shewchuk's Compress, §2.8): the same value in as few components as two
// sweeps of fast two-sums find, one from the largest component down and one back up; returns the
// new size. The result is nonoverlapping and its largest component approximates the value to
// within one ulp, so products of compressed expansions stay short.
inline int compress_raw(double* e, int n) noexcept {
  if (n == 0) return 0;
  // Downward sweep: each carry that leaves a nonzero error is parked at the top end; writes stay
  // above the component being read.
  int bottom = n - 1;
  double q = e[n - 1];
  for (int i = n - 2; i >= 0; --i) {
    double big, small;
    fast_two_sum(q, e[i], big, small);
    if (small != 0.0) {
      e[bottom--] = big;
      q = small;
    } else {
      q = big;
    }
  }
  e[bottom] = q;
  // Upward sweep over the parked components; writes stay below the component being read.
  int top = 0;
  q = e[bottom];
  for (int i = bottom + 1; i < n; ++i) {
    double big, small;
    fast_two_sum(e[i], q, big, small);
    if (small != 0.0) e[top++] = small;
    q = big;
  }
  e[top++] = q;
  return top;
}

// An expansion of at most N components, stored in increasing magnitude with zeros eliminated;
// the empty expansion is zero. The components are left uninitialised beyond `size`.
template <int N>
struct Expansion {
  static constexpr int kCapacity = N;
  int size = 0;
  double c[N];

  // For a nonoverlapping expansion the largest component carries the sign.
  Sign sign() const noexcept { return size == 0 ? Sign::Zero : sign_of(c[size - 1]); }
  double top() const noexcept { return size == 0 ? 0.0 : c[size - 1]; }
  // Sum of the components, smallest first: the value within a relative error of a few ulps.
  double estimate() const noexcept {
    double v = 0.0;
    for (int k = 0; k < size; ++k) v += c[k];
    return v;
  }
  // Sum of |component| below the largest, rounded: an upper bound on |value - top()| up to a
  // factor (1 + size * 2^-53).
  double rest_magnitude() const noexcept {
    double v = 0.0;
    for (int k = 0; k + 1 < size; ++k) v += std::fabs(c[k]);
    return v;
  }
};

inline Expansion<1> from_double(double a) noexcept {
  Expansion<1> r;
  if (a != 0.0) r.c[r.size++] = a;
  return r;
}

// The exact product a * b.
inline Expansion<2> product(double a, double b) noexcept {
  Expansion<2> r;
  double x, y;
  two_product(a, b, x, y);
  if (y != 0.0) r.c[r.size++] = y;
  if (x != 0.0) r.c[r.size++] = x;
  return r;
}

inline Expansion<2> square(double a) noexcept { return product(a, a); }

template <int A, int B>
Expansion<A + B> sum(const Expansion<A>& e, const Expansion<B>& f) noexcept {
  Expansion<A + B> h;
  h.size = sum_raw(e.c, e.size, f.c, f.size, 1.0, h.c);
  return h;
}

template <int A, int B>
Expansion<A + B> difference(const Expansion<A>& e, const Expansion<B>& f) noexcept {
  Expansion<A + B> h;
  h.size = sum_raw(e.c, e.size, f.c, f.size, -1.0, h.c);
  return h;
}

template <int A>
Expansion<2 * A> scale(const Expansion<A>& e, double b) noexcept {
  Expansion<2 * A> h;
  h.size = scale_raw(e.c, e.size, b, h.c);
  return h;
}

// The exact e * f: f scaled by each component of e, accumulated. Pass the shorter first.
template <int A, int B>
Expansion<2 * A * B> product(const Expansion<A>& e, const Expansion<B>& f) noexcept {
  Expansion<2 * A * B> acc;
  if (e.size == 0 || f.size == 0) return acc;
  acc.size = scale_raw(f.c, f.size, e.c[0], acc.c);
  double partial[2 * B];
  double merged[2 * A * B];
  for (int k = 1; k < e.size; ++k) {
    const int np = scale_raw(f.c, f.size, e.c[k], partial);
    const int nm = sum_raw(acc.c, acc.size, partial, np, 1.0, merged);
    for (int i = 0; i < nm; ++i) acc.c[i] = merged[i];
    acc.size = nm;
  }
  return acc;
}

// The exact a * b - c * d: the 2x2 minors of every determinant.
inline Expansion<4> cross_difference(double a, double b, double c, double d) noexcept {
  return difference(product(a, b), product(c, d));
}

}  // namespace dtlab::expansion
