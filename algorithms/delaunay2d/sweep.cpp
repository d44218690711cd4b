// Variant "sweep": Sinclair's sweep-hull (s-hull, 2010) closed by Lawson flips (Lawson 1977).
// Points go in by increasing distance from a centre (sweep_order.hpp), so each lies
// strictly outside the hull of those before it; it is joined to the chain of hull edges it
// strictly sees, then the edges opposite it are flipped until locally Delaunay under
// incircle_perturbed. That is the Delaunay kernel with ghosts, grown by flips, so the result is
// the perturbed Delaunay triangulation every variant shares. A hash of hull vertices by angle
// around the centre (as in Delaunator) finds a visible edge; exact orient2d decides it.
//
// Why radial and not lexicographic: the lexicographic sweep (also exact: the largest point is a
// hull vertex) keeps the hull of a half-plane of points, whose long edges over a flat front leave
// fans of skinny triangles; on a grid each new point flips about sqrt(n) of them (measured:
// 310 incircle tests per point on a 10^5 grid), Theta(n^1.5) in all.
// Cocircular points: the perturbed triangulation (perturbation.hpp) cuts off the lexicographically
// largest point as an ear, then the next, so points added in increasing (x, y) order each join as
// an ear without a flip, and points added against it rebuild a fan each time (quadratic: 68 s for
// 2*10^4 exact_circle points, when the centre was the bounding box's middle, a rounding away from
// the circle's, and the sweep ran round the circle from one side). The centre is therefore the
// circumcentre of a seed triangle, correctly rounded (sweep_order.hpp): on a circle whose centre is
// a pair of doubles every point ties and ties go in (x, y) order. Cocircular input whose centre is
// not a double keeps the quadratic case: the distances to the rounded centre order the points
// round the circle from the side the rounding points to, against (x, y) order unless that is the
// leftmost point, and near-ties may not be reordered (a point nearer by a rounding may lie inside
// the hull of one behind it). Measured: 19,683 integer points on the circle of centre (1, 4/3)
// through (2, 0): 32 s and 97 million in-circle tests (incremental: 0.17 s).
// Slow case that remains (the Delaunay triangulation of each prefix must be kept, and a fixed
// order cannot avoid it as a random one does): collinear runs swept along their line (each new end
// point takes over the fan of a neighbouring run: ~530 incircle tests per point on the
// "collinear" set of 10^5). On "circle" the seed's circumcentre is off the circle's (by the
// points' rounding over the seed's spacing squared), so the points run round the circle from one
// side until the hull holds the centre; each new point faces a chord across the circle, and the
// in-circle tests on such spread, near-cocircular quadruples need the exact stage (about one per
// point: 3x incremental's time at 10^6).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "algorithms/delaunay2d/prepare.hpp"
#include "algorithms/delaunay2d/sweep_order.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

namespace {

constexpr std::uint32_t kInf = Triangulation2::kInfinite;
constexpr std::uint32_t kNext[3] = {1, 2, 0};
constexpr std::uint32_t kPrev[3] = {2, 0, 1};

constexpr std::uint32_t next_of(std::uint32_t h) noexcept { return Triangulation2::next(h); }
constexpr std::uint32_t prev_of(std::uint32_t h) noexcept { return Triangulation2::prev(h); }

// The sweep engine, on raw views of the triangulation's arrays (sized once for the final 2m - 2
// triangles) and on the points in sweep order: vertex ids are sweep ranks while it runs.
//
// The hull is read through the ghosts: ghost G = (inf, b, a) stands for hull edge a -> b; its
// edge 2 (inf -> b) is twin to edge 1 (b -> inf) of the ghost of the next hull edge b -> c.
// hull_out_[v] is the ghost of the hull edge leaving v, or kNone once v is inside the hull.
class SweepHull {
 public:
  SweepHull(const Vec2* points, std::size_t point_count, std::uint32_t* vertices, std::uint32_t* neighbours,
            std::size_t capacity, const Vec2& center)
      : p_(points),
        v_(vertices),
        n_(neighbours),
        capacity_(capacity),
        center_(center),
        hull_out_(point_count, kNone),
        hash_(std::max<std::size_t>(16, static_cast<std::size_t>(std::sqrt(static_cast<double>(point_count)))),
              kNone) {
    stack_.reserve(64);
  }

  // The first triangle (a, b, c), counter-clockwise, and its three ghosts.
  void start(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const std::uint32_t v[3] = {a, b, c};
    set_triangle(0, a, b, c);
    for (std::uint32_t i = 0; i < 3; ++i) {
      // Ghost 1 + i lies across edge i (v[i+1] -> v[i+2]) of triangle 0.
      set_triangle(1 + i, kInf, v[kPrev[i]], v[kNext[i]]);
      link(i, 3 * (1 + i));
      hull_out_[v[kNext[i]]] = 1 + i;
      hash_[bucket(p_[v[i]])] = v[i];
    }
    hull_size_ = 3;
    for (std::uint32_t i = 0; i < 3; ++i) link(3 * (1 + i) + 1, 3 * (1 + kPrev[i]) + 2);
    count_ = 4;
  }

  // Inserts point p, which must lie strictly outside the hull.
  void insert(std::uint32_t p) {
    const Vec2& q = p_[p];
    std::uint32_t first = visible_ghost(p);
    // The visible chain first .. last; it never holds the whole hull (a point outside a convex
    // polygon sees all edges but at least one), which bounds both walks.
    std::uint32_t last = first;
    std::size_t steps = 0;
    for (std::uint32_t g = prev_ghost(first); g != last && sees(g, q); g = prev_ghost(g)) {
      first = g;
      if (++steps > count_) throw InternalError("sweep Delaunay: hull walk exceeded its bound");
    }
    for (std::uint32_t g = next_ghost(last); g != first && sees(g, q); g = next_ghost(g)) {
      last = g;
      if (++steps > count_) throw InternalError("sweep Delaunay: hull walk exceeded its bound");
    }
    const std::uint32_t before = prev_ghost(first), after = next_ghost(last);
    const std::uint32_t a0 = from(first), av = to(last);

    // Each visible ghost (inf, b, a) becomes the finite triangle (p, b, a): counter-clockwise as
    // p is strictly right of a -> b, and its links inside the chain stay right. The chain's inner
    // vertices leave the hull; p takes over their hash buckets, being their hull neighbour now.
    stack_.clear();
    for (std::uint32_t g = first;; g = next_ghost(g)) {
      v_[3 * g] = p;
      stack_.push_back(3 * g);  // edge 0, the old hull edge, opposite p
      if (g == last) break;
      const std::uint32_t inner = to(g);
      hull_out_[inner] = kNone;
      std::uint32_t& slot = hash_[bucket(p_[inner])];
      if (slot == inner) slot = p;
      --hull_size_;
    }
    ++hull_size_;
    DTLAB_ASSERT(count_ + 2 <= capacity_);
    const std::uint32_t g1 = static_cast<std::uint32_t>(count_), g2 = g1 + 1;
    count_ += 2;
    set_triangle(g1, kInf, p, a0);  // hull edge a0 -> p
    set_triangle(g2, kInf, av, p);  // hull edge p -> av
    link(3 * g1, 3 * first + 1);
    link(3 * g1 + 1, 3 * before + 2);
    link(3 * g1 + 2, 3 * g2 + 1);
    link(3 * g2, 3 * last + 2);
    link(3 * g2 + 2, 3 * after + 1);
    hull_out_[a0] = g1;
    hull_out_[p] = g2;
    hash_[bucket(q)] = p;
    hash_[bucket(p_[a0])] = a0;
    if (2 * hull_size_ > hash_.size()) rehash(g2);

    legalize(p);
  }

  std::size_t triangle_count() const noexcept { return count_; }

 private:
  static constexpr std::uint32_t kNone = Triangulation2::kNone;

  void set_triangle(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c) noexcept {
    v_[3 * t] = a, v_[3 * t + 1] = b, v_[3 * t + 2] = c;
  }
  void link(std::uint32_t g, std::uint32_t h) noexcept { n_[g] = h, n_[h] = g; }

  std::uint32_t from(std::uint32_t ghost) const noexcept { return v_[3 * ghost + 2]; }
  std::uint32_t to(std::uint32_t ghost) const noexcept { return v_[3 * ghost + 1]; }
  std::uint32_t next_ghost(std::uint32_t ghost) const noexcept { return n_[3 * ghost + 2] / 3; }
  std::uint32_t prev_ghost(std::uint32_t ghost) const noexcept { return n_[3 * ghost + 1] / 3; }

  // q strictly right of the ghost's hull edge: the ghost is in conflict with q (on the line,
  // q is never between the ends, being outside the hull).
  bool sees(std::uint32_t ghost, const Vec2& q) const noexcept {
    return orient2d(p_[from(ghost)], p_[to(ghost)], q) == Sign::Negative;
  }

  // The hash bucket of the direction from the centre to q, by a pseudo-angle increasing
  // counter-clockwise (a monotone function of the angle; no trigonometry). Speed only.
  std::size_t bucket(const Vec2& q) const noexcept {
    const double dx = q.x - center_.x, dy = q.y - center_.y;
    const double l1 = std::fabs(dx) + std::fabs(dy);
    if (!(l1 > 0.0)) return 0;
    const double r = dx / l1;                                 // in [-1, 1]
    const double a = (dy > 0.0 ? 3.0 - r : 1.0 + r) / 4.0;    // in [0, 1)
    const auto b = static_cast<std::size_t>(a * static_cast<double>(hash_.size()));
    return std::min(b, hash_.size() - 1);
  }

  // A hull ghost that p strictly sees: from a live hull vertex hashed at or near p's angle, the
  // two hull edges at it, then outwards in both directions at once until one is visible (a point
  // outside the hull sees at least one edge, so the walks meet only after finding it). The walk
  // is short when the hull vertices nearest p's angle are near the edges p sees: always once the
  // centre is inside the hull, and on circles whenever the centre is inside the circle. A walk in
  // one direction only goes around the hull each time the hashed vertex is on the wrong side
  // (on "circle", where nearly all points stay on the hull: 340 orient2d calls per point at 10^5).
  std::uint32_t visible_ghost(std::uint32_t p) const {
    const Vec2& q = p_[p];
    const std::uint32_t v = hashed_hull_vertex(q);
    std::uint32_t ccw = hull_out_[v], cw = prev_ghost(ccw);
    for (std::size_t steps = 0;; ++steps) {
      if (sees(ccw, q)) return ccw;
      if (sees(cw, q)) return cw;
      if (steps > hull_size_)
        throw InternalError("sweep Delaunay: point (rank " + std::to_string(p) + ") sees no hull edge");
      ccw = next_ghost(ccw), cw = prev_ghost(cw);
    }
  }

  // The live hull vertex in the bucket nearest q's (both ways round). The vertices hashed last,
  // p and a0 of the latest insertion, are live, so the scan ends within one round.
  std::uint32_t hashed_hull_vertex(const Vec2& q) const {
    const std::size_t size = hash_.size(), b = bucket(q);
    for (std::size_t k = 0; k <= size / 2; ++k) {
      const std::uint32_t up = hash_[(b + k) % size], down = hash_[(b + size - k) % size];
      if (up != kNone && hull_out_[up] != kNone) return up;
      if (down != kNone && hull_out_[down] != kNone) return down;
    }
    throw InternalError("sweep Delaunay: no hull vertex in the angle hash");
  }

  // A fresh hash of four times as many buckets as the hull has vertices (refilled once it has
  // fewer than twice as many), filled from the hull, which `ghost` is on: on near-cocircular
  // input the hull holds most points, and with a fixed number of buckets the walk from the hashed
  // vertex would grow with it. The sizes grow geometrically, so the refills cost O(n) in all.
  void rehash(std::uint32_t ghost) {
    hash_.assign(4 * hull_size_, kNone);
    std::uint32_t g = ghost;
    for (std::size_t k = 0; k < hull_size_; ++k, g = next_ghost(g)) hash_[bucket(p_[from(g)])] = from(g);
    if (g != ghost) throw InternalError("sweep Delaunay: the hull is not a cycle of its size");
  }

  // Lawson flips of the edges opposite p (the half-edges on stack_) until each is locally
  // Delaunay. A flip swaps edge x-y of triangles (p, x, y) and (d, y, x) for p-d when p is in
  // the circle of (d, y, x), which is then a triangle of the cavity; the quadrilateral p, x, d, y
  // is convex because d lies in the circle of (p, x, y) beyond x-y, inside the angle x p y.
  // Each flip raises p's degree by one, which bounds the loop.
  void legalize(std::uint32_t p) {
    const Vec2& q = p_[p];
    const std::size_t bound = count_;
    std::size_t flips = 0;
    while (!stack_.empty()) {
      const std::uint32_t h = stack_.back();
      stack_.pop_back();
      const std::uint32_t g = n_[h];
      const std::uint32_t u = g / 3;
      // A ghost across is never in conflict: p is on the inner side of its hull edge.
      if (v_[3 * u] == kInf) continue;
      if (incircle_perturbed(p_[v_[3 * u]], p_[v_[3 * u + 1]], p_[v_[3 * u + 2]], q) != Sign::Positive) continue;
      const std::uint32_t hn = next_of(h), gn = next_of(g), gp = prev_of(g);
      const std::uint32_t across_x = n_[hn];  // twin of y -> p
      const std::uint32_t across_d = n_[gn];  // twin of x -> d
      v_[prev_of(h)] = v_[g];                 // (p, x, y) becomes (p, x, d)
      v_[gp] = p;                             // (d, y, x) becomes (d, y, p)
      link(h, across_d);
      link(g, across_x);
      link(hn, gn);
      stack_.push_back(h);   // x -> d
      stack_.push_back(gp);  // d -> y
      if (++flips > bound) throw InternalError("sweep Delaunay: flips exceeded their bound");
    }
  }

  const Vec2* p_;
  std::uint32_t* v_;
  std::uint32_t* n_;
  std::size_t capacity_;
  std::size_t count_ = 0;
  Vec2 center_;
  std::vector<std::uint32_t> hull_out_;
  std::size_t hull_size_ = 0;
  std::vector<std::uint32_t> hash_;  // a vertex per angle bucket, possibly no longer on the hull
  std::vector<std::uint32_t> stack_;
};

}  // namespace

void delaunay2d_sweep(const PreparedPoints2& input, Triangulation2& triangulation) {
  std::vector<Vec2>& points = triangulation.mutable_points();
  DTLAB_ASSERT(points.size() == input.points.size());
  const std::size_t m = input.distinct.size();
  DTLAB_ASSERT(m >= 3);

  const Vec2 center = sweep_center(input.points, input.distinct);
  const std::vector<std::uint32_t> order = radial_sweep_order(input.points, input.distinct, center);
  for (std::size_t r = 0; r < m; ++r) points[r] = input.points[order[r]];

  // The first points may run along one line: j is the first off the line through points 0 and 1.
  std::size_t j = 2;
  Sign turn = Sign::Zero;
  for (; j < m; ++j)
    if ((turn = orient2d(points[0], points[1], points[j])) != Sign::Zero) break;
  DTLAB_ASSERT(turn != Sign::Zero);

  const std::size_t capacity = 2 * m - 2;  // triangles of the final triangulation, ghosts included
  std::vector<std::uint32_t>& vertices = triangulation.mutable_vertices();
  std::vector<std::uint32_t>& neighbours = triangulation.mutable_neighbours();
  vertices.assign(3 * capacity, 0);
  neighbours.assign(3 * capacity, 0);

  SweepHull sweep(points.data(), m, vertices.data(), neighbours.data(), capacity, center);
  const auto apex = static_cast<std::uint32_t>(j);
  if (turn == Sign::Positive) {
    sweep.start(0, 1, apex);
  } else {
    sweep.start(0, apex, 1);
  }
  // Points 2 .. j-1 extend the segment of 0 and 1 on its line (each is farther from the centre,
  // so outside the segment): each strictly sees only an edge from the segment's end to the apex.
  // The apex is farther than all of them, yet the hull of the points before each is a triangle
  // on that segment, which the point lies outside: the sweep's invariant holds throughout.
  for (std::uint32_t r = 2; r < apex; ++r) sweep.insert(r);
  for (std::uint32_t r = apex + 1; r < m; ++r) sweep.insert(r);
  DTLAB_ASSERT(sweep.triangle_count() == capacity);

  // Back to input ids and input order.
  for (std::uint32_t& v : vertices)
    if (v != kInf) v = order[v];
  std::copy(input.points.begin(), input.points.end(), points.begin());
}

}  // namespace dtlab
