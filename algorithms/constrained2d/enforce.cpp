// Segment insertion shared by every constrained method. First every crossing of the input
// segments, found at once and snap rounded (crossings.hpp): its correctly rounded point inserted
// and each segment split at the hot points it meets. Then each piece is walked along its pipe
// (book §1.7) and enforced by edge swaps (§3.3.3; Sloan, "A fast algorithm for generating
// constrained Delaunay triangulations", 1993: the crossed edges in a queue, each swapped when
// its quadrilateral is strictly convex, requeued while it still crosses). A vertex exactly on a
// piece splits it; a piece along an edge already constrained is an overlap (collinear segments);
// a crossed constrained edge (which snap rounding should leave none of) is split at the
// correctly rounded exact intersection (kernel/rounding.hpp), a bounded fallback.
#include <algorithm>
#include <cstdio>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/constrained2d/context.hpp"
#include "algorithms/constrained2d/crossings.hpp"
#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "kernel/rounding.hpp"

namespace dtlab {

namespace {

constexpr std::uint32_t kNone = ConstrainedMesh2::kNone;

struct Piece {
  std::uint32_t a, b, segment;
};

std::string point_text(const Vec2& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
  return buf;
}

// Swaps the edges crossing the open segment s-q (none constrained, no vertex on it) until sq is
// an edge; returns its half-edge s -> q. Sloan's queue, or (rng given) a random crossed edge
// each time: some crossed edge is always flippable, so a full round of the queue (or as many
// random draws, then a scan) without a flip means a broken invariant.
std::uint32_t enforce_by_swaps(ConstrainedMesh2& mesh, std::uint32_t s, std::uint32_t q,
                               const std::vector<std::uint32_t>& crossed, std::uint64_t* rng) {
  if (!crossed.empty()) {
    Triangulation2& tri = mesh.tri();
    // A crossed edge by its vertices, with the half-edge it had when queued: still valid unless
    // a flip rewrote its triangle (checked), else looked up again.
    struct Crossed {
      std::uint32_t u, v, h;
    };
    const auto half_edge = [&](const Crossed& e) {
      return tri.origin(e.h) == e.u && tri.destination(e.h) == e.v ? e.h : mesh.find_half_edge(e.u, e.v);
    };
    std::deque<Crossed> queue;
    for (const std::uint32_t h : crossed) queue.push_back({tri.origin(h), tri.destination(h), h});
    const Vec2& S = mesh.point(s);
    const Vec2& Q = mesh.point(q);
    const std::uint64_t k = crossed.size();
    const std::uint64_t bound = 4 * k * (k + 1) + 16;
    std::uint64_t flips = 0;
    std::size_t idle = 0;
    const auto cannot = [&] {
      return InternalError("edge swapping: no crossed edge of segment " + std::to_string(s) + "-" + std::to_string(q) +
                           " can be swapped");
    };
    while (!queue.empty()) {
      if (rng) {  // a random crossed edge to the front; after a fruitless round, the first flippable one
        std::uint64_t& x = *rng;  // xorshift64
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        std::size_t pick = static_cast<std::size_t>(x % queue.size());
        if (idle > queue.size()) {
          pick = queue.size();
          for (std::size_t i = 0; i < queue.size() && pick == queue.size(); ++i)
            if (mesh.flippable(half_edge(queue[i]))) pick = i;
          if (pick == queue.size()) throw cannot();
        }
        std::swap(queue.front(), queue[pick]);
      }
      Crossed e = queue.front();
      queue.pop_front();
      e.h = half_edge(e);
      DTLAB_ASSERT(e.h != kNone && mesh.constraint(e.h) == kNone);
      if (!mesh.flippable(e.h)) {
        queue.push_back(e);
        if (++idle > queue.size() && !rng) throw cannot();
        continue;
      }
      idle = 0;
      if (++flips > bound)
        throw InternalError("edge swapping for segment " + std::to_string(s) + "-" + std::to_string(q) +
                            " exceeded its bound of " + std::to_string(bound) + " swaps");
      const std::uint32_t f = mesh.flip(e.h);
      const std::uint32_t c = tri.origin(f), d = tri.destination(f);
      if (c == s || c == q || d == s || d == q) continue;
      const Sign sc = orient2d(S, Q, mesh.point(c));
      const Sign sd = orient2d(S, Q, mesh.point(d));
      if (sc != Sign::Zero && sd != Sign::Zero && sc != sd) queue.push_back({c, d, f});
    }
  }
  const std::uint32_t h = mesh.find_half_edge(s, q);
  DTLAB_ASSERT(h != kNone);
  return h;
}

// x (on the line ab) strictly between a and b, exactly.
bool strictly_inside(const ExactPoint2& x, const Vec2& a, const Vec2& b) {
  if (a.x != b.x) {
    const Rational lo(std::min(a.x, b.x)), hi(std::max(a.x, b.x));
    return lo < x.x && x.x < hi;
  }
  const Rational lo(std::min(a.y, b.y)), hi(std::max(a.y, b.y));
  return lo < x.y && x.y < hi;
}

}  // namespace

namespace {

// The state of one resolution: the mesh, the bounds and what was inserted.
class SegmentResolver {
 public:
  explicit SegmentResolver(const Constrained2dContext& context)
      : context_(context),
        mesh_(context.mesh),
        result_(context.result),
        input_points_(context.result.input_point_count),
        max_crossings_(bound_crossings(context.segments.size())),
        rng_((context.options.seed ^ 0x5A5A'0F0F'C3C3'9696ull) | 1) {}

  // The fast path: each segment walked and enforced in input order, split where it meets a
  // vertex, an overlap or a crossing at a double point. Returns false at the first crossing
  // that is not a double point (chains would bend, and only snapping them all keeps them
  // apart), having changed the mesh (swaps, and the exact crossing points, which stay Steiner
  // vertices) but no constraint, and of the messages only those naming these points.
  bool enforce_without_rounding() {
    const std::size_t messages = result_.messages.size(), message_count = result_.message_count;
    std::vector<Piece> pieces;
    pieces.reserve(context_.segments.size());
    for (std::size_t k = 0; k < context_.segments.size(); ++k)
      pieces.push_back({context_.segments[k][0], context_.segments[k][1], context_.ids[k]});
    fast_path_ = true;
    const bool done = enforce(pieces, false);
    fast_path_ = false;
    if (done) return true;
    mesh_.clear_constraints();
    result_.messages.resize(messages);
    result_.message_count = message_count;
    for (std::string& note : steiner_notes_) context_.note(std::move(note));
    return false;
  }

  // Every crossing snap rounded (crossings.hpp), then each segment enforced piece by piece
  // between its stops.
  void snap_and_enforce() {
    const SnappedCrossings snapped = snap_crossings(mesh_, context_.segments);
    std::vector<std::uint32_t> hot_vertex(snapped.hot.size(), kNone);
    for (std::size_t i = 0; i < snapped.hot.size(); ++i) hot_vertex[i] = insert_hot(snapped.hot[i]);

    // Every segment split at its stops: the vertices exactly on it (its pipe, §1.7) and the hot
    // points it meets.
    std::vector<Piece> pieces;
    std::vector<std::pair<Vec2, std::uint32_t>> stops;
    for (std::size_t k = 0; k < context_.segments.size(); ++k) {
      const auto [a, b] = context_.segments[k];
      stops.clear();
      for (std::uint32_t i = snapped.first[k]; i < snapped.first[k + 1]; ++i) {
        const std::uint32_t stop = snapped.stops[i];
        const std::uint32_t v = stop & SnappedCrossings::kHot ? hot_vertex[stop & ~SnappedCrossings::kHot] : stop;
        if (v == a || v == b) continue;
        if (v < input_points_)
          context_.note("segment " + context_.number(context_.ids[k]) + " passes through vertex " + context_.number(v) +
                        ": split there");
        stops.emplace_back(mesh_.point(v), v);
      }
      std::uint32_t from = a;
      for (const std::uint32_t v : order_along_segment(mesh_.point(a), mesh_.point(b), stops)) {
        pieces.push_back({from, v, context_.ids[k]});
        from = v;
      }
      pieces.push_back({from, b, context_.ids[k]});
    }
    enforce(pieces, true);
  }

 private:
  // Bounds: s segments cross at most s(s-1)/2 times; rounding bends add a few.
  static std::uint64_t bound_crossings(std::uint64_t segments) {
    return segments * (segments - (segments > 0)) / 2 + 16 * segments + 16;
  }

  // A snapped crossing's vertex: an existing one at its point (an input vertex, or a crossing
  // the fast path inserted), or a new Steiner vertex.
  std::uint32_t insert_hot(const SnappedCrossings::Hot& hot) {
    const std::uint32_t j = context_.ids[hot.s], k = context_.ids[hot.t];
    const Vec2 x = hot.point;
    if (!coordinate_in_range(x.x) || !coordinate_in_range(x.y))
      throw InputError("segments " + context_.number(j) + " and " + context_.number(k) +
                           " cross at a point outside the supported coordinate range " + point_text(x),
                       {j, k});
    if (!within_rounding_bound(hot.exact, x)) ++result_.rounding_checks_failed;
    const ConstrainedMesh2::Location where = mesh_.locate(x, mesh_.triangle_of_vertex(context_.segments[hot.s][0]));
    if (where.where == ConstrainedMesh2::Where::Vertex) {
      // An input vertex, or a crossing the fast path inserted (counted and named then).
      if (where.handle < input_points_)
        context_.note("segments " + context_.number(j) + " and " + context_.number(k) + " cross at vertex " +
                      context_.number(where.handle) + (hot.exact_double ? "" : " (their intersection rounds to it)"));
      return where.handle;
    }
    const std::uint32_t w = mesh_.insert(x, where);
    steiner_at_.emplace(std::pair{hot.exact.x, hot.exact.y}, w);
    ++result_.crossing_steiner_points;
    context_.note("segments " + context_.number(j) + " and " + context_.number(k) + " cross: Steiner vertex " +
                  context_.number(w) + " at " + point_text(x) +
                  (hot.exact_double ? " (exact)" : " (rounded; the pieces bend there by at most ulp/2)"));
    return w;
  }

  // Walks and enforces the pieces (a stack: a piece split at a vertex or crossing pushes its
  // parts). A crossing of two constrained chains: split both at the correctly rounded exact
  // point; without `rounding`, return false instead where that point is not a double.
  bool enforce(const std::vector<Piece>& pieces, bool rounding) {
    std::vector<Piece> stack;
    for (const Piece& piece : pieces) {
      stack.push_back(piece);
      while (!stack.empty()) {
        const Piece p = stack.back();
        stack.pop_back();
        if (p.a == p.b) continue;
        // A step finishes a piece, splits it at a vertex exactly on it (at most once per vertex
        // and piece) or at a crossing: bounded by pieces x vertices, a guard against looping.
        if (++steps_ > (pieces.size() + 2 * crossings_ + 4) * (std::uint64_t{mesh_.vertex_count()} + 16))
          throw InternalError("segment resolution did not converge (at segment " + context_.number(p.segment) + ")");
        const ConstrainedMesh2::SegmentWalk walk = mesh_.walk(p.a, p.b);
        const auto hit = std::find_if(walk.crossed.begin(), walk.crossed.end(),
                                      [&](std::uint32_t h) { return mesh_.constraint(h) != kNone; });
        if (hit == walk.crossed.end()) {
          const std::uint32_t h =
              enforce_by_swaps(mesh_, p.a, walk.stop, walk.crossed, context_.options.random_swaps ? &rng_ : nullptr);
          const std::uint32_t existing = mesh_.add_constraint(h, p.segment);
          if (existing != kNone && existing != p.segment) {
            context_.note("segments " + context_.number(existing) + " and " + context_.number(p.segment) +
                          " overlap along edge " + context_.number(p.a) + "-" + context_.number(walk.stop) +
                          "; the edge is constrained by both (its marker is segment " +
                          context_.number(std::min(existing, p.segment)) + "'s)");
          }
          if (walk.stop != p.b) {
            if (walk.stop < input_points_)
              context_.note("segment " + context_.number(p.segment) + " passes through vertex " +
                            context_.number(walk.stop) + ": split there");
            stack.push_back({walk.stop, p.b, p.segment});
          }
          continue;
        }
        if (!split_crossing(p, *hit, rounding, stack)) return false;
      }
    }
    return true;
  }

  // Piece p crosses the constrained edge h (segment j): both split at their crossing.
  bool split_crossing(const Piece& p, std::uint32_t h, bool rounding, std::vector<Piece>& stack) {
    Triangulation2& tri = mesh_.tri();
    const std::uint32_t u = tri.origin(h), v = tri.destination(h), j = mesh_.constraint(h);
    if (++crossings_ > max_crossings_)
      throw InternalError("segment resolution: more crossings than segments allow (segments " + context_.number(j) +
                          " and " + context_.number(p.segment) + ")");
    // The exact point: where the two INPUT segments meet, so that every crossing of the same two
    // segments, and every segment through the same exact point, finds the same vertex. Only if
    // that point is not strictly inside both input segments (their chains crossing where the
    // segments do not, after bends of an ulp) are the two pieces' lines used.
    const auto& si = context_.input_segment(p.segment);
    const auto& sj = context_.input_segment(j);
    std::optional<ExactPoint2> exact = line_intersection_exact(mesh_.point(si[0]), mesh_.point(si[1]),
                                                               mesh_.point(sj[0]), mesh_.point(sj[1]));
    bool bent = false;
    if (!exact || !strictly_inside(*exact, mesh_.point(si[0]), mesh_.point(si[1])) ||
        !strictly_inside(*exact, mesh_.point(sj[0]), mesh_.point(sj[1]))) {
      exact = line_intersection_exact(mesh_.point(p.a), mesh_.point(p.b), mesh_.point(u), mesh_.point(v));
      bent = true;
    }
    DTLAB_ASSERT(exact.has_value());  // the walk saw u and v strictly on either side of ab
    RoundedPoint2 rounded = round_point_checked(*exact);
    if (!rounded.exact && !rounding) return false;
    Vec2 x = rounded.point;
    if (!coordinate_in_range(x.x) || !coordinate_in_range(x.y))
      throw InputError("segments " + context_.number(j) + " and " + context_.number(p.segment) +
                           " cross at a point outside the supported coordinate range " + point_text(x),
                       {j, p.segment});
    // An existing vertex at the crossing: the one made for the same exact point (the same two
    // input segments), or one the rounded point falls on.
    auto known = steiner_at_.end();
    std::optional<std::uint32_t> found;
    const auto look_up = [&] {
      known = steiner_at_.find({exact->x, exact->y});
      found.reset();
      if (known != steiner_at_.end()) {
        found = known->second;
      } else if (const ConstrainedMesh2::Location where = mesh_.locate(x, Triangulation2::triangle_of(h));
                 where.where == ConstrainedMesh2::Where::Vertex) {
        found = where.handle;
      }
    };
    look_up();
    // The vertex of the two input segments' crossing may be an end of the crossed edge that
    // lies outside the piece (not strictly between its ends along it, order_along_segment): the chains, bent by an ulp near it, cross again
    // a few ulps away, and p's chain, routed back through that vertex, which it passed already,
    // would loop and step back along its segment. The pieces' own crossing is taken instead.
    // (A vertex of the input crossing that is no end of the crossed edge is kept even where it
    // lies outside the piece: replacing it makes the two chains cross again and again.)
    if (found && !bent && (*found == u || *found == v) &&
        order_along_segment(mesh_.point(p.a), mesh_.point(p.b), {{mesh_.point(*found), *found}}).empty()) {
      exact = line_intersection_exact(mesh_.point(p.a), mesh_.point(p.b), mesh_.point(u), mesh_.point(v));
      DTLAB_ASSERT(exact.has_value());
      bent = true;
      rounded = round_point_checked(*exact);
      x = rounded.point;
      look_up();
    }
    if (!within_rounding_bound(*exact, x)) ++result_.rounding_checks_failed;
    std::uint32_t w;
    if (found) {
      w = *found;
      if (known == steiner_at_.end())
        context_.note("segments " + context_.number(j) + " and " + context_.number(p.segment) + " cross at vertex " +
                      context_.number(w) + (rounded.exact ? "" : " (their intersection rounds to it)"));
    } else {
      const ConstrainedMesh2::Location where = mesh_.locate(x, Triangulation2::triangle_of(h));
      w = mesh_.insert(x, where);
      steiner_at_.emplace(std::pair{exact->x, exact->y}, w);
      ++result_.crossing_steiner_points;
      if (bent) result_.bent_crossings.push_back({w, {p.segment, j}, {p.a, p.b, u, v}});
      std::string note = "segments " + context_.number(j) + " and " + context_.number(p.segment) +
                         " cross: Steiner vertex " + context_.number(w) + " at " + point_text(x) +
                         (rounded.exact ? " (exact)" : " (rounded; the pieces bend there by at most ulp/2)");
      if (fast_path_) steiner_notes_.push_back(note);
      context_.note(std::move(note));
    }
    // Process order (a stack): first segment j's chain through w, then p's.
    stack.push_back({w, p.b, p.segment});
    stack.push_back({p.a, w, p.segment});
    if (w != u && w != v) {
      const std::uint32_t e = mesh_.find_half_edge(u, v);
      if (e != kNone && mesh_.constraint(e) == j) {  // not split by the insertion: reroute through w
        std::vector<std::uint32_t> segments = mesh_.shared_segments(e);
        segments.push_back(j);
        mesh_.set_constraint(e, kNone);
        for (const std::uint32_t s : segments) {
          stack.push_back({w, v, s});
          stack.push_back({u, w, s});
        }
      }
    }
    return true;
  }

  const Constrained2dContext& context_;
  ConstrainedMesh2& mesh_;
  Constrained2dResult& result_;
  const std::uint32_t input_points_;
  const std::uint64_t max_crossings_;
  std::uint64_t crossings_ = 0, steps_ = 0;
  std::uint64_t rng_;  // random swap order (xorshift64)
  std::map<std::pair<Rational, Rational>, std::uint32_t> steiner_at_;  // exact crossing -> its vertex
  bool fast_path_ = false;
  std::vector<std::string> steiner_notes_;  // the fast path's crossing points, named
};

}  // namespace

void resolve_and_enforce_segments(const Constrained2dContext& context) {
  SegmentResolver resolver(context);
  if (!resolver.enforce_without_rounding()) resolver.snap_and_enforce();
}

}  // namespace dtlab
