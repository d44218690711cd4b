// Vertex relocation of book §8.4 in 3D: the optimal point P* of the ball of P ("optimal shape
// relocation", (8.17)) is the mean of the ideal points I_j of the ball's boundary facets, each
// I_j the apex of the regular tetrahedron on the facet in the facet's metric, weighted by the
// current Q_Kj (a_j = Q_Kj: the worse tetrahedra pull harder). The sub-relaxation (8.13)
// P' = (1 - w) P + w P* tries w = 1, 1/2, ... and keeps the first P' whose ball is valid (exact
// orient3d) and better (worst Q_K, in the metric at P').
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>
#include <utility>

#include "algorithms/optimize3d/local.hpp"
#include "algorithms/optimize3d/operators.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quality.hpp"
#include "mesh/navigation3.hpp"

namespace dtlab {

using namespace optimize3d_detail;

namespace {

// A weight beyond this (a flat tetrahedron has Q_K = +inf) would swamp the mean.
constexpr double kMaxWeight = 1e6;
constexpr double kRegularHeight = 0.81649658092772603273;  // sqrt(2/3): height / edge

// The facet opposite v in tetrahedron t, in kFacetVertex order: (f0, f1, f2, v) is positive.
std::array<std::uint32_t, 3> opposite_facet(const Mesh3& mesh, std::uint32_t t, std::uint32_t v) {
  for (std::uint32_t i = 0; i < 4; ++i)
    if (mesh.vertex(t, i) == v) return mesh.facet_vertices(Mesh3::facet(t, i));
  return {Mesh3::kNone, Mesh3::kNone, Mesh3::kNone};
}

// M^1/2 and M^-1/2 of the last anisotropic metric asked for: a uniform field asks for the same
// one at every facet, and the eigen-decompositions cost more than the rest of ideal_apex. The
// same values as computing them each time.
class MetricRoots {
 public:
  void of(const Metric3& m) {
    if (valid_ && m.m == metric_.m) return;
    root = power(m, 0.5);
    inverse_root = power(m, -0.5);
    metric_ = m;
    valid_ = true;
  }
  Metric3 root, inverse_root;

 private:
  Metric3 metric_;
  bool valid_ = false;
};

// The apex, on the positive side of (a, b, c), of the regular tetrahedron on the facet (its edge
// the mean of the facet's three): Euclidean, as in any scalar metric.
Vec3 ideal_apex_euclidean(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = cross(b - a, c - a);
  const double area2 = norm_by_square(n);
  const double edge = (norm_by_square(b - a) + norm_by_square(c - b) + norm_by_square(a - c)) / 3.0;
  const Vec3 centre = (1.0 / 3.0) * (a + b + c);
  if (!(area2 > 0.0)) return centre;
  return centre + (kRegularHeight * edge / area2) * n;
}

// The same in m: in the space where m is the identity.
Vec3 ideal_apex(const Vec3& a, const Vec3& b, const Vec3& c, const Metric3& m, MetricRoots& roots) {
  if (m.is_scalar()) return ideal_apex_euclidean(a, b, c);
  roots.of(m);
  const Metric3& root = roots.root;
  const Metric3& inverse_root = roots.inverse_root;
  const Vec3 x = transform(root, a), y = transform(root, b), z = transform(root, c);
  const Vec3 n = cross(y - x, z - x);
  const double area2 = norm(n);
  const double edge = (norm(y - x) + norm(z - y) + norm(x - z)) / 3.0;
  const Vec3 centre = (1.0 / 3.0) * (x + y + z);
  if (!(area2 > 0.0)) return transform(inverse_root, centre);
  return transform(inverse_root, centre + (kRegularHeight * edge / area2) * n);
}

Metric3 mean_metric(const Metric3& a, const Metric3& b, const Metric3& c) {
  Metric3 m;
  for (int i = 0; i < 6; ++i) m.m[i] = (a.m[i] + b.m[i] + c.m[i]) / 3.0;
  return m;
}

}  // namespace

namespace {

// optimal_point with the ball's current Q_K already known (quality[k] of ball[k]).
Vec3 optimal_point_of(const Mesh3& mesh, std::uint32_t v, std::span<const std::uint32_t> ball,
                      std::span<const double> quality, MetricRoots& roots) {
  Vec3 sum{0.0, 0.0, 0.0};
  double weights = 0.0;
  for (std::size_t k = 0; k < ball.size(); ++k) {
    const auto f = opposite_facet(mesh, ball[k], v);
    const double w = std::min(quality[k], kMaxWeight);
    const Vec3 apex =
        mesh.metrics_all_scalar()
            ? ideal_apex_euclidean(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]))
            : ideal_apex(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]),
                         mean_metric(mesh.metric(f[0]), mesh.metric(f[1]), mesh.metric(f[2])), roots);
    sum = sum + w * apex;
    weights += w;
  }
  if (!(weights > 0.0)) return mesh.point(v);
  return (1.0 / weights) * sum;
}

}  // namespace

Vec3 optimal_point(const Mesh3& mesh, std::uint32_t v, std::span<const std::uint32_t> ball) {
  std::vector<double> quality;
  quality.reserve(ball.size());
  for (const std::uint32_t t : ball) quality.push_back(tetrahedron_quality(mesh, t));
  MetricRoots roots;
  return optimal_point_of(mesh, v, ball, quality, roots);
}

namespace {

// The buffers of one relocation, kept across the vertices of a sweep.
struct RelocateScratch {
  std::vector<std::uint32_t> ball;
  std::vector<std::array<std::uint32_t, 3>> facets;
  std::vector<double> quality;
  MetricRoots roots;
  // The candidates' Q_K over each facet, prepared at its first use (Euclidean: the facet and the
  // moved vertex all in isotropic metrics); state 0: not yet, 1: prepared, 2: anisotropic.
  std::vector<FacetQuality3> prepared;
  std::vector<std::uint8_t> state;
  // Q_K by tetrahedron slot, NaN when unknown (relocate_sweep3's; null: computed each time).
  std::vector<double>* known = nullptr;
};

// try_relocate3 for a vertex whose ball is in s.ball (v free: is_free_vertex held).
bool relocate_free_vertex(Mesh3& mesh, std::uint32_t v, const MetricField3& field, const Relocate3Options& options,
                          RelocateScratch& s) {
  const std::vector<std::uint32_t>& ball = s.ball;
  std::vector<std::array<std::uint32_t, 3>>& facets = s.facets;
  facets.clear();
  s.quality.clear();
  double before = 0.0;
  std::size_t worst = 0;
  for (std::size_t k = 0; k < ball.size(); ++k) {
    facets.push_back(opposite_facet(mesh, ball[k], v));
    double q;
    if (s.known) {
      double& c = (*s.known)[ball[k]];
      if (std::isnan(c)) c = tetrahedron_quality(mesh, ball[k]);
      q = c;
    } else {
      q = tetrahedron_quality(mesh, ball[k]);
    }
    s.quality.push_back(q);
    if (q > before) {
      before = q;
      worst = k;
    }
  }
  // P* first; when no relaxation of it improves the ball, the ideal point of the worst
  // tetrahedron alone (the ball's worst is what the criterion asks to improve).
  const auto& fw = facets[worst];
  const Metric3 mw = mean_metric(mesh.metric(fw[0]), mesh.metric(fw[1]), mesh.metric(fw[2]));
  const std::array<Vec3, 2> targets{optimal_point_of(mesh, v, ball, s.quality, s.roots),
                                    ideal_apex(mesh.point(fw[0]), mesh.point(fw[1]), mesh.point(fw[2]), mw, s.roots)};
  const double bound = before * (1.0 - options.margin);
  const std::size_t n = facets.size();
  // A candidate is kept only when every new tetrahedron is positive and below the bound, so the
  // facets may be tested in any order: the one that refused the last candidate (a shorter step
  // toward the same target is usually refused by the same one) first, then the others in order.
  std::size_t first_flat = 0, first_worse = 0;
  auto index_at = [](std::size_t first, std::size_t k) { return k == 0 ? first : (k <= first ? k - 1 : k); };
  s.prepared.resize(n);
  s.state.assign(n, 0);
  const bool moved_v = relax_vertex(mesh, v, targets, options.tries, field, ball, [&](const Vec3& moved, const Metric3& metric) {
    const bool euclidean = metric.is_scalar();
    // The quality bound first, then the exact orientations: most candidates fail the bound
    // (early, on the facet that refused the last one), and a candidate is kept only when both
    // hold, so the order changes no decision. Q_K without the flatness test, as
    // positive_quality_in computes it (in isotropic metrics, the Euclidean value); of an
    // inverted candidate it is some finite or infinite value, and the orientation refuses it.
    // The ball's new worst is below the bound iff each new tetrahedron's Q_K is.
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t i = index_at(first_worse, j);
      const auto& f = facets[i];
      if (s.state[i] == 0) {
        const bool iso = mesh.metrics_all_scalar() || (mesh.metric(f[0]).is_scalar() && mesh.metric(f[1]).is_scalar() &&
                                                        mesh.metric(f[2]).is_scalar());
        if (iso) s.prepared[i] = FacetQuality3(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]));
        s.state[i] = iso ? 1 : 2;
      }
      const bool better = euclidean && s.state[i] == 1
                              ? s.prepared[i].with_apex(moved) < bound
                              : positive_quality_in(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), moved,
                                                    mesh.metric(f[0]), mesh.metric(f[1]), mesh.metric(f[2]), metric) < bound;
      if (!better) {
        first_worse = i;
        return false;
      }
    }
    for (std::size_t j = 0; j < n; ++j) {
      const auto& f = facets[index_at(first_flat, j)];
      if (orient3d(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), moved) != Sign::Positive) {
        first_flat = index_at(first_flat, j);
        return false;
      }
    }
    return true;
  });
  if (moved_v && s.known)
    for (const std::uint32_t t : ball) (*s.known)[t] = std::numeric_limits<double>::quiet_NaN();
  return moved_v;
}

}  // namespace

bool try_relocate3(Mesh3& mesh, std::uint32_t v, const MetricField3& field, const Relocate3Options& options) {
  // The buffers live across calls (the bad tetrahedra ask for thousands of relocations).
  thread_local RelocateScratch s;
  if (!is_free_vertex(mesh, v, s.ball)) return false;
  return relocate_free_vertex(mesh, v, field, options, s);
}

std::uint64_t relocate_sweep3(Mesh3& mesh, const MetricField3& field, const Relocate3Options& options) {
  return relocate_sweep(mesh, field, options, nullptr);
}

std::uint64_t optimize3d_detail::relocate_sweep(Mesh3& mesh, const MetricField3& field, const Relocate3Options& options,
                                                AttemptMemo* memo, Region region) {
  // Worst ball first (ties by vertex id): the classification of §8.6. One pass over the
  // tetrahedra gives every vertex's worst Q_K and what is_free_vertex asks of its ball (every
  // tetrahedron at it in the domain, with one reference, no constrained facet at it); the ball
  // of a vertex is every live tetrahedron holding it, so the values are those of the ball.
  const std::uint32_t nv = mesh.vertex_capacity();
  constexpr int kUnset = std::numeric_limits<int>::min();
  std::vector<double> worst(nv, 0.0);
  // Q_K of every tetrahedron, as the classification computes it; a relocation forgets its
  // ball's, and the next ball that needs one computes it again.
  std::vector<double> known(mesh.tetrahedron_capacity(), std::numeric_limits<double>::quiet_NaN());
  std::vector<int> ref(nv, kUnset);
  std::vector<std::uint8_t> locked(nv, 0);
  for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
    if (!mesh.is_alive(t)) continue;
    const auto tv = mesh.tetrahedron(t);
    const bool domain = mesh.in_domain(t);
    const double q = domain ? tetrahedron_quality(mesh, t) : 0.0;
    if (domain) known[t] = q;
    const int r = domain ? mesh.ref(t) : 0;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t w = tv[i];
      if (w >= nv) continue;  // the infinite vertex
      if (!domain) {
        locked[w] = 1;
        continue;
      }
      if (ref[w] == kUnset) {
        ref[w] = r;
      } else if (ref[w] != r) {
        locked[w] = 1;
      }
      worst[w] = std::max(worst[w], q);
      // A constrained facet i holds the three vertices other than tv[i].
      if (mesh.is_constrained(Mesh3::facet(t, i)))
        for (std::uint32_t j = 0; j < 4; ++j)
          if (j != i && tv[j] < nv) locked[tv[j]] = 1;
    }
  }
  std::vector<std::pair<double, std::uint32_t>> order;
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (mesh.is_dead_vertex(v) || locked[v] || ref[v] == kUnset) continue;
    if ((mesh.flags(v) & (Mesh3::kFixed | Mesh3::kOnBoundary)) != 0 || !in_region(region, v)) continue;
    order.emplace_back(worst[v], v);
  }
  std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) {
    return x.first > y.first || (x.first == y.first && x.second < y.second);
  });
  std::uint64_t moved = 0;
  RelocateScratch s;
  s.known = &known;
  // Mesh3::ball's breadth-first search, in its order (the sums over the ball keep their bits),
  // with a stamp per tetrahedron for "seen" instead of a search of the list.
  std::vector<std::uint32_t> seen(mesh.tetrahedron_capacity(), 0);
  std::uint32_t stamp = 0;
  for (const auto& entry : order) {
    // Relocation changes no topology: the vertex is still free; its ball is fetched once.
    const std::uint32_t v = entry.second;
    // Its ball (topology, positions, metrics) unchanged since it failed: it fails again.
    if (memo && memo->relocation.failed_since(v, mesh.changed_at(v))) continue;
    ++stamp;
    nav3::ball(mesh, v, mesh.vertex_tetrahedron(v), s.ball, nav3::marking(seen, stamp));
    if (relocate_free_vertex(mesh, v, field, options, s)) {
      ++moved;
    } else if (memo) {
      memo->relocation.record(v, mesh.new_epoch());
    }
  }
  return moved;
}

}  // namespace dtlab
