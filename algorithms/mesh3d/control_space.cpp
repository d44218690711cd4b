// The 3D control space (control_space.hpp): the background's adjacency matched by sorted facet
// keys, point location by a bounded visibility walk (exact orient3d), the metric interpolated from
// the tetrahedron's vertices with barycentric weights (kernel/metric.hpp).
#include "algorithms/mesh3d/control_space.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/mesh3.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

namespace {

constexpr auto kFacetVertex = Tetrahedralization3::kFacetVertex;

double det3(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  return dot(u, cross(v, w));
}

}  // namespace

ControlSpace3::ControlSpace3(const MeshData3& background, std::vector<Metric3> metrics, MetricInterpolation mode)
    : points_(background.vertices), metrics_(std::move(metrics)), tets_(background.tetrahedra), mode_(mode) {
  if (tets_.empty()) throw InputError("the background mesh has no tetrahedron");
  if (metrics_.size() != points_.size()) {
    throw InputError("the background mesh has " + std::to_string(points_.size()) + " vertices but " +
                     std::to_string(metrics_.size()) + " metrics are given");
  }
  for (std::size_t t = 0; t < tets_.size(); ++t) {
    const auto& v = tets_[t];
    if (std::max({v[0], v[1], v[2], v[3]}) >= points_.size())
      throw InputError("background tetrahedron " + std::to_string(t + 1) + " uses a vertex out of range", {t});
    if (orient3d(points_[v[0]], points_[v[1]], points_[v[2]], points_[v[3]]) != Sign::Positive)
      throw InputError("background tetrahedron " + std::to_string(t + 1) + " is not positive (flat or inverted)", {t});
  }
  build(mode);
}

ControlSpace3::ControlSpace3(const Mesh3& background, std::vector<Metric3> metrics, MetricInterpolation mode)
    : points_(background.points().begin(), background.points().end()), metrics_(std::move(metrics)), mode_(mode) {
  if (metrics_.size() < points_.size()) {
    throw InputError("the control space has " + std::to_string(metrics_.size()) + " metrics for " +
                     std::to_string(points_.size()) + " background vertices");
  }
  metrics_.resize(points_.size());
  for (std::uint32_t t = 0; t < background.tetrahedron_capacity(); ++t) {
    if (background.is_alive(t) && !background.is_ghost(t)) tets_.push_back(background.tetrahedron(t));
  }
  if (tets_.empty()) throw InputError("the background mesh has no tetrahedron");
  // Dead vertex slots carry whatever metric; give them the identity so that validation passes.
  for (std::uint32_t v = 0; v < background.vertex_capacity(); ++v) {
    if (background.is_dead_vertex(v)) metrics_[v] = Metric3{};
  }
  build(mode);
}

void ControlSpace3::build(MetricInterpolation mode) {
  mode_ = mode;
  std::vector<std::uint8_t> used(points_.size(), 0);
  for (const auto& v : tets_)
    for (const std::uint32_t x : v) used[x] = 1;
  for (std::size_t v = 0; v < points_.size(); ++v) {
    if (used[v] && !metrics_[v].is_positive_definite())
      throw InputError("the metric at background vertex " + std::to_string(v + 1) + " is not positive definite", {v});
  }
  // Twins: the facets' sorted vertex triples, sorted; equal neighbours pair up.
  struct Key {
    std::array<std::uint32_t, 3> v;
    std::uint32_t handle;
  };
  std::vector<Key> keys;
  keys.reserve(4 * tets_.size());
  for (std::uint32_t t = 0; t < tets_.size(); ++t) {
    for (std::uint32_t i = 0; i < 4; ++i) {
      std::array<std::uint32_t, 3> f{tets_[t][kFacetVertex[i][0]], tets_[t][kFacetVertex[i][1]], tets_[t][kFacetVertex[i][2]]};
      std::sort(f.begin(), f.end());
      keys.push_back({f, 4 * t + i});
    }
  }
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) { return a.v != b.v ? a.v < b.v : a.handle < b.handle; });
  neighbours_.assign(tets_.size(), {kNone, kNone, kNone, kNone});
  for (std::size_t k = 0; k < keys.size();) {
    std::size_t e = k + 1;
    while (e < keys.size() && keys[e].v == keys[k].v) ++e;
    if (e - k > 2) {
      throw InputError("background facet (" + std::to_string(keys[k].v[0] + 1) + ", " + std::to_string(keys[k].v[1] + 1) +
                       ", " + std::to_string(keys[k].v[2] + 1) + ") is shared by more than two tetrahedra");
    }
    if (e - k == 2) {
      neighbours_[keys[k].handle >> 2][keys[k].handle & 3] = keys[k + 1].handle >> 2;
      neighbours_[keys[k + 1].handle >> 2][keys[k + 1].handle & 3] = keys[k].handle >> 2;
    }
    k = e;
  }
  uniform_.resize(tets_.size());
  for (std::size_t t = 0; t < tets_.size(); ++t) {
    const auto& v = tets_[t];
    uniform_[t] = metrics_[v[0]] == metrics_[v[1]] && metrics_[v[1]] == metrics_[v[2]] && metrics_[v[2]] == metrics_[v[3]];
  }
  constant_ = true;
  for (std::size_t t = 0; t < tets_.size() && constant_; ++t)
    constant_ = uniform_[t] && metrics_[tets_[t][0]] == metrics_[tets_[0][0]];
  grid_ = ElementGrid<Vec3>(points_, std::span<const std::array<std::uint32_t, 4>>(tets_));
}

bool ControlSpace3::contains(std::uint32_t t, const Vec3& p) const {
  const auto& v = tets_[t];
  return closed_tetrahedron_holds(points_[v[0]], points_[v[1]], points_[v[2]], points_[v[3]], p);
}

ControlSpace3 ControlSpace3::uniform_size(std::span<const Vec3> points, double h) {
  if (!(h > 0.0) || !std::isfinite(h))
    throw InputError("size: give a positive finite size H (the metric H^-2 I)");
  if (points.empty()) throw InputError("a uniform size needs a domain: no points");
  Vec3 lo = points.front(), hi = lo;
  for (const Vec3& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  return uniform(Metric3::isotropic(h), lo - Vec3{1, 1, 1}, hi + Vec3{1, 1, 1});
}

ControlSpace3 ControlSpace3::uniform(const Metric3& metric, const Vec3& lo, const Vec3& hi) {
  MeshData3 box;
  for (std::uint32_t c = 0; c < 8; ++c)
    box.vertices.push_back({(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z});
  box.vertex_refs.assign(8, 0);
  // Kuhn's six tetrahedra around the diagonal 0-7: one per order of the axes.
  const std::array<std::array<std::uint32_t, 3>, 6> orders{{{1, 2, 4}, {1, 4, 2}, {2, 1, 4}, {2, 4, 1}, {4, 1, 2}, {4, 2, 1}}};
  for (const auto& o : orders) {
    std::array<std::uint32_t, 4> t{0, o[0], o[0] | o[1], 7};
    if (orient3d(box.vertices[t[0]], box.vertices[t[1]], box.vertices[t[2]], box.vertices[t[3]]) != Sign::Positive)
      std::swap(t[1], t[2]);
    box.tetrahedra.push_back(t);
  }
  box.tetrahedron_refs.assign(6, 0);
  return ControlSpace3(box, std::vector<Metric3>(8, metric));
}

double ControlSpace3::median_largest_size() const {
  std::vector<double> h;
  std::vector<std::uint8_t> used(points_.size(), 0);
  for (const auto& v : tets_)
    for (const std::uint32_t x : v) used[x] = 1;
  for (std::size_t v = 0; v < points_.size(); ++v)
    if (used[v]) h.push_back(sizes(metrics_[v])[0]);
  DTLAB_ASSERT(!h.empty());
  std::nth_element(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(h.size() / 2), h.end());
  return h[h.size() / 2];
}

std::uint32_t ControlSpace3::walk(const Vec3& p, std::uint32_t t) const {
  // The visibility walk may cycle in a non-Delaunay background: bounded, and the facet tried
  // first rotates with the step so that a cycle is broken deterministically.
  const std::size_t bound = tets_.size() + 64;
  for (std::size_t step = 0; step < bound; ++step) {
    std::uint32_t next = kNone;
    for (std::uint32_t k = 0; k < 4; ++k) {
      const std::uint32_t i = static_cast<std::uint32_t>((k + step) & 3u);
      const auto& f = kFacetVertex[i];
      const auto& v = tets_[t];
      if (orient3d(points_[v[f[0]]], points_[v[f[1]]], points_[v[f[2]]], p) == Sign::Negative) {
        if (neighbours_[t][i] == kNone) continue;  // beyond the background there
        next = neighbours_[t][i];
        break;
      }
    }
    if (next == kNone) return t;  // inside t (or outside the background beyond t's boundary facets)
    t = next;
  }
  return t;
}

Metric3 ControlSpace3::metric_at(const Vec3& p, std::uint32_t& hint) const {
  // The hint when it holds p (consecutive questions are usually close), else a walk from an
  // element of p's grid bucket: a walk from a far hint (the relocation sweep asks worst ball
  // first, anywhere in the domain) would cross the background.
  if (constant_) return metrics_[tets_[0][0]];  // the size map of `--size`: nothing to locate
  std::uint32_t t;
  if (hint < tets_.size() && contains(hint, p)) {
    t = hint;
  } else {
    std::uint32_t start = hint < tets_.size() ? hint : 0;
    if (const auto near = grid_.candidates(p); !near.empty()) start = near.front();
    t = walk(p, start);
  }
  if (!contains(t, p)) {
    // The walk stopped at the boundary: through a hole or a concavity, or p is outside.
    for (const std::uint32_t c : grid_.candidates(p)) {
      if (contains(c, p)) {
        t = c;
        break;
      }
    }
  }
  hint = t;
  const auto& v = tets_[t];
  if (uniform_[t]) return metrics_[v[0]];
  std::array<double, 4> w{};
  double sum = 0.0;
  for (std::uint32_t i = 0; i < 4; ++i) {
    const auto& f = kFacetVertex[i];
    const Vec3 &a = points_[v[f[0]]], &b = points_[v[f[1]]], &c = points_[v[f[2]]];
    const double whole = det3(a, b, c, points_[v[i]]);
    w[i] = std::clamp(det3(a, b, c, p) / whole, 0.0, 1.0);
    sum += w[i];
  }
  if (!(sum > 0.0)) w = {0.25, 0.25, 0.25, 0.25}, sum = 1.0;
  for (double& x : w) x /= sum;
  const std::array<Metric3, 4> m{metrics_[v[0]], metrics_[v[1]], metrics_[v[2]], metrics_[v[3]]};
  return interpolate(std::span<const Metric3>(m), std::span<const double>(w), mode_);
}

}  // namespace dtlab
