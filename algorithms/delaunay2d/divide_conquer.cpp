// Variant "divide-conquer": divide-and-conquer Delaunay triangulation (Lee & Schachter 1980),
// merged as in Guibas & Stolfi 1985 (§8: lower common tangent, then the "rising bubble" that
// picks the next cross edge from a left and a right candidate), with the cuts alternating between
// vertical and horizontal at each level (Dwyer 1987), on the half-edge structure of
// divide_conquer_mesh.hpp. Every in-circle decision is incircle_perturbed, so ties resolve as in
// every other variant; the result is converted to Triangulation2 (ghosts and twins) at the end.
#include <algorithm>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/delaunay2d/divide_conquer_mesh.hpp"
#include "algorithms/delaunay2d/prepare.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

namespace {

using dc::EdgeMesh;

// A cut direction. Axis 0 orders points by (x, y): halves are separated by a vertical line
// (tilted infinitesimally, so that equal x still separates). Axis 1 orders them by (y, -x), the
// same order in the frame turned by -90 degrees: halves are separated by a horizontal line. The
// merge only asks orient2d and incircle, which a rotation leaves unchanged, so it serves both.
bool before(const Vec2& a, const Vec2& b, int axis) noexcept {
  if (axis == 0) return a.x < b.x || (a.x == b.x && a.y < b.y);
  return a.y < b.y || (a.y == b.y && a.x > b.x);
}

// Hull edges of a sub-triangulation, in the frame of the cut that will merge it: `low` is the
// counter-clockwise hull edge out of the first vertex in that frame's order, `high` the
// clockwise hull edge out of the last one (Guibas & Stolfi's ldo / rdo).
struct HullEnds {
  std::uint32_t low, high;
};

struct Node {
  std::uint32_t lo, hi;
  int axis;
};

// Nodes of at most this many points keep their parent's axis all the way down: their points
// are simply sorted, and no hull walk re-expresses their children's ends. Dwyer's gain (no
// long thin strips) comes from the upper levels.
constexpr std::uint32_t kSameAxisBelow = 32;

class DivideConquer {
 public:
  DivideConquer(const Vec2* points, std::uint32_t n) : p_(points), n_(n), mesh_(n) {}

  // Triangulates points [0, n), already arranged by arrange(): returns the hull ends in the
  // frame of axis 0.
  HullEnds run() { return solve(0, n_, 0, 0); }

  EdgeMesh& mesh() noexcept { return mesh_; }

 private:
  // Recursion depth is ceil(log2 n) + 1 at most (halves differ by at most one point).
  HullEnds solve(std::uint32_t lo, std::uint32_t hi, int axis, int depth) {
    DTLAB_ASSERT(depth <= 64);
    const std::uint32_t count = hi - lo;
    if (count == 2) {
      const std::uint32_t e = mesh_.make_edge(lo, lo + 1);
      return {e, EdgeMesh::sym(e)};
    }
    if (count == 3) return triangle(lo);
    const std::uint32_t mid = lo + count / 2;
    if (count <= kSameAxisBelow) {
      const HullEnds left = solve(lo, mid, axis, depth + 1);
      return merge(left, solve(mid, hi, axis, depth + 1), count);
    }
    HullEnds left = solve(lo, mid, 1 - axis, depth + 1);
    HullEnds right = solve(mid, hi, 1 - axis, depth + 1);
    left = reframe(left, axis);
    right = reframe(right, axis);
    return merge(left, right, count);
  }

  // Points lo, lo + 1, lo + 2 in increasing order: a triangle, or a chain when collinear.
  HullEnds triangle(std::uint32_t lo) {
    const std::uint32_t a = mesh_.make_edge(lo, lo + 1);
    const std::uint32_t b = mesh_.make_edge(lo + 1, lo + 2);
    mesh_.insert_after(EdgeMesh::sym(a), b);
    const Sign turn = orient2d(p_[lo], p_[lo + 1], p_[lo + 2]);
    if (turn == Sign::Zero) return {a, EdgeMesh::sym(b)};
    const std::uint32_t c = mesh_.connect(b, a);  // lo + 2 -> lo
    if (turn == Sign::Positive) return {a, EdgeMesh::sym(b)};
    return {EdgeMesh::sym(c), c};
  }

  // The hull ends of a child (in its own frame) re-expressed in the frame of `axis`, by one
  // walk around the child's hull. The extreme vertices of any order that is monotone along
  // lines are hull vertices visited once, collinear hulls (chains) included.
  HullEnds reframe(HullEnds ends, int axis) const {
    const std::uint32_t start = EdgeMesh::sym(ends.low);  // outer face on its left
    std::uint32_t g = start, lowest = start, highest = start;
    for (std::uint32_t steps = 0;; ++steps) {
      DTLAB_ASSERT(steps <= 2 * n_);
      const Vec2& v = p_[mesh_.dest(g)];
      if (before(v, p_[mesh_.dest(lowest)], axis)) lowest = g;
      if (before(p_[mesh_.dest(highest)], v, axis)) highest = g;
      g = mesh_.lnext(g);
      if (g == start) break;
    }
    return {EdgeMesh::sym(lowest), mesh_.lnext(highest)};
  }

  bool left_of(std::uint32_t v, std::uint32_t e) const noexcept {
    return orient2d(p_[v], p_[mesh_.org(e)], p_[mesh_.dest(e)]) == Sign::Positive;
  }
  bool right_of(std::uint32_t v, std::uint32_t e) const noexcept {
    return orient2d(p_[v], p_[mesh_.dest(e)], p_[mesh_.org(e)]) == Sign::Positive;
  }

  // Lower common tangent, then cross edges bottom to top. The candidate tests are those of
  // Guibas & Stolfi, except that a candidate is deleted only for a next candidate strictly
  // above the base line: there the in-circle question is between four points of a genuine
  // configuration, never with a point on the base line, where a perturbed answer would mislead.
  HullEnds merge(HullEnds left, HullEnds right, std::uint32_t count) {
    std::uint32_t ldo = left.low, ldi = left.high;
    std::uint32_t rdi = right.low, rdo = right.high;
    for (std::uint32_t steps = 0;; ++steps) {
      if (steps > 2 * count + 4) throw InternalError("divide-conquer Delaunay: lower tangent did not converge");
      if (left_of(mesh_.org(rdi), ldi)) {
        ldi = mesh_.lnext(ldi);
      } else if (right_of(mesh_.org(ldi), rdi)) {
        rdi = mesh_.rprev(rdi);
      } else {
        break;
      }
    }
    std::uint32_t base = mesh_.connect(EdgeMesh::sym(rdi), ldi);  // right -> left
    if (mesh_.org(ldi) == mesh_.org(ldo)) ldo = EdgeMesh::sym(base);
    if (mesh_.org(rdi) == mesh_.org(rdo)) rdo = base;

    // A candidate's far end is above the base line r -> l (on its right).
    const auto above = [&](std::uint32_t e) {
      const std::uint32_t v = mesh_.dest(e);
      if (v == mesh_.org(base) || v == mesh_.dest(base)) return false;
      return orient2d(p_[v], p_[mesh_.dest(base)], p_[mesh_.org(base)]) == Sign::Positive;
    };
    // Each pass adds one cross edge or deletes one edge of a half: bounded by 3 * count each.
    const std::size_t bound = 6 * static_cast<std::size_t>(count) + 6;
    std::size_t steps = 0;
    for (;;) {
      const Vec2& l = p_[mesh_.dest(base)];
      const Vec2& r = p_[mesh_.org(base)];
      std::uint32_t lcand = mesh_.onext(EdgeMesh::sym(base));
      const bool lvalid = above(lcand);
      if (lvalid) {
        for (std::uint32_t next = mesh_.onext(lcand);
             above(next) && incircle_perturbed(l, r, p_[mesh_.dest(lcand)], p_[mesh_.dest(next)]) == Sign::Positive;
             next = mesh_.onext(lcand)) {
          mesh_.delete_edge(lcand);
          lcand = next;
          if (++steps > bound) throw InternalError("divide-conquer Delaunay: merge exceeded its bound");
        }
      }
      std::uint32_t rcand = mesh_.oprev(base);
      const bool rvalid = above(rcand);
      if (rvalid) {
        for (std::uint32_t next = mesh_.oprev(rcand);
             above(next) && incircle_perturbed(l, r, p_[mesh_.dest(rcand)], p_[mesh_.dest(next)]) == Sign::Positive;
             next = mesh_.oprev(rcand)) {
          mesh_.delete_edge(rcand);
          rcand = next;
          if (++steps > bound) throw InternalError("divide-conquer Delaunay: merge exceeded its bound");
        }
      }
      if (!lvalid && !rvalid) break;
      // (lcand's end, l, r) is counter-clockwise; the right candidate wins iff its end is inside
      // that circle.
      if (!lvalid || (rvalid && incircle_perturbed(p_[mesh_.dest(lcand)], l, r, p_[mesh_.dest(rcand)]) == Sign::Positive)) {
        base = mesh_.connect(rcand, EdgeMesh::sym(base));
      } else {
        base = mesh_.connect(EdgeMesh::sym(base), EdgeMesh::sym(lcand));
      }
      if (++steps > bound) throw InternalError("divide-conquer Delaunay: merge exceeded its bound");
    }
    return {ldo, rdo};
  }

  const Vec2* p_;
  std::uint32_t n_;
  EdgeMesh mesh_;
};

struct Item {
  Vec2 p;
  std::uint32_t id;
};

// Arranges items so that every node of the recursion (halves of floor / ceil size, alternating
// axes down to kSameAxisBelow points) finds its first half below its median in its axis' order:
// a k-d tree layout, built with an explicit stack by selection (O(n log n)), sorted leaves.
template <int kAxis>
void split_or_sort(std::span<Item> items, const Node& node, std::vector<Node>& stack) {
  // Bitwise, not short-circuit: one branch per comparison in the selection loops.
  const auto less = [](const Item& a, const Item& b) {
    if constexpr (kAxis == 0) return (a.p.x < b.p.x) | ((a.p.x == b.p.x) & (a.p.y < b.p.y));
    return (a.p.y < b.p.y) | ((a.p.y == b.p.y) & (a.p.x > b.p.x));
  };
  const auto first = items.begin() + node.lo, last = items.begin() + node.hi;
  if (node.hi - node.lo <= kSameAxisBelow) {
    std::sort(first, last, less);
    return;
  }
  const std::uint32_t mid = node.lo + (node.hi - node.lo) / 2;
  std::nth_element(first, items.begin() + mid, last, less);
  stack.push_back({node.lo, mid, 1 - kAxis});
  stack.push_back({mid, node.hi, 1 - kAxis});
}

void arrange(std::span<Item> items) {
  std::vector<Node> stack;
  stack.push_back({0, static_cast<std::uint32_t>(items.size()), 0});
  while (!stack.empty()) {
    const Node node = stack.back();
    stack.pop_back();
    if (node.axis == 0) {
      split_or_sort<0>(items, node, stack);
    } else {
      split_or_sort<1>(items, node, stack);
    }
  }
}

}  // namespace

void delaunay2d_divide_conquer(const PreparedPoints2& input, Triangulation2& triangulation) {
  std::vector<Vec2>& points = triangulation.mutable_points();
  DTLAB_ASSERT(points.size() == input.points.size());
  const std::size_t m = input.distinct.size();
  DTLAB_ASSERT(m >= 3);
  std::vector<std::uint32_t> ids(m);
  {
    const auto items = std::make_unique_for_overwrite<Item[]>(m);
    advise_huge_pages(items.get(), m * sizeof(Item));
    for (std::size_t k = 0; k < m; ++k) items[k] = {input.points[input.distinct[k]], input.distinct[k]};
    arrange(std::span<Item>(items.get(), m));
    // The points in recursion order, in the triangulation's point array (restored at the end).
    for (std::size_t k = 0; k < m; ++k) points[k] = items[k].p, ids[k] = items[k].id;
  }
  DivideConquer dc(points.data(), static_cast<std::uint32_t>(m));
  const HullEnds ends = dc.run();
  dc.mesh().to_triangulation(EdgeMesh::sym(ends.low), ids, triangulation);
  std::copy(input.points.begin(), input.points.end(), points.begin());
}

}  // namespace dtlab
