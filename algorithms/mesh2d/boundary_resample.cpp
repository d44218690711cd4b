// Boundary discretisation in the metric (book §11.2, curve meshing under a size map; §6's
// "geometric meshes" for the metric case): each input segment is cut into sub-segments of metric
// length close to 1. The metric may vary along a segment far more than between its ends (a layer
// crossing a side), so its length is integrated on a sampling refined until every sample step is
// at most kStepLength long in the metric, and the cut points are placed at equal steps of the
// cumulated length. Cut points are the rounded points of the segment (within their rounding bound
// of it, exactly on it when the segment is axis-aligned); each sub-segment keeps the marker.
#include <algorithm>
#include <cmath>
#include <string>

#include "algorithms/mesh2d/mesh2d.hpp"
#include "kernel/error.hpp"

namespace dtlab {

namespace {

constexpr double kStepLength = 0.2;           // metric length of one integration step at most
constexpr std::uint32_t kMaxSamples = 1u << 22;  // per segment
constexpr double kLongLength = 1.4142135623730951;  // sqrt 2

}  // namespace

ResampledBoundary resample_boundary(const Mesh2dInput& input, const ControlSpace2& control, const Mesh2dOptions& options) {
  ResampledBoundary out;
  out.points.assign(input.points.begin(), input.points.end());
  std::uint32_t hint = ControlSpace2::kNoHint;
  std::vector<double> t, length;  // sample parameters and cumulated metric lengths
  std::vector<Metric2> m;
  for (std::size_t s = 0; s < input.segments.size(); ++s) {
    const std::uint32_t a = input.segments[s][0], b = input.segments[s][1];
    const int marker = s < input.segment_markers.size() ? input.segment_markers[s] : 0;
    const Vec2 pa = input.points[a], pb = input.points[b];
    const Vec2 ab = pb - pa;
    // Refine the sampling until each step is short in the metric: intervals bisected depth
    // first, left half first, so the samples come out in order (linear in their number).
    t = {0.0};
    m = {control.metric_at(pa, hint)};
    struct Interval {
      double t0, t1;
      Metric2 m1;
    };
    std::vector<Interval> stack{{0.0, 1.0, control.metric_at(pb, hint)}};
    while (!stack.empty()) {
      const Interval iv = stack.back();
      stack.pop_back();
      const double l = edge_length(pa + iv.t0 * ab, m.back(), pa + iv.t1 * ab, iv.m1);
      const double mid = 0.5 * (iv.t0 + iv.t1);
      if (l <= kStepLength || mid <= iv.t0 || mid >= iv.t1) {
        if (t.size() >= kMaxSamples) {
          throw InputError("mesh2d: segment " + std::to_string(s + options.first_number) + " needs more than " +
                               std::to_string(kMaxSamples) + " samples to measure in the metric (is the size that small?)",
                           {s});
        }
        t.push_back(iv.t1);
        m.push_back(iv.m1);
        continue;
      }
      stack.push_back({mid, iv.t1, iv.m1});
      stack.push_back({iv.t0, mid, control.metric_at(pa + mid * ab, hint)});
    }
    length.assign(t.size(), 0.0);
    for (std::size_t i = 1; i < t.size(); ++i) {
      length[i] = length[i - 1] + edge_length(pa + t[i - 1] * ab, m[i - 1], pa + t[i] * ab, m[i]);
    }
    const double total = length.back();
    // Pieces of length close to 1, none longer than sqrt 2; a segment no longer than that is kept.
    const bool long_segment = total > kLongLength;
    out.long_segments += long_segment;
    const std::uint32_t n = long_segment ? static_cast<std::uint32_t>(std::max(std::round(total), std::ceil(total / kLongLength))) : 1;
    if (out.points.size() + n > options.max_vertices) {
      throw InputError("mesh2d: the boundary needs more than the vertex bound of " + std::to_string(options.max_vertices) + " points");
    }
    std::uint32_t previous = a;
    std::size_t i = 1;
    for (std::uint32_t k = 1; k < n; ++k) {
      const double target = total * k / n;
      while (length[i] < target) ++i;
      const double u = t[i - 1] + (t[i] - t[i - 1]) * (target - length[i - 1]) / (length[i] - length[i - 1]);
      const Vec2 p = pa + u * ab;
      if (p == out.points[previous] || p == pb) continue;  // a cut that rounds onto its neighbour
      out.points.push_back(p);
      const auto v = static_cast<std::uint32_t>(out.points.size() - 1);
      out.segments.push_back({previous, v});
      out.markers.push_back(marker);
      previous = v;
    }
    out.segments.push_back({previous, b});
    out.markers.push_back(marker);
  }
  return out;
}

}  // namespace dtlab
