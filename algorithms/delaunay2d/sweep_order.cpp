#include "algorithms/delaunay2d/sweep_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/exact_rational.hpp"
#include "kernel/predicates.hpp"
#include "kernel/predicates/expansion.hpp"
#include "kernel/rounding.hpp"

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

struct Box {
  double xmin, xmax, ymin, ymax;
};

Box bounding_box(std::span<const Vec2> points, std::span<const std::uint32_t> ids) {
  DTLAB_ASSERT(!ids.empty());
  Box box{points[ids[0]].x, points[ids[0]].x, points[ids[0]].y, points[ids[0]].y};
  for (const std::uint32_t i : ids) {
    box.xmin = std::min(box.xmin, points[i].x), box.xmax = std::max(box.xmax, points[i].x);
    box.ymin = std::min(box.ymin, points[i].y), box.ymax = std::max(box.ymax, points[i].y);
  }
  return box;
}

double in_range_or_zero(double v) noexcept { return coordinate_in_range(v) ? v : 0.0; }

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

Vec2 bounding_box_middle(std::span<const Vec2> points, std::span<const std::uint32_t> ids) {
  const Box box = bounding_box(points, ids);
  // Halves are exact in range; a midpoint below the range goes to 0.
  return {in_range_or_zero(box.xmin / 2 + box.xmax / 2), in_range_or_zero(box.ymin / 2 + box.ymax / 2)};
}

bool rounded_circumcenter(const Vec2& a, const Vec2& b, const Vec2& c, Vec2& center) {
  if (orient2d(a, b, c) == Sign::Zero) return false;
  // Centre = (Nx, Ny) / D with D = 2 det(b - a, c - a), N from the lifted determinant's minors.
  const Rational ax(a.x), ay(a.y), bx(b.x), by(b.y), cx(c.x), cy(c.y);
  const Rational la = ax * ax + ay * ay, lb = bx * bx + by * by, lc = cx * cx + cy * cy;
  const Rational d = Rational(2) * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by));
  const Rational nx = la * (by - cy) + lb * (cy - ay) + lc * (ay - by);
  const Rational ny = la * (cx - bx) + lb * (ax - cx) + lc * (bx - ax);
  center = {round_to_double(nx / d), round_to_double(ny / d)};
  return true;
}

Vec2 sweep_center(std::span<const Vec2> points, std::span<const std::uint32_t> ids) {
  const Vec2 middle = bounding_box_middle(points, ids);
  if (ids.size() < 3) return middle;
  // The seed triangle is a speed heuristic in doubles: the point nearest the middle, its nearest
  // neighbour, and the third point that makes the smallest circumcircle with them.
  auto nearest = [&](const Vec2& q, std::uint32_t skip) {
    std::uint32_t best = skip;
    double best_d = std::numeric_limits<double>::infinity();
    for (const std::uint32_t i : ids) {
      const double dx = points[i].x - q.x, dy = points[i].y - q.y, d = dx * dx + dy * dy;
      if (i != skip && d < best_d) best_d = d, best = i;
    }
    return best;
  };
  const std::uint32_t i0 = nearest(middle, static_cast<std::uint32_t>(-1));
  const std::uint32_t i1 = nearest(points[i0], i0);
  const Vec2 a = points[i0], b = points[i1];
  std::uint32_t i2 = i0;
  double best_r = std::numeric_limits<double>::infinity();
  for (const std::uint32_t i : ids) {
    // Twice the signed area and the circumradius squared, in doubles; flat or overflowing
    // candidates give no finite radius and are skipped.
    const double bx = b.x - a.x, by = b.y - a.y, cx = points[i].x - a.x, cy = points[i].y - a.y;
    const double den = 2.0 * (bx * cy - by * cx);
    if (den == 0.0) continue;
    const double bl = bx * bx + by * by, cl = cx * cx + cy * cy;
    const double ux = (cy * bl - by * cl) / den, uy = (bx * cl - cx * bl) / den, r = ux * ux + uy * uy;
    if (r < best_r) best_r = r, i2 = i;
  }
  Vec2 center;
  if (i2 == i0 || !rounded_circumcenter(a, b, points[i2], center)) return middle;
  // Outside the box the sweep would run as from afar, along a flat front (sweep.cpp).
  const Box box = bounding_box(points, ids);
  if (!(box.xmin <= center.x && center.x <= box.xmax && box.ymin <= center.y && center.y <= box.ymax)) return middle;
  return {in_range_or_zero(center.x), in_range_or_zero(center.y)};
}

}  // namespace dtlab
