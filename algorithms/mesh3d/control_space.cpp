// The 3D control space (control_space.hpp): point location in the background Mesh3 by the
// visibility walk of mesh/navigation3.hpp (settled by a bucket grid when it leaves the domain),
// the metric interpolated from the tetrahedron's vertices with barycentric weights
// (kernel/metric.hpp).
#include "algorithms/mesh3d/control_space.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "algorithms/common/uniform_size_box.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/navigation3.hpp"
#include "mesh/tetrahedralization3_build.hpp"

namespace dtlab {

namespace {

constexpr auto kFacetVertex = Tetrahedralization3::kFacetVertex;

double det3(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  return dot(u, cross(v, w));
}

// The background from a file as a Mesh3, after the checks its constructor documents.
Mesh3 background_mesh(const MeshData3& background, std::size_t metrics) {
  const auto& tets = background.tetrahedra;
  const auto& points = background.vertices;
  if (tets.empty()) throw InputError("the background mesh has no tetrahedron");
  if (metrics != points.size()) {
    throw InputError("the background mesh has " + std::to_string(points.size()) + " vertices but " +
                     std::to_string(metrics) + " metrics are given");
  }
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const auto& v = tets[t];
    if (std::max({v[0], v[1], v[2], v[3]}) >= points.size())
      throw InputError("background tetrahedron " + std::to_string(t + 1) + " uses a vertex out of range", {t});
    if (orient3d(points[v[0]], points[v[1]], points[v[2]], points[v[3]]) != Sign::Positive)
      throw InputError("background tetrahedron " + std::to_string(t + 1) + " is not positive (flat or inverted)", {t});
  }
  const Tetrahedralization3 tet = tetrahedralization_from_tetrahedra(points, tets);
  return Mesh3(tet, std::vector<int>(tet.tetrahedron_count(), 0), {});
}

}  // namespace

ControlSpace3::ControlSpace3(const MeshData3& background, std::vector<Metric3> metrics, MetricInterpolation mode)
    : mesh_(background_mesh(background, metrics.size())), mode_(mode) {
  build(metrics);
}

ControlSpace3::ControlSpace3(Mesh3 background, std::vector<Metric3> metrics, MetricInterpolation mode)
    : mesh_(std::move(background)), mode_(mode) {
  mesh_.clear_constraints();
  build(metrics);
}

void ControlSpace3::build(const std::vector<Metric3>& metrics) {
  const std::uint32_t n = mesh_.vertex_capacity(), capacity = mesh_.tetrahedron_capacity();
  if (metrics.size() < n) {
    throw InputError("the control space has " + std::to_string(metrics.size()) + " metrics for " + std::to_string(n) +
                     " background vertices");
  }
  // A live vertex is a vertex of a finite tetrahedron (a ghost's lie on a hull facet).
  for (std::uint32_t v = 0; v < n; ++v) {
    const bool dead = mesh_.is_dead_vertex(v);
    if (!dead && !metrics[v].is_positive_definite())
      throw InputError("the metric at background vertex " + std::to_string(v + 1) + " is not positive definite", {v});
    mesh_.set_metric(v, dead ? Metric3{} : metrics[v]);
  }
  std::vector<bool> skip(capacity, true);
  std::vector<std::array<std::uint32_t, 4>> tets(capacity, {0, 0, 0, 0});
  uniform_.assign(capacity, 0);
  constant_ = true;
  for (std::uint32_t t = 0; t < capacity; ++t) {
    if (!mesh_.is_alive(t) || mesh_.is_ghost(t)) continue;
    if (start_ == kNoHint) start_ = t;
    skip[t] = false;
    ++walk_bound_;
    const auto v = tets[t] = mesh_.tetrahedron(t);
    const auto m = [&](std::uint32_t i) -> const Metric3& { return mesh_.metric(v[i]); };
    uniform_[t] = m(0) == m(1) && m(1) == m(2) && m(2) == m(3);
    constant_ = constant_ && uniform_[t] && m(0) == mesh_.metric(mesh_.vertex(start_, 0));
  }
  if (start_ == kNoHint) throw InputError("the background mesh has no tetrahedron");
  walk_bound_ += 64;
  grid_ = ElementGrid<Vec3>(mesh_.points(), std::span<const std::array<std::uint32_t, 4>>(tets), &skip);
}

bool ControlSpace3::contains(std::uint32_t t, const Vec3& p) const {
  const auto v = mesh_.tetrahedron(t);
  return closed_tetrahedron_holds(mesh_.point(v[0]), mesh_.point(v[1]), mesh_.point(v[2]), mesh_.point(v[3]), p);
}

ControlSpace3 ControlSpace3::uniform_size(std::span<const Vec3> points, double h) {
  const auto [lo, hi] = uniform_size_box(points, h);
  return uniform(Metric3::isotropic(h), lo, hi);
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
  for (std::uint32_t v = 0; v < mesh_.vertex_capacity(); ++v)
    if (!mesh_.is_dead_vertex(v)) h.push_back(sizes(mesh_.metric(v))[0]);
  DTLAB_ASSERT(!h.empty());
  std::nth_element(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(h.size() / 2), h.end());
  return h[h.size() / 2];
}

Metric3 ControlSpace3::metric_at(const Vec3& p, std::uint32_t& hint) const {
  // The hint when it holds p (consecutive questions are usually close), else a walk from an
  // element of p's grid bucket: a walk from a far hint (the relocation sweep asks worst ball
  // first, anywhere in the domain) would cross the background.
  if (constant_) return mesh_.metric(mesh_.vertex(start_, 0));  // the size map of `--size`: nothing to locate
  const bool valid = hint < mesh_.tetrahedron_capacity() && mesh_.is_alive(hint) && !mesh_.is_ghost(hint);
  std::uint32_t t;
  if (valid && contains(hint, p)) {
    t = hint;
  } else {
    std::uint32_t start = valid ? hint : start_;
    if (const auto near = grid_.candidates(p); !near.empty()) start = near.front();
    // Deterministic (the first facet tested rotates with the step, breaking the cycles a
    // non-Delaunay background allows), bounded, the background's boundary skipped.
    const auto beyond = [this](std::uint32_t h) {
      return mesh_.is_ghost(Mesh3::tetrahedron_of(mesh_.twin(h))) ? nav3::Beyond::Skip : nav3::Beyond::Cross;
    };
    t = nav3::visibility_walk(mesh_, p, start, walk_bound_, [](std::uint64_t step) { return static_cast<std::uint32_t>(step & 3u); },
                              beyond)
            .tetrahedron;
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
  const auto v = mesh_.tetrahedron(t);
  if (uniform_[t]) return mesh_.metric(v[0]);
  std::array<double, 4> w{};
  double sum = 0.0;
  for (std::uint32_t i = 0; i < 4; ++i) {
    const auto& f = kFacetVertex[i];
    const Vec3 &a = mesh_.point(v[f[0]]), &b = mesh_.point(v[f[1]]), &c = mesh_.point(v[f[2]]);
    const double whole = det3(a, b, c, mesh_.point(v[i]));
    w[i] = std::clamp(det3(a, b, c, p) / whole, 0.0, 1.0);
    sum += w[i];
  }
  if (!(sum > 0.0)) w = {0.25, 0.25, 0.25, 0.25}, sum = 1.0;
  for (double& x : w) x /= sum;
  const std::array<Metric3, 4> m{mesh_.metric(v[0]), mesh_.metric(v[1]), mesh_.metric(v[2]), mesh_.metric(v[3])};
  return interpolate(std::span<const Metric3>(m), std::span<const double>(w), mode_);
}

}  // namespace dtlab
