// The filtered predicates' slow path (predicates.hpp): stage 2, then stage 3 when stage 2 cannot
// certify, then stage 4 (GMP) if stage 3 cannot either, each counted in this thread's
// PredicateStats: stages 3 and 4 both as "exact", stage 4 also as "gmp". Out of line so that the
// inline stage 1 stays small at every call site.
#include "kernel/predicates.hpp"

namespace dtlab::detail {

Sign orient2d_slow(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  StageCounts& counts = tls_predicate_stats[Predicate::Orient2d];
  if (const FilteredSign s = stage::orient2d_adaptive(a, b, c)) {
    ++counts.adaptive;
    return *s;
  }
  ++counts.exact;
  if (const FilteredSign s = stage::orient2d_expansion(a, b, c)) return *s;
  ++counts.gmp;
  return stage::orient2d_exact(a, b, c);
}

Sign incircle_slow(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d,
                   LiftCofactors* cofactors) noexcept {
  StageCounts& counts = tls_predicate_stats[Predicate::Incircle];
  if (const FilteredSign s = incircle_adaptive(a, b, c, d, cofactors)) {
    ++counts.adaptive;
    return *s;
  }
  ++counts.exact;
  if (const FilteredSign s = stage::incircle_expansion(a, b, c, d)) return *s;
  ++counts.gmp;
  return stage::incircle_exact(a, b, c, d);
}

Sign orient3d_slow(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  StageCounts& counts = tls_predicate_stats[Predicate::Orient3d];
  if (const FilteredSign s = stage::orient3d_adaptive(a, b, c, d)) {
    ++counts.adaptive;
    return *s;
  }
  ++counts.exact;
  if (const FilteredSign s = stage::orient3d_expansion(a, b, c, d)) return *s;
  ++counts.gmp;
  return stage::orient3d_exact(a, b, c, d);
}

Sign insphere_slow(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                   LiftCofactors* cofactors) noexcept {
  StageCounts& counts = tls_predicate_stats[Predicate::Insphere];
  if (const FilteredSign s = insphere_adaptive(a, b, c, d, e, cofactors)) {
    ++counts.adaptive;
    return *s;
  }
  ++counts.exact;
  if (const FilteredSign s = stage::insphere_expansion(a, b, c, d, e)) return *s;
  ++counts.gmp;
  return stage::insphere_exact(a, b, c, d, e);
}

}  // namespace dtlab::detail
