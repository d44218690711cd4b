// The symbolic perturbation of incircle and insphere, as documented in perturbation.hpp: the
// lifted coordinate of each point gets eps^rank, rank 1 for the lexicographically largest point
// of the call (after Devillers and Teillaud, CGTA 2011), so that an exact zero is resolved by the
// first non-vanishing cofactor, an orientation of the other points, taken by decreasing rank.
#include <array>
#include <cstddef>

#include "kernel/predicates.hpp"

namespace dtlab::detail {
namespace {

// p < q in lexicographic order (x, then y, then z), evaluated without branches: on cospherical
// input the comparisons are coin flips that branches would mispredict.
inline bool lex_less(const Vec2& p, const Vec2& q) noexcept {
  return (p.x < q.x) | ((p.x == q.x) & (p.y < q.y));
}
inline bool lex_less(const Vec3& p, const Vec3& q) noexcept {
  return (p.x < q.x) | ((p.x == q.x) & ((p.y < q.y) | ((p.y == q.y) & (p.z < q.z))));
}

// Indices of the points, lexicographically largest first. Equal points (outside the scheme's
// precondition) keep their argument order.
template <class Point, std::size_t N>
std::array<int, N> by_decreasing_rank(const std::array<const Point*, N>& points) noexcept {
  std::array<int, N> order{};
  for (std::size_t i = 0; i < N; ++i) order[i] = static_cast<int>(i);
  for (std::size_t i = 1; i < N; ++i) {  // insertion sort: N is 4 or 5
    const int moving = order[i];
    std::size_t j = i;
    while (j > 0 && lex_less(*points[order[j - 1]], *points[moving])) {
      order[j] = order[j - 1];
      --j;
    }
    order[j] = moving;
  }
  return order;
}

// With every cofactor known, the first non-zero one by decreasing rank: that of the largest point
// among those with a non-zero cofactor (the earliest argument among equal points, as above).
template <class Point, std::size_t N>
Sign first_nonzero_by_rank(const std::array<const Point*, N>& points, const LiftCofactors& known) noexcept {
  int best = -1;
  for (std::size_t p = 0; p < N; ++p) {
    if (known.sign[p] == Sign::Zero) continue;
    if (best < 0 || lex_less(*points[static_cast<std::size_t>(best)], *points[p])) best = static_cast<int>(p);
  }
  return best < 0 ? Sign::Zero : known.sign[static_cast<std::size_t>(best)];
}

}  // namespace

Sign incircle_perturbation(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d,
                           const LiftCofactors* known) noexcept {
  ++tls_predicate_stats[Predicate::Incircle].perturbed;
  const std::array<const Vec2*, 4> points{&a, &b, &c, &d};
  if (known && known->known) return first_nonzero_by_rank(points, *known);
  for (const int p : by_decreasing_rank(points)) {
    Sign cofactor = Sign::Zero;
    switch (p) {
      case 0: cofactor = orient2d(b, c, d); break;
      case 1: cofactor = -orient2d(a, c, d); break;
      case 2: cofactor = orient2d(a, b, d); break;
      default: cofactor = -orient2d(a, b, c); break;
    }
    if (cofactor != Sign::Zero) return cofactor;
  }
  return Sign::Zero;
}

Sign insphere_perturbation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                           const LiftCofactors* known) noexcept {
  ++tls_predicate_stats[Predicate::Insphere].perturbed;
  const std::array<const Vec3*, 5> points{&a, &b, &c, &d, &e};
  if (known && known->known) return first_nonzero_by_rank(points, *known);
  for (const int p : by_decreasing_rank(points)) {
    Sign cofactor = Sign::Zero;
    switch (p) {
      case 0: cofactor = -orient3d(b, c, d, e); break;
      case 1: cofactor = orient3d(a, c, d, e); break;
      case 2: cofactor = -orient3d(a, b, d, e); break;
      case 3: cofactor = orient3d(a, b, c, e); break;
      default: cofactor = -orient3d(a, b, c, d); break;
    }
    if (cofactor != Sign::Zero) return cofactor;
  }
  return Sign::Zero;
}

Sign incircle_perturbed_slow(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept {
  LiftCofactors cofactors;
  const Sign s = incircle_slow(a, b, c, d, &cofactors);
  return s != Sign::Zero ? s : incircle_perturbation(a, b, c, d, &cofactors);
}

Sign insphere_perturbed_slow(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                             const Vec3& e) noexcept {
  LiftCofactors cofactors;
  const Sign s = insphere_slow(a, b, c, d, e, &cofactors);
  return s != Sign::Zero ? s : insphere_perturbation(a, b, c, d, e, &cofactors);
}

}  // namespace dtlab::detail
