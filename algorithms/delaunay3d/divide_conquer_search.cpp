// Kd-tree and make-simplex search of variant "divide-conquer" (divide_conquer_search.hpp).
//
// The search is a depth-first branch and bound over the kd-tree, nearer child first. A node is
// pruned when its box lies in the closed inner half-space of the facet, or outside the sphere of
// the best apex so far. Both tests are floating-point with an error bound derived below, so that
// a node is pruned only when it provably holds no point that could win: the bounds only decide
// where to look; which point wins is decided by the exact orient3d and insphere_perturbed. Why
// the sphere of the best candidate bounds the search: the spheres through a, b, c form a pencil;
// on the positive side of the facet, the part of the sphere through a better apex lies inside
// the part of the sphere through a worse one, so every point that can still win lies in the
// current sphere, and a point that lost once loses to every later best.
#include "algorithms/delaunay3d/divide_conquer_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"

namespace dtlab::dewall {

namespace {

constexpr double kEps = 0x1p-53;  // unit roundoff
// Relative slack for norms and squared distances computed in floating point (a few kEps each);
// far above what they can be off by, far below what would cost search time.
constexpr double kSlack = 1e-10;

double coordinate(const Vec3& p, int k) noexcept { return k == 0 ? p.x : (k == 1 ? p.y : p.z); }

// (axis k, then k + 1, then k + 2) lexicographically: a strict order on distinct points.
bool less_along(const Vec3& p, const Vec3& q, int k) noexcept {
  for (int j = 0; j < 3; ++j) {
    const int axis = (k + j) % 3;
    const double s = coordinate(p, axis), t = coordinate(q, axis);
    if (s != t) return s < t;
  }
  return false;
}

inline double gap(double p, double low, double high) noexcept {
  return p < low ? low - p : (p > high ? p - high : 0.0);
}

inline double box_distance2(const Vec3& p, const Vec3& low, const Vec3& high) noexcept {
  const double dx = gap(p.x, low.x, high.x), dy = gap(p.y, low.y, high.y), dz = gap(p.z, low.z, high.z);
  return dx * dx + dy * dy + dz * dz;
}

Vec3 cross3(const Vec3& u, const Vec3& v) noexcept {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}

double norm1(const Vec3& u) noexcept { return std::fabs(u.x) + std::fabs(u.y) + std::fabs(u.z); }

// The plane of facet (a, b, c): orient3d(a, b, c, q) = n . (q - a) with n = (b - a) x (c - a).
// Each computed difference is off by at most kEps relatively, each component of n by at most
// 4 kEps * mag (mag = |u_j v_k| + |u_k v_j|), and the maximum of n . (q - a) over a box (one
// corner per axis) by at most 4.1 kEps * sum (mag + |n|) |q - a|: 8 kEps is safe.
struct Plane {
  Vec3 a, n, mag;

  Plane(const Vec3& pa, const Vec3& pb, const Vec3& pc) noexcept : a(pa) {
    const Vec3 u = pb - pa, v = pc - pa;
    n = cross3(u, v);
    mag = {std::fabs(u.y * v.z) + std::fabs(u.z * v.y), std::fabs(u.z * v.x) + std::fabs(u.x * v.z),
           std::fabs(u.x * v.y) + std::fabs(u.y * v.x)};
  }

  // False only if every point of the box is on the plane or on its negative side.
  bool may_reach(const Vec3& low, const Vec3& high) const noexcept {
    double value = 0.0, error = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double nk = coordinate(n, k);
      const double dl = coordinate(low, k) - coordinate(a, k), dh = coordinate(high, k) - coordinate(a, k);
      value += std::max(nk * dl, nk * dh);
      error += (coordinate(mag, k) + std::fabs(nk)) * std::max(std::fabs(dl), std::fabs(dh));
    }
    return value + 8 * kEps * error > 0.0;
  }
};

// A floating-point circumsphere of (a, b, c, q) with a proven bound: every point strictly inside
// the exact sphere is within `reach` of `centre`. Centre - a = N / (2 D), with u, v, w = b - a,
// c - a, q - a, D = u . (v x w) and N = |u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v). Every
// monomial of D (of N) is a product of 3 (4) rounded differences computed with at most 8 (12)
// more roundings, and the absolute values of the monomials sum to at most U V W (U V W (U + V +
// W)) with U, V, W the 1-norms of u, v, w; so |D error| <= 16 kEps U V W and |N error| <= 24 kEps
// U V W (U + V + W) (twice the count). Then |N/D computed - N/D| <= (eN + |N/D computed| eD) /
// (|D| - eD). A nearly flat tetrahedron (|D| <= 2 eD) gives no bound: the search goes on by the
// half-space test alone.
struct Sphere {
  bool bounded = false;
  Vec3 centre;
  double reach2 = 0.0;  // squared reach, rounded up

  Sphere() = default;
  Sphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& q) noexcept {
    const Vec3 u = b - a, v = c - a, w = q - a;
    const Vec3 vw = cross3(v, w), wu = cross3(w, u), uv = cross3(u, v);
    const double d = dot(u, vw);
    const double uu = dot(u, u), vv = dot(v, v), ww = dot(w, w);
    const Vec3 n = uu * vw + vv * wu + ww * uv;
    const double nu = norm1(u), nv = norm1(v), nw = norm1(w);
    const double error_d = 16 * kEps * nu * nv * nw;
    const double error_n = 24 * kEps * nu * nv * nw * (nu + nv + nw);
    if (!(std::fabs(d) > 2 * error_d)) return;
    const double denominator = std::fabs(d) - error_d;
    double delta = 0.0;
    Vec3 offset;
    for (int k = 0; k < 3; ++k) {
      const double x = coordinate(n, k) / d;
      delta += 0.5 * (error_n + std::fabs(x) * error_d) / denominator + 2 * kEps * std::fabs(x);
      (k == 0 ? offset.x : (k == 1 ? offset.y : offset.z)) = 0.5 * x;
    }
    centre = a + offset;
    delta += 2 * kEps * norm1(centre);  // the addition a + offset
    delta *= 2;                          // margin over the bound's own rounding
    const double reach = norm(a - centre) * (1 + kSlack) + 2 * delta;
    if (!std::isfinite(reach)) return;
    reach2 = reach * reach * (1 + kSlack);
    bounded = true;
  }

  // True only if q is strictly outside the exact sphere.
  bool surely_outside(const Vec3& q) const noexcept {
    const Vec3 d = q - centre;
    return dot(d, d) * (1 - kSlack) > reach2;
  }
  // True only if the exact sphere's closed box lies in the open interior of the cell.
  bool inside(const std::array<Vec3, 2>& cell) const noexcept {
    const double reach = std::sqrt(reach2) * (1 + kSlack);
    for (int k = 0; k < 3; ++k) {
      const double centre_k = coordinate(centre, k);
      const double margin = reach + 4 * kEps * std::fabs(centre_k);  // rounding of centre_k -+ reach
      if (!(coordinate(cell[0], k) < centre_k - margin && centre_k + margin < coordinate(cell[1], k))) return false;
    }
    return true;
  }
  // False only if the box is strictly outside the exact sphere.
  bool may_reach(const Vec3& low, const Vec3& high) const noexcept {
    return !(box_distance2(centre, low, high) * (1 - kSlack) > reach2);
  }
};

}  // namespace

KdTree::KdTree(std::span<const Vec3> input, std::span<const std::uint32_t> distinct) {
  struct Item {
    Vec3 p;
    std::uint32_t id;
  };
  const auto m = static_cast<std::uint32_t>(distinct.size());
  std::vector<Item> items(m);
  for (std::uint32_t r = 0; r < m; ++r) items[r] = {input[distinct[r]], distinct[r]};

  auto make_node = [&items](std::uint32_t begin, std::uint32_t end) {
    KdNode node;
    node.begin = begin, node.mid = end, node.end = end;
    node.low = node.high = items[begin].p;
    for (std::uint32_t r = begin + 1; r < end; ++r) {
      const Vec3& p = items[r].p;
      node.low = {std::min(node.low.x, p.x), std::min(node.low.y, p.y), std::min(node.low.z, p.z)};
      node.high = {std::max(node.high.x, p.x), std::max(node.high.y, p.y), std::max(node.high.z, p.z)};
    }
    return node;
  };
  if (m == 0) return;
  const std::size_t capacity = 2 * (m / kLeafSize) + 3;
  nodes_.reserve(capacity), cells_.reserve(capacity), parents_.reserve(capacity), axes_.reserve(capacity);
  const double infinity = std::numeric_limits<double>::infinity();
  nodes_.push_back(make_node(0, m));
  cells_.push_back({Vec3{-infinity, -infinity, -infinity}, Vec3{infinity, infinity, infinity}});
  parents_.push_back(kNone);
  axes_.push_back(0);
  std::vector<std::uint32_t> todo{0};
  while (!todo.empty()) {
    const std::uint32_t index = todo.back();
    todo.pop_back();
    const KdNode node = nodes_[index];
    if (node.end - node.begin <= kLeafSize) continue;
    const Vec3 extent = node.high - node.low;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t mid = node.begin + (node.end - node.begin) / 2;
    std::nth_element(items.begin() + node.begin, items.begin() + mid, items.begin() + node.end,
                     [axis](const Item& s, const Item& t) { return less_along(s.p, t.p, axis); });
    const auto left = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(make_node(node.begin, mid));
    nodes_.push_back(make_node(mid, node.end));
    nodes_[index].mid = mid;
    nodes_[index].left = left;
    axes_[index] = static_cast<std::uint8_t>(axis);
    // Left points are <= the split coordinate on the axis, right points >= it.
    const double split = coordinate(items[mid].p, axis);
    std::array<Vec3, 2> left_cell = cells_[index], right_cell = cells_[index];
    (axis == 0 ? left_cell[1].x : (axis == 1 ? left_cell[1].y : left_cell[1].z)) = split;
    (axis == 0 ? right_cell[0].x : (axis == 1 ? right_cell[0].y : right_cell[0].z)) = split;
    cells_.push_back(left_cell), cells_.push_back(right_cell);
    parents_.push_back(index), parents_.push_back(index);
    axes_.push_back(0), axes_.push_back(0);
    todo.push_back(left);
    todo.push_back(left + 1);
  }
  points_.resize(m);
  ids_.resize(m);
  leaf_of_.resize(m);
  for (std::uint32_t r = 0; r < m; ++r) points_[r] = items[r].p, ids_[r] = items[r].id;
  for (std::uint32_t k = 0; k < nodes_.size(); ++k)
    if (nodes_[k].is_leaf())
      for (std::uint32_t r = nodes_[k].begin; r < nodes_[k].end; ++r) leaf_of_[r] = k;
}

struct ApexSearch::Query {
  const Vec3 &pa, &pb, &pc;
  std::uint32_t a, b, c;
  Plane plane;
  Vec3 target;
  Sphere sphere;
  std::uint32_t best = kNone;
  std::size_t pops = 0;
};

// Depth-first over `subtree`, the child nearer the target first.
void ApexSearch::explore(std::uint32_t subtree, Query& q) {
  const auto P = tree_.points();
  const auto nodes = tree_.nodes();
  stack_.clear();
  stack_.push_back(subtree);
  while (!stack_.empty()) {
    // Every node is pushed at most once per search (a tree, each subtree explored once).
    if (++q.pops > nodes.size())
      throw InternalError("divide-conquer 3D Delaunay: the apex search exceeded its bound of " +
                          std::to_string(nodes.size()) + " nodes");
    const std::uint32_t k = stack_.back();
    stack_.pop_back();
    const KdNode& node = nodes[k];
    ++nodes_visited_;
    if (q.sphere.bounded && !q.sphere.may_reach(node.low, node.high)) continue;
    if (!q.plane.may_reach(node.low, node.high)) continue;
    if (node.is_leaf()) {
      for (std::uint32_t r = node.begin; r < node.end; ++r) {
        if (r == q.a || r == q.b || r == q.c) continue;  // on the plane; orient3d would need its slow stages to say so
        const Vec3& p = P[r];
        if (q.sphere.bounded && q.sphere.surely_outside(p)) continue;
        if (orient3d(q.pa, q.pb, q.pc, p) != Sign::Positive) continue;
        if (q.best == kNone || insphere_perturbed(q.pa, q.pb, q.pc, P[q.best], p) == Sign::Positive) {
          q.best = r;
          q.sphere = Sphere(q.pa, q.pb, q.pc, p);
        }
      }
      continue;
    }
    const int axis = tree_.split_axis(k);
    const bool left_first = coordinate(q.target, axis) <= coordinate(tree_.cell(node.left)[1], axis);
    stack_.push_back(left_first ? node.left + 1 : node.left);
    stack_.push_back(left_first ? node.left : node.left + 1);
  }
}

// Bottom-up: the leaf of a first, then the sibling subtree of each ancestor in turn, until the
// sphere of the best apex lies inside the current node's cell (no point outside it can win).
std::uint32_t ApexSearch::apex(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const auto P = tree_.points();
  const auto nodes = tree_.nodes();
  Query q{P[a], P[b], P[c], a, b, c, Plane(P[a], P[b], P[c]), (1.0 / 3.0) * (P[a] + P[b] + P[c]), Sphere{}};
  std::uint32_t k = tree_.leaf_of(a);
  explore(k, q);
  while (k != 0) {
    if (q.sphere.bounded && q.sphere.inside(tree_.cell(k))) break;
    const std::uint32_t parent = tree_.parent(k);
    const std::uint32_t left = nodes[parent].left;
    explore(k == left ? left + 1 : left, q);
    k = parent;
  }
  return q.best;
}

}  // namespace dtlab::dewall
