#include "verify/generators/portable_random.hpp"

#include <cmath>

namespace dtlab::portable {

// x = m 2^e exactly (frexp), then the atanh series of m near 1.
double log(double x) {
  int e = 0;
  double m = std::frexp(x, &e);  // m in [0.5, 1)
  if (m < 0.70710678118654752) {
    m *= 2.0;
    --e;
  }
  const double s = (m - 1.0) / (m + 1.0);  // |s| <= 0.172
  const double s2 = s * s;
  double sum = 0.0;
  for (int k = 21; k >= 1; k -= 2) sum = sum * s2 + 1.0 / k;
  return 2.0 * s * sum + e * 0.69314718055994531;
}

// Quadrant by 4u, then Taylor series on [0, pi/4].
Vec2 unit_circle(double u) {
  constexpr double kHalfPi = 1.5707963267948966;
  const double t = 4.0 * u;
  const int quadrant = static_cast<int>(t) & 3;
  double r = t - std::floor(t);  // exact
  const bool complement = r > 0.5;
  if (complement) r = 1.0 - r;  // exact for r in (0.5, 1)
  const double a = r * kHalfPi;
  const double a2 = a * a;
  double sin_sum = 0.0, cos_sum = 0.0;
  double sin_term = a, cos_term = 1.0;
  for (int k = 1; k <= 11; ++k) {
    sin_sum += sin_term;
    cos_sum += cos_term;
    sin_term *= -a2 / ((2.0 * k) * (2.0 * k + 1.0));
    cos_term *= -a2 / ((2.0 * k - 1.0) * (2.0 * k));
  }
  double c = cos_sum, s = sin_sum;
  if (complement) std::swap(c, s);
  switch (quadrant) {
    case 0: return {c, s};
    case 1: return {-s, c};
    case 2: return {-c, -s};
    default: return {s, -c};
  }
}

Vec2 normal_pair(Rng& rng) {
  const double u1 = 1.0 - unit(rng);  // (0, 1]
  const double r = std::sqrt(-2.0 * log(u1));
  return r * unit_circle(unit(rng));
}

}  // namespace dtlab::portable
