// Field points by advancing-front placement in the Delaunay framework (book §5.8 / §7.8): Rebay's
// frontal-Delaunay method (J. Comput. Phys. 106, 1993) in the metric's unit space, as Mavriplis
// (J. Comput. Phys. 117, 1995) takes it to stretched meshes, each point inserted at once by the
// Delaunay kernel (Frey, Borouchaki, George, CMAME 157, 1998). The front: the edges between a
// non-accepted domain triangle and an accepted one or a constrained edge; from the shortest, the apex
// of the unit equilateral triangle, clamped inside the circumcircle, filtered as the edge method does.
// Ours: a triangle whose front edges all fail is settled, and the front moves past it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <string>
#include <vector>

#include "algorithms/mesh2d/delaunay_kernel.hpp"
#include "algorithms/mesh2d/mesh2d.hpp"
#include "kernel/error.hpp"
#include "kernel/interrupt.hpp"
#include "kernel/quality.hpp"

namespace dtlab {

namespace {

// A triangle is accepted when every edge is at most split_length in the metric and its shape
// quality in the vertex metrics is at most this (the right isosceles triangle has Q = 1.39: it
// passes; worse shapes get points from their front edges).
constexpr double kAcceptedQuality = 1.5;
// The circumradius of the unit equilateral triangle, Rebay's optimal radius in the unit space.
constexpr double kUnitCircumradius = 0.57735026918962576451;  // 1 / sqrt(3)
// A clamped point sits this fraction of the way to the far side of the circumcircle, strictly
// inside it, so that the triangle it was placed for is in conflict with it.
constexpr double kInsideCircumcircle = 0.98;
// Heap pops per live vertex before the loop is declared runaway (each insertion pushes the edges
// of its ball, about 18 half-edges; each wave the whole front once).
constexpr std::uint64_t kStepsPerVertex = 1024;

struct FrontEdge {
  double length;         // metric length of the edge (vertex metrics)
  std::uint32_t a, b;    // its ends, a -> b with the non-accepted triangle on the left
  std::uint32_t h;       // the half-edge in the non-accepted triangle
  std::uint64_t gen;     // that triangle's generation when pushed (stale entries are dropped)
};

// Shortest first, then by ids: deterministic, and the finest parts of the front advance first, so
// that sizes grow outwards from small boundary pieces rather than large fronts overrunning them.
struct LongerFirst {
  bool operator()(const FrontEdge& x, const FrontEdge& y) const {
    if (x.length != y.length) return x.length > y.length;
    if (x.a != y.a) return x.a > y.a;
    if (x.b != y.b) return x.b > y.b;
    return x.gen > y.gen;
  }
};

// Active: not accepted, to be given points. Accepted: good in size and shape. Settled: active, but
// every front edge of it failed (its point filtered or outside): the front passes it by, as if it
// were accepted, so that it reaches every triangle, even beside a boundary cut coarser than the
// size, where no triangle can be accepted.
enum State : std::uint8_t { kActive = 0, kAccepted = 1, kSettled = 2 };

class Front {
 public:
  Front(Mesh2& mesh, const ControlSpace2& control, const Mesh2dOptions& options, Mesh2dStats& stats)
      : mesh_(mesh), control_(control), options_(options), stats_(stats), kernel_(mesh) {}

  void run() {
    for (std::uint32_t t = 0; t < mesh_.triangle_capacity(); ++t) classify(t);
    for (std::uint32_t wave = 0;; ++wave) {
      poll_interrupt(options_.interrupt, "mesh2d: during the field points (advancing front)");
      if (wave == options_.max_passes) {
        throw InputError("mesh2d: the advancing front did not settle within " + std::to_string(options_.max_passes) +
                         " waves (" + std::to_string(stats_.field_points) + " field points so far)");
      }
      // A new wave retries every triangle given up on: the mesh around it has changed.
      tried_.assign(3 * static_cast<std::size_t>(mesh_.triangle_capacity()), 0);
      for (std::uint32_t t = 0; t < mesh_.triangle_capacity(); ++t) {
        if (state_[t] == kSettled) state_[t] = kActive;
      }
      for (std::uint32_t t = 0; t < mesh_.triangle_capacity(); ++t) {
        if (!mesh_.in_domain(t) || state_[t] != kActive) continue;
        for (std::uint32_t i = 0; i < 3; ++i) push_if_front(Mesh2::half_edge(t, i));
      }
      const std::uint64_t inserted = advance();
      stats_.field_points += inserted;
      stats_.passes = wave + 1;
      if (inserted == 0) break;
    }
    stats_.cavity_corrections += kernel_.corrections();
  }

 private:
  bool is_accepted(std::uint32_t t) const {
    const std::uint32_t v[3] = {mesh_.vertex(t, 0), mesh_.vertex(t, 1), mesh_.vertex(t, 2)};
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t a = v[i], b = v[(i + 1) % 3];
      if (edge_length(mesh_.point(a), mesh_.metric(a), mesh_.point(b), mesh_.metric(b)) > options_.split_length) return false;
    }
    return shape_quality(mesh_.point(v[0]), mesh_.point(v[1]), mesh_.point(v[2]), mesh_.metric(v[0]), mesh_.metric(v[1]),
                         mesh_.metric(v[2])) <= kAcceptedQuality;
  }

  // A new generation for slot t (a new triangle there), with its class.
  void classify(std::uint32_t t) {
    if (state_.size() < mesh_.triangle_capacity()) {
      state_.resize(mesh_.triangle_capacity(), kActive);
      generation_.resize(mesh_.triangle_capacity(), 0);
      tried_.resize(3 * static_cast<std::size_t>(mesh_.triangle_capacity()), 0);
    }
    generation_[t] = ++last_generation_;
    state_[t] = mesh_.in_domain(t) && is_accepted(t) ? kAccepted : kActive;
  }

  // h's triangle is an active domain triangle and across h lies an accepted or settled one, a
  // constrained edge or the exterior.
  bool is_front(std::uint32_t h) const {
    const std::uint32_t t = Mesh2::triangle_of(h);
    if (!mesh_.in_domain(t) || state_[t] != kActive) return false;
    const std::uint32_t u = Mesh2::triangle_of(mesh_.twin(h));
    return mesh_.is_constrained(h) || !mesh_.in_domain(u) || state_[u] != kActive;
  }

  // Every front edge of t failed: t joins the settled side, and the front moves past it to its
  // active neighbours.
  void settle_if_done(std::uint32_t t) {
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      if (is_front(h) && tried_[h] != generation_[t]) return;  // still queued
    }
    state_[t] = kSettled;
    for (std::uint32_t i = 0; i < 3; ++i) push_if_front(mesh_.twin(Mesh2::half_edge(t, i)));
  }

  void push_if_front(std::uint32_t h) {
    const std::uint32_t t = Mesh2::triangle_of(h);
    if (!is_front(h) || tried_[h] == generation_[t]) return;
    const std::uint32_t a = mesh_.origin(h), b = mesh_.destination(h);
    queue_.push({edge_length(mesh_.point(a), mesh_.metric(a), mesh_.point(b), mesh_.metric(b)), a, b, h, generation_[t]});
  }

  // Rebay's point for front edge h in the metric m: in m's unit space, on the bisector at height
  // d = rho + sqrt(rho^2 - p^2), rho = max(1/sqrt3, p) (p the half length), at most
  // kInsideCircumcircle of the way to the far point of the circumcircle of h's triangle.
  // False when that triangle is flat in m (no side to place on).
  bool place(std::uint32_t h, const Metric2& m, Vec2& out) const {
    const Vec2 pa = mesh_.point(mesh_.origin(h)), pb = mesh_.point(mesh_.destination(h));
    const Vec2 pc = mesh_.point(mesh_.vertex_at(h));
    const Vec2 mid = 0.5 * (pa + pb);
    const Metric2 sqrt_m = power(m, 0.5), inv_sqrt_m = power(m, -0.5);
    const Vec2 e = transform(sqrt_m, pb - pa);
    const double length = norm(e);
    if (!(length > 0.0)) return false;
    const Vec2 normal{-e.y / length, e.x / length};  // left of a -> b: towards the triangle
    const Vec2 c = transform(sqrt_m, pc - mid);
    const double p = 0.5 * length;
    const double c_height = dot(normal, c);
    if (!(c_height > 0.0)) return false;
    // Circumcentre of (-e/2, e/2, c) at k * normal: |k n - c|^2 = p^2 + k^2.
    const double k = (dot(c, c) - p * p) / (2.0 * c_height);
    const double far_side = k + std::sqrt(p * p + k * k);
    const double rho = std::max(kUnitCircumradius, p);
    const double height = std::min(rho + std::sqrt(std::max(0.0, rho * rho - p * p)), kInsideCircumcircle * far_side);
    if (!(height > 0.0)) return false;
    out = mid + transform(inv_sqrt_m, height * normal);
    return std::isfinite(out.x) && std::isfinite(out.y);
  }

  // The point for front edge h, in the metric at the edge's midpoint.
  bool ideal_point(std::uint32_t h, Vec2& out) {
    const Vec2 mid = 0.5 * (mesh_.point(mesh_.origin(h)) + mesh_.point(mesh_.destination(h)));
    return place(h, control_.metric_at(mid, hint_), out);
  }

  // The smallest metric distance (in mp) from p to a constrained edge of t or of its neighbours.
  // The filter holds it to filter_distance as it holds the nearest vertex: a point clamped inside
  // a flat circumcircle would otherwise lie next to a long boundary edge, making a sliver on it.
  double nearest_constraint(const Vec2& p, const Metric2& mp, std::uint32_t t) const {
    double best = std::numeric_limits<double>::infinity();
    const auto visit = [&](std::uint32_t u) {
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t g = Mesh2::half_edge(u, i);
        if (!mesh_.is_constrained(g)) continue;
        const Vec2 a = mesh_.point(mesh_.origin(g)), b = mesh_.point(mesh_.destination(g));
        const Vec2 ab = b - a;
        // The nearest point of the segment in mp's inner product.
        const double ab2 = mp.length(ab) * mp.length(ab);
        const Vec2 ap = p - a;
        const double cross = mp.m[0] * ap.x * ab.x + mp.m[1] * (ap.x * ab.y + ap.y * ab.x) + mp.m[2] * ap.y * ab.y;
        const double s = ab2 > 0.0 ? std::clamp(cross / ab2, 0.0, 1.0) : 0.0;
        best = std::min(best, mp.length(p - (a + s * ab)));
      }
    };
    visit(t);
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t u = Mesh2::triangle_of(mesh_.twin(Mesh2::half_edge(t, i)));
      if (mesh_.in_domain(u)) visit(u);
    }
    return best;
  }

  // Tries one front edge; true when a point was inserted.
  bool try_edge(std::uint32_t h) {
    const std::uint32_t t = Mesh2::triangle_of(h);
    Vec2 p;
    if (!ideal_point(h, p)) {
      ++stats_.not_inserted;
      return false;
    }
    // The walk stops at constrained edges: a point across one would not open this triangle.
    const Mesh2::Location loc = mesh_.locate(p, t, true);
    if (loc.blocked || loc.where == Mesh2::Where::Outside || loc.where == Mesh2::Where::Vertex ||
        !mesh_.in_domain(loc.triangle)) {
      ++stats_.not_inserted;
      return false;
    }
    const Metric2 mp = control_.metric_at(p, hint_);
    if (!kernel_.find_cavity(p, mp, loc.triangle)) {
      ++stats_.not_inserted;
      return false;
    }
    if (kernel_.nearest_cavity_vertex(p, mp) < options_.filter_distance ||
        nearest_constraint(p, mp, loc.triangle) < options_.filter_distance) {
      ++stats_.filtered;
      return false;
    }
    if (mesh_.live_vertex_count() >= options_.max_vertices) {
      throw InputError("mesh2d: the mesh reached the vertex bound of " + std::to_string(options_.max_vertices) +
                       " (is the size far smaller than the domain?)");
    }
    kernel_.commit(p, mp);
    const std::vector<std::uint32_t>& ball = kernel_.ball();
    for (const std::uint32_t u : ball) classify(u);
    for (const std::uint32_t u : ball) {
      for (std::uint32_t i = 0; i < 3; ++i) push_if_front(Mesh2::half_edge(u, i));
      // Edge 0 lies on the cavity's boundary: an accepted ball triangle puts its neighbour on the front.
      if (state_[u] != kActive) push_if_front(mesh_.twin(Mesh2::half_edge(u, 0)));
    }
    return true;
  }

  std::uint64_t advance() {
    std::uint64_t inserted = 0;
    while (!queue_.empty()) {
      if (++steps_ > kStepsPerVertex * (static_cast<std::uint64_t>(mesh_.live_vertex_count()) + 1)) {
        throw InputError("mesh2d: the advancing front did not end within " + std::to_string(steps_ - 1) + " steps (" +
                         std::to_string(stats_.field_points + inserted) + " field points so far)");
      }
      const FrontEdge f = queue_.top();
      queue_.pop();
      const std::uint32_t t = Mesh2::triangle_of(f.h);
      if (!mesh_.in_domain(t) || generation_[t] != f.gen || tried_[f.h] == f.gen || !is_front(f.h)) continue;
      DTLAB_ASSERT(mesh_.origin(f.h) == f.a && mesh_.destination(f.h) == f.b);
      tried_[f.h] = f.gen;
      if (try_edge(f.h)) {
        ++inserted;
      } else {
        settle_if_done(t);
      }
    }
    return inserted;
  }

  Mesh2& mesh_;
  const ControlSpace2& control_;
  const Mesh2dOptions& options_;
  Mesh2dStats& stats_;
  DelaunayKernel2 kernel_;
  std::priority_queue<FrontEdge, std::vector<FrontEdge>, LongerFirst> queue_;
  std::vector<State> state_;               // per triangle slot
  std::vector<std::uint64_t> generation_;  // per triangle slot: bumped for each new triangle there
  std::vector<std::uint64_t> tried_;       // per half-edge: the generation it was tried in, this wave
  std::uint64_t last_generation_ = 0;
  std::uint64_t steps_ = 0;
  std::uint32_t hint_ = ControlSpace2::kNoHint;
};

}  // namespace

void insert_front_points(Mesh2& mesh, const ControlSpace2& control, const Mesh2dOptions& options, Mesh2dStats& stats) {
  Front(mesh, control, options, stats).run();
}

}  // namespace dtlab
