#include "algorithms/delaunay2d/sweep_order.hpp"

#include <algorithm>
#include <cmath>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates/expansion.hpp"

namespace dtlab {

namespace {

// A point id with its squared distance to the centre rounded to a double.
struct RadialKey {
  double key;
  std::uint32_t id;
};

// Each of the four roundings in fl(fl(dx)^2 + fl(dy)^2) has relative error at most u = 2^-53 and
// both terms are non-negative, so |fl(d) - d| <= 4.01 u d. Two keys whose rounded difference
// exceeds twice that bound on their sum (rounding of the test itself included) are ordered by it.
constexpr double kRelativeError = 8.0 * 0x1p-53;

expansion::Expansion<16> exact_squared_distance(double x, double y, const Vec2& c) noexcept {
  expansion::Expansion<2> dx, dy;
  double hi, lo;
  expansion::two_diff(x, c.x, hi, lo);
  if (lo != 0.0) dx.c[dx.size++] = lo;
  if (hi != 0.0) dx.c[dx.size++] = hi;
  expansion::two_diff(y, c.y, hi, lo);
  if (lo != 0.0) dy.c[dy.size++] = lo;
  if (hi != 0.0) dy.c[dy.size++] = hi;
  return expansion::sum(expansion::product(dx, dx), expansion::product(dy, dy));
}

// The squared distance of p to c in k, and whether the double is exact (as on integer grids,
// where ties abound and then cost no expansion).
bool rounded_exactly(const Vec2& p, const Vec2& c, double& k) noexcept {
  double dx, dy, ex, ey, sx, sy, fx, fy, e;
  expansion::two_diff(p.x, c.x, dx, ex);
  expansion::two_diff(p.y, c.y, dy, ey);
  expansion::two_product(dx, dx, sx, fx);
  expansion::two_product(dy, dy, sy, fy);
  expansion::two_sum(sx, sy, k, e);
  return ex == 0.0 && ey == 0.0 && fx == 0.0 && fy == 0.0 && e == 0.0;
}

// Exact order of two points by distance to c, ties by (x, y).
bool exactly_nearer(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  double ka, kb;
  Sign s;
  if (rounded_exactly(a, c, ka) && rounded_exactly(b, c, kb)) {
    s = ka < kb ? Sign::Negative : ka > kb ? Sign::Positive : Sign::Zero;
  } else {
    s = expansion::difference(exact_squared_distance(a.x, a.y, c), exact_squared_distance(b.x, b.y, c)).sign();
  }
  if (s != Sign::Zero) return s == Sign::Negative;
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

}  // namespace

std::vector<std::uint32_t> radial_sweep_order(std::span<const Vec2> points, std::span<const std::uint32_t> ids,
                                              const Vec2& center) {
  std::vector<RadialKey> keys(ids.size());
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const Vec2& p = points[ids[k]];
    const double dx = p.x - center.x, dy = p.y - center.y;
    keys[k] = {dx * dx + dy * dy, ids[k]};
  }
  // Sort by the rounded keys, then re-sort exactly each run of keys that are pairwise closer than
  // the rounding bound: keys farther apart than it are ordered correctly already.
  std::sort(keys.begin(), keys.end(), [](const RadialKey& a, const RadialKey& b) { return a.key < b.key; });
  for (std::size_t lo = 0; lo < keys.size();) {
    std::size_t hi = lo + 1;
    while (hi < keys.size() && keys[hi].key - keys[hi - 1].key <= kRelativeError * (keys[hi].key + keys[hi - 1].key))
      ++hi;
    if (hi - lo > 1)
      std::sort(keys.begin() + static_cast<std::ptrdiff_t>(lo), keys.begin() + static_cast<std::ptrdiff_t>(hi),
                [&](const RadialKey& a, const RadialKey& b) { return exactly_nearer(points[a.id], points[b.id], center); });
    lo = hi;
  }
  std::vector<std::uint32_t> order(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) order[k] = keys[k].id;
  return order;
}

Vec2 sweep_center(std::span<const Vec2> points, std::span<const std::uint32_t> ids) {
  DTLAB_ASSERT(!ids.empty());
  double xmin = points[ids[0]].x, xmax = xmin, ymin = points[ids[0]].y, ymax = ymin;
  for (const std::uint32_t i : ids) {
    xmin = std::min(xmin, points[i].x), xmax = std::max(xmax, points[i].x);
    ymin = std::min(ymin, points[i].y), ymax = std::max(ymax, points[i].y);
  }
  // Halves are exact in range; a midpoint below the range goes to 0.
  auto in_range = [](double v) { return coordinate_in_range(v) ? v : 0.0; };
  return {in_range(xmin / 2 + xmax / 2), in_range(ymin / 2 + ymax / 2)};
}

}  // namespace dtlab
