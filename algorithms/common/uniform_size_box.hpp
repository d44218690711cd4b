// The box that a uniform size covers, for ControlSpace2::uniform_size and
// ControlSpace3::uniform_size alike: the points' bounding box grown by 1 on every side, so that
// every point of the domain, and the empty mesh's bounding box around it, lies well inside.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

#include "kernel/error.hpp"

namespace dtlab {

// InputError for a size that is not positive and finite, or for no points.
template <class Vec>
std::pair<Vec, Vec> uniform_size_box(std::span<const Vec> points, double h) {
  if (!(h > 0.0) || !std::isfinite(h)) throw InputError("size: give a positive finite size H (the metric H^-2 I)");
  if (points.empty()) throw InputError("a uniform size needs a domain: no points");
  Vec lo = points.front(), hi = lo;
  const auto widen = [](Vec& l, Vec& u, const Vec& p) {
    l.x = std::min(l.x, p.x), u.x = std::max(u.x, p.x);
    l.y = std::min(l.y, p.y), u.y = std::max(u.y, p.y);
    if constexpr (requires { p.z; }) l.z = std::min(l.z, p.z), u.z = std::max(u.z, p.z);
  };
  for (const Vec& p : points) widen(lo, hi, p);
  Vec one = lo;
  one.x = one.y = 1.0;
  if constexpr (requires { one.z; }) one.z = 1.0;
  return {lo - one, hi + one};
}

}  // namespace dtlab
