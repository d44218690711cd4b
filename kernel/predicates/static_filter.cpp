#include "kernel/predicates/static_filter.hpp"

#include <algorithm>

namespace dtlab {

StaticBounds3 static_bounds3(std::span<const Vec3> points) noexcept {
  if (points.empty()) return {};
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points) {
    lo.x = std::min(lo.x, p.x), hi.x = std::max(hi.x, p.x);
    lo.y = std::min(lo.y, p.y), hi.y = std::max(hi.y, p.y);
    lo.z = std::min(lo.z, p.z), hi.z = std::max(hi.z, p.z);
  }
  const double mx = hi.x - lo.x, my = hi.y - lo.y, mz = hi.z - lo.z;
  const double m = std::max(std::max(mx, my), mz);
  const double m2 = m * m;
  StaticBounds3 out;
  out.orient3d = stage::semistatic_bound::kOrient3d * mx * my * mz;
  out.insphere = stage::semistatic_bound::kInsphere * m2 * m2 * m;
  return out;
}

}  // namespace dtlab
