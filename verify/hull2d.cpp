#include "verify/hull2d.hpp"

#include <algorithm>

#include "kernel/predicates.hpp"

namespace dtlab {

Hull2 convex_hull_with_collinear(std::span<const Vec2> points, std::span<const std::uint32_t> ids) {
  std::vector<std::uint32_t> sorted(ids.begin(), ids.end());
  // Stable, so that among equal locations the first id in `ids` order stays.
  std::stable_sort(sorted.begin(), sorted.end(), [&](std::uint32_t a, std::uint32_t b) {
    return (points[a] <=> points[b]) < 0;
  });
  sorted.erase(std::unique(sorted.begin(), sorted.end(),
                           [&](std::uint32_t a, std::uint32_t b) { return points[a] == points[b]; }),
               sorted.end());

  Hull2 hull;
  const auto all_collinear = [&] {
    for (std::size_t i = 2; i < sorted.size(); ++i) {
      if (orient2d(points[sorted[0]], points[sorted[1]], points[sorted[i]]) != Sign::Zero) return false;
    }
    return true;
  };
  if (sorted.size() < 3 || all_collinear()) {
    hull.collinear = true;
    return hull;
  }

  // A chain pops its last point only on a strict clockwise turn, so collinear points stay.
  // Both chains are correct once the set is not collinear: the lower one runs from the
  // smallest to the largest point, the upper one back.
  const auto chain = [&](auto first, auto last) {
    std::vector<std::uint32_t> c;
    for (auto it = first; it != last; ++it) {
      while (c.size() >= 2 && orient2d(points[c[c.size() - 2]], points[c.back()], points[*it]) == Sign::Negative) {
        c.pop_back();
      }
      c.push_back(*it);
    }
    c.pop_back();  // the other chain starts there
    return c;
  };
  hull.cycle = chain(sorted.begin(), sorted.end());
  const std::vector<std::uint32_t> upper = chain(sorted.rbegin(), sorted.rend());
  hull.cycle.insert(hull.cycle.end(), upper.begin(), upper.end());
  return hull;
}

}  // namespace dtlab
