// snap_crossings (crossings.hpp): candidate pairs from a uniform grid the segments are drawn
// into, exact crossing tests (orient2d), exact intersections rounded correctly (MPFR), then each
// segment's stops: the hot points whose rounding box it meets, ordered along it exactly.
#include "algorithms/constrained2d/crossings.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "kernel/predicates.hpp"

namespace dtlab {

namespace {

using Segment = std::array<std::uint32_t, 2>;

// A uniform grid of side x side cells over the segments' bounding box, about one cell per
// segment: each segment is drawn into every cell it may meet (conservatively), so two segments
// that meet share a cell.
class SegmentGrid {
 public:
  SegmentGrid(std::span<const Vec2> points, std::span<const Segment> segments) {
    bool any = false;
    for (const Segment& s : segments)
      for (const std::uint32_t v : s) {
        const Vec2& p = points[v];
        if (!any) lo_ = hi_ = p, any = true;
        lo_.x = std::min(lo_.x, p.x), lo_.y = std::min(lo_.y, p.y);
        hi_.x = std::max(hi_.x, p.x), hi_.y = std::max(hi_.y, p.y);
      }
    side_ = static_cast<int>(std::clamp(std::ceil(std::sqrt(static_cast<double>(segments.size()))), 1.0, 1024.0));
    // Widths in doubles can overflow (coordinates up to 2^142 only, so they do not) or be zero.
    sx_ = hi_.x > lo_.x ? side_ / (hi_.x - lo_.x) : 0.0;
    sy_ = hi_.y > lo_.y ? side_ / (hi_.y - lo_.y) : 0.0;
  }

  // Calls f(cell) for each cell segment ab may meet: for each column of its bounding box, the
  // rows between its heights at the column's sides, one more row each way for rounding.
  template <class F>
  void cover(const Vec2& a, const Vec2& b, F&& f) const {
    const double xmin = std::min(a.x, b.x), xmax = std::max(a.x, b.x);
    const double ymin = std::min(a.y, b.y), ymax = std::max(a.y, b.y);
    const int c0 = column(xmin), c1 = column(xmax);
    for (int c = c0; c <= c1; ++c) {
      double y0 = ymin, y1 = ymax;
      if (c0 != c1 && a.x != b.x) {
        const double xl = std::max(xmin, lo_.x + c / sx_), xr = std::min(xmax, lo_.x + (c + 1) / sx_);
        const double t0 = (xl - a.x) / (b.x - a.x), t1 = (xr - a.x) / (b.x - a.x);
        const double ya = a.y + t0 * (b.y - a.y), yb = a.y + t1 * (b.y - a.y);
        y0 = std::max(ymin, std::min(ya, yb));
        y1 = std::min(ymax, std::max(ya, yb));
      }
      const int r0 = std::max(0, row(y0) - 1), r1 = std::min(side_ - 1, row(y1) + 1);
      for (int r = r0; r <= r1; ++r) f(static_cast<std::uint32_t>(c * side_ + r));
    }
  }

 private:
  int column(double x) const { return std::clamp(static_cast<int>((x - lo_.x) * sx_), 0, side_ - 1); }
  int row(double y) const { return std::clamp(static_cast<int>((y - lo_.y) * sy_), 0, side_ - 1); }

  Vec2 lo_{0, 0}, hi_{0, 0};
  int side_ = 1;
  double sx_ = 0, sy_ = 0;
};

bool boxes_overlap(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  return std::max(std::min(a.x, b.x), std::min(c.x, d.x)) <= std::min(std::max(a.x, b.x), std::max(c.x, d.x)) &&
         std::max(std::min(a.y, b.y), std::min(c.y, d.y)) <= std::min(std::max(a.y, b.y), std::max(c.y, d.y));
}

// Pairs (i < j) of segments that share a grid cell and whose bounding boxes overlap, each once
// (with a shared endpoint too: the other endpoint may lie on or near the other segment).
std::vector<std::uint64_t> candidate_pairs(std::span<const Vec2> points, std::span<const Segment> segments) {
  const SegmentGrid grid(points, segments);
  std::vector<std::uint64_t> in_cell;  // (cell << 32) | segment
  for (std::uint32_t k = 0; k < segments.size(); ++k)
    grid.cover(points[segments[k][0]], points[segments[k][1]],
               [&](std::uint32_t cell) { in_cell.push_back(std::uint64_t{cell} << 32 | k); });
  std::sort(in_cell.begin(), in_cell.end());
  std::vector<std::uint64_t> pairs;
  for (std::size_t begin = 0; begin < in_cell.size();) {
    std::size_t end = begin;
    while (end < in_cell.size() && in_cell[end] >> 32 == in_cell[begin] >> 32) ++end;
    for (std::size_t x = begin; x < end; ++x)
      for (std::size_t y = x + 1; y < end; ++y) {
        const auto i = static_cast<std::uint32_t>(in_cell[x]), j = static_cast<std::uint32_t>(in_cell[y]);
        const Segment& s = segments[i];
        const Segment& t = segments[j];
        if (!boxes_overlap(points[s[0]], points[s[1]], points[t[0]], points[t[1]])) continue;
        pairs.push_back(std::uint64_t{i} << 32 | j);  // i < j: cells list segments ascending
      }
    begin = end;
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

bool properly_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const Sign c_side = orient2d(a, b, c), d_side = orient2d(a, b, d);
  if (c_side == Sign::Zero || d_side == Sign::Zero || c_side == d_side) return false;
  const Sign a_side = orient2d(c, d, a), b_side = orient2d(c, d, b);
  return a_side != Sign::Zero && b_side != Sign::Zero && a_side != b_side;
}

}  // namespace

std::vector<std::uint32_t> order_along_segment(const Vec2& a, const Vec2& b,
                                               std::vector<std::pair<Vec2, std::uint32_t>> stops) {
  if (stops.empty()) return {};
  const Rational ex = Rational(b.x) - Rational(a.x), ey = Rational(b.y) - Rational(a.y);
  const Rational length2 = ex * ex + ey * ey;
  std::vector<std::pair<Rational, std::uint32_t>> keyed;
  keyed.reserve(stops.size());
  for (const auto& [p, id] : stops) {
    Rational t = (Rational(p.x) - Rational(a.x)) * ex + (Rational(p.y) - Rational(a.y)) * ey;
    if (t.sign() == Sign::Positive && t < length2) keyed.emplace_back(std::move(t), id);
  }
  std::sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) {
    return x.first < y.first || (x.first == y.first && x.second < y.second);
  });
  std::vector<std::uint32_t> ids;
  for (const auto& [t, id] : keyed)
    if (ids.empty() || ids.back() != id) ids.push_back(id);
  return ids;
}

SnappedCrossings snap_crossings(std::span<const Vec2> points, std::span<const Segment> segments) {
  SnappedCrossings out;
  const auto m = static_cast<std::uint32_t>(segments.size());
  const std::vector<std::uint64_t> pairs = candidate_pairs(points, segments);

  struct Crossing {
    Vec2 point;
    ExactPoint2 exact;
    bool exact_double;
    std::uint32_t s, t;
  };
  std::vector<Crossing> crossings;
  for (const std::uint64_t pair : pairs) {
    const auto s = static_cast<std::uint32_t>(pair >> 32), t = static_cast<std::uint32_t>(pair);
    const Vec2 &a = points[segments[s][0]], &b = points[segments[s][1]];
    const Vec2 &c = points[segments[t][0]], &d = points[segments[t][1]];
    if (!properly_cross(a, b, c, d)) continue;
    ExactPoint2 exact = *line_intersection_exact(a, b, c, d);  // lines not parallel: they cross
    const RoundedPoint2 rounded = round_point_checked(exact);
    out.rounded = out.rounded || !rounded.exact;
    crossings.push_back({rounded.point, std::move(exact), rounded.exact, s, t});
  }
  // Distinct points, by coordinates; each keeps its first pair.
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& x, const Crossing& y) {
    return std::tie(x.point.x, x.point.y, x.s, x.t) < std::tie(y.point.x, y.point.y, y.s, y.t);
  });
  std::vector<std::vector<std::uint32_t>> own(m);  // each segment's hot points
  for (const Crossing& c : crossings) {
    if (out.hot.empty() || !(out.hot.back().point == c.point))
      out.hot.push_back({c.point, c.exact, c.exact_double, c.s, c.t});
    const auto h = static_cast<std::uint32_t>(out.hot.size() - 1);
    own[c.s].push_back(h);
    own[c.t].push_back(h);
  }

  // Neighbours: the candidate pairs, both ways (compressed rows).
  std::vector<std::uint32_t> first(m + 1, 0), near(2 * pairs.size());
  for (const std::uint64_t pair : pairs) ++first[(pair >> 32) + 1], ++first[static_cast<std::uint32_t>(pair) + 1];
  for (std::uint32_t k = 0; k < m; ++k) first[k + 1] += first[k];
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (const std::uint64_t pair : pairs) {
      const auto s = static_cast<std::uint32_t>(pair >> 32), t = static_cast<std::uint32_t>(pair);
      near[fill[s]++] = t;
      near[fill[t]++] = s;
    }
  }

  out.first.assign(1, 0);
  std::vector<std::pair<Vec2, std::uint32_t>> candidates;
  for (std::uint32_t k = 0; k < m; ++k) {
    const auto [ia, ib] = segments[k];
    const Vec2 &a = points[ia], &b = points[ib];
    candidates.clear();
    for (const std::uint32_t h : own[k]) candidates.emplace_back(out.hot[h].point, SnappedCrossings::kHot | h);
    // Once a crossing is rounded, chains bend: route this one through every hot point nearby.
    if (out.rounded)
      for (std::uint32_t x = first[k]; x < first[k + 1]; ++x) {
        const std::uint32_t j = near[x];
        for (const std::uint32_t h : own[j])
          if (rounding_box_meets_segment(out.hot[h].point, a, b))
            candidates.emplace_back(out.hot[h].point, SnappedCrossings::kHot | h);
        for (const std::uint32_t v : segments[j])
          if (v != ia && v != ib && rounding_box_meets_segment(points[v], a, b)) candidates.emplace_back(points[v], v);
      }
    // Two stops at one point (a hot point on an input vertex): the vertex.
    std::sort(candidates.begin(), candidates.end(), [](const auto& x, const auto& y) {
      return std::tie(x.first.x, x.first.y, x.second) < std::tie(y.first.x, y.first.y, y.second);
    });
    std::size_t kept = 0;
    for (std::size_t i = 0; i < candidates.size(); ++i)
      if (kept == 0 || !(candidates[kept - 1].first == candidates[i].first)) candidates[kept++] = candidates[i];
    candidates.resize(kept);
    const std::vector<std::uint32_t> ordered = order_along_segment(a, b, candidates);
    out.stops.insert(out.stops.end(), ordered.begin(), ordered.end());
    out.first.push_back(static_cast<std::uint32_t>(out.stops.size()));
  }
  return out;
}

}  // namespace dtlab
