// The control space (control_space.hpp): point location in the background by the visibility walk
// of Mesh2 (settled by a bucket grid when it leaves the domain), then the metric interpolated
// from the triangle's vertices (kernel/metric.hpp).
#include "algorithms/mesh2d/control_space.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "algorithms/common/uniform_size_box.hpp"
#include "kernel/error.hpp"
#include "mesh/mesh2_from_data.hpp"

namespace dtlab {

ControlSpace2::ControlSpace2(const MeshData2& background, std::vector<Metric2> metrics, MetricInterpolation mode)
    : ControlSpace2(background.triangles.empty() ? Mesh2{} : mesh2_from_data(background), std::move(metrics), mode) {
  if (background.triangles.empty()) throw InputError("the background mesh has no triangle");
  if (metrics_.size() != background.vertices.size()) {
    throw InputError("the background mesh has " + std::to_string(background.vertices.size()) + " vertices but " +
                     std::to_string(metrics_.size()) + " metrics are given");
  }
}

ControlSpace2::ControlSpace2(Mesh2 background, std::vector<Metric2> metrics, MetricInterpolation mode)
    : mesh_(std::move(background)), metrics_(std::move(metrics)), mode_(mode) {
  for (std::uint32_t t = 0; t < mesh_.triangle_capacity(); ++t) {
    if (mesh_.is_alive(t) && !mesh_.is_ghost(t)) {
      start_ = t;
      break;
    }
  }
  if (start_ == kNoHint) return;  // the MeshData2 constructor names the problem
  if (metrics_.size() < mesh_.vertex_capacity()) {
    throw InputError("the control space has " + std::to_string(metrics_.size()) + " metrics for " +
                     std::to_string(mesh_.vertex_capacity()) + " background vertices");
  }
  validate();
  std::vector<std::array<std::uint32_t, 3>> triangles(mesh_.triangle_capacity(), {0, 0, 0});
  std::vector<bool> skip(mesh_.triangle_capacity(), true);
  for (std::uint32_t t = 0; t < mesh_.triangle_capacity(); ++t) {
    if (!mesh_.is_alive(t) || mesh_.is_ghost(t)) continue;
    triangles[t] = {mesh_.vertex(t, 0), mesh_.vertex(t, 1), mesh_.vertex(t, 2)};
    skip[t] = false;
  }
  grid_ = ElementGrid<Vec2>(mesh_.points(), std::span<const std::array<std::uint32_t, 3>>(triangles), &skip);
}

ControlSpace2 ControlSpace2::uniform_size(std::span<const Vec2> points, double h) {
  const auto [lo, hi] = uniform_size_box(points, h);
  return uniform(Metric2::isotropic(h), lo, hi);
}

ControlSpace2 ControlSpace2::uniform(const Metric2& metric, const Vec2& lo, const Vec2& hi) {
  MeshData2 box;
  box.vertices = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
  box.vertex_refs.assign(4, 0);
  box.triangles = {{0, 1, 2}, {0, 2, 3}};
  box.triangle_refs.assign(2, 0);
  return ControlSpace2(box, std::vector<Metric2>(4, metric));
}

void ControlSpace2::validate() const {
  for (std::uint32_t v = 0; v < mesh_.vertex_capacity(); ++v) {
    if (mesh_.is_dead_vertex(v)) continue;
    if (!metrics_[v].is_positive_definite()) {
      throw InputError("the metric at background vertex " + std::to_string(v + 1) + " is not positive definite", {v});
    }
  }
}

Metric2 ControlSpace2::metric_at(const Vec2& p, std::uint32_t& hint) const {
  DTLAB_ASSERT(start_ != kNoHint);
  std::uint32_t from = start_;
  if (hint < mesh_.triangle_capacity() && mesh_.is_alive(hint)) from = hint;
  else if (const auto near = grid_.candidates(p); !near.empty()) from = near.front();
  Mesh2::Location loc = mesh_.locate(p, from);
  if (loc.where == Mesh2::Where::Outside) {
    // The walk left through a hole or a concavity, or p is outside: the triangles of its bucket.
    for (const std::uint32_t t : grid_.candidates(p)) {
      if (closed_triangle_holds(mesh_.point(mesh_.vertex(t, 0)), mesh_.point(mesh_.vertex(t, 1)),
                                mesh_.point(mesh_.vertex(t, 2)), p)) {
        loc = mesh_.locate(p, t);
        break;
      }
    }
  }
  std::uint32_t t = loc.triangle;
  if (mesh_.is_ghost(t)) t = Mesh2::triangle_of(mesh_.twin(Mesh2::half_edge(t, 0)));
  hint = t;
  const std::array<std::uint32_t, 3> v{mesh_.vertex(t, 0), mesh_.vertex(t, 1), mesh_.vertex(t, 2)};
  // At a vertex, its metric. (The walk may end in a sliver whose area is 0 in doubles, though
  // positive exactly: its weights would be 0 / 0.)
  if (loc.where == Mesh2::Where::Vertex) return metrics_[loc.handle];
  const Vec2 &a = mesh_.point(v[0]), &b = mesh_.point(v[1]), &c = mesh_.point(v[2]);
  // Barycentric weights in doubles, clamped to the triangle (a point outside the background takes
  // the metric at the nearest point of the triangle reached, up to the clamping).
  const double area = cross(b - a, c - a);
  if (!(area > 0.0)) {
    // Such a sliver elsewhere than at a vertex: the metric of its vertex nearest to p.
    std::uint32_t k = 0;
    for (std::uint32_t i = 1; i < 3; ++i) {
      if (norm(mesh_.point(v[i]) - p) < norm(mesh_.point(v[k]) - p)) k = i;
    }
    return metrics_[v[k]];
  }
  std::array<double, 3> w{cross(b - p, c - p) / area, cross(c - p, a - p) / area, 0.0};
  w[0] = std::clamp(w[0], 0.0, 1.0);
  w[1] = std::clamp(w[1], 0.0, 1.0);
  w[2] = std::max(0.0, 1.0 - w[0] - w[1]);
  const double sum = w[0] + w[1] + w[2];
  for (double& x : w) x /= sum;
  const std::array<Metric2, 3> m{metrics_[v[0]], metrics_[v[1]], metrics_[v[2]]};
  if (m[0] == m[1] && m[1] == m[2]) return m[0];
  return interpolate(std::span<const Metric2>(m), std::span<const double>(w), mode_);
}

}  // namespace dtlab
