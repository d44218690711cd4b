// Static filter bounds (Meyer and Pion, "FPG: a code generator for fast and certified geometric
// predicates", RNC 2008; the static filter of Marot, Pellerin, Remacle 2019): when every point
// of the calls is known in advance, one bound per predicate, from the extent of the set, serves
// every call, and the filter costs one comparison. It is the semi-static bound (semistatic.hpp)
// with each maximum of the differences replaced by the extent of the set along that axis,
// M = fl(max - min): |fl(p - q)| <= M for any p, q of the set since rounding is monotone, and the
// bound is evaluated in the very same order, so it is never below the semi-static one. A call
// the static bound does not decide goes on to the semi-static bound, then the exact stages:
// the sign returned is the same, only cheaper.
#pragma once

#include <span>

#include "kernel/predicates/semistatic.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

struct StaticBounds3 {
  double orient3d = stage::kNoStaticBound;
  double insphere = stage::kNoStaticBound;
};

// The bounds for calls whose operands are all among `points` (finite, in the supported range:
// coordinate_range.hpp). None (infinite) for an empty set.
StaticBounds3 static_bounds3(std::span<const Vec3> points) noexcept;

}  // namespace dtlab
