// Variant "divide-conquer": DeWall, Cignoni, Montani, Scopigno, "DeWall: a fast divide and
// conquer Delaunay triangulation in E^d" (CAD 30(5), 1998). The point set is split by a wall (the
// median of the longest axis of a kd-tree node); the tetrahedra crossing the wall are built first
// by advancing a front of open facets ("make simplex" on each: the apex whose sphere is empty),
// and each half then goes on with the open facets that lie in it, down the tree (an explicit
// stack). A front facet with no point beyond it is a hull facet and gets a ghost.
//
// Departures from the paper, each for robustness on degenerate input:
//  - make simplex decides with orient3d and insphere_perturbed only (divide_conquer_search.hpp),
//    so ties resolve as in the perturbed Delaunay tetrahedralization every variant builds. Points
//    on the facet's plane never need considering: the facet is a facet of a Delaunay
//    tetrahedron, so they lie outside its circle (perturbed), and an apex must be off the plane.
//  - The first tetrahedron stands on a hull facet found by exact gift wrapping, whose flat hull
//    faces are triangulated by the perturbed in-circle rule (divide_conquer_start.hpp); a
//    visibility walk from it, building the tetrahedra it crosses, reaches the first wall.
//  - The search for an apex runs over all points (a kd-tree, pruned to the sphere), not only the
//    current half. Normally the Delaunay apex of a facet of a half lies in that half (every
//    tetrahedron crossing an enclosing wall is already built), but a half's wall can fall apart
//    into pieces that no open facet of the wall touches; then a facet of the half meets a
//    tetrahedron of the wall, the global search still finds it, and its facets outside the half
//    are finished in a last pass. Every tetrahedron is built by make simplex on a Delaunay facet,
//    so the result never depends on the order.
#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/delaunay3d/divide_conquer_search.hpp"
#include "algorithms/delaunay3d/divide_conquer_start.hpp"
#include "algorithms/delaunay3d/prepare.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/facet_table.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

namespace {

using T3 = Tetrahedralization3;
using dewall::KdNode;
using dewall::KdTree;
using OpenFacets = FacetTable;
constexpr std::uint32_t kInf = T3::kInfinite;
constexpr std::uint32_t kNone = T3::kNone;
constexpr auto kFacet = T3::kFacetVertex;

// Halves of at most this many points are not split further: their facets form one front.
constexpr std::uint32_t kSmallestWall = 64;

// Where a facet lies relative to a node of the tree: in its left half, its right half, across
// its wall, or not in the node (a vertex outside it).
enum class Side { Left, Right, Wall, Outside };

struct Range {
  std::uint32_t begin, mid, end;  // mid == end: not split

  Side side(const std::array<std::uint32_t, 3>& v) const noexcept {
    const std::uint32_t lo = std::min({v[0], v[1], v[2]}), hi = std::max({v[0], v[1], v[2]});
    if (lo < begin || hi >= end) return Side::Outside;
    if (hi < mid) return Side::Left;
    if (lo >= mid) return Side::Right;
    return Side::Wall;
  }
};

class DeWall {
 public:
  DeWall(const KdTree& tree, std::vector<T3::Record>& records)
      : tree_(tree), P_(tree.points()), records_(records), search_(tree) {
    const std::size_t m = P_.size();
    // Triangulations of m points in 3D have at most about m^2 / 2 tetrahedra, the hull at most
    // 2m - 4 triangles: a front that builds more is broken.
    limit_ = std::min<std::size_t>(m * m / 2 + 2 * m + 16, T3::kMaxTetrahedra);
  }

  void run() {
    start();
    const auto nodes = tree_.nodes();
    struct Task {
      std::uint32_t node;
      std::vector<std::uint32_t> facets;
    };
    std::vector<Task> stack;
    stack.push_back({0, std::move(root_facets_)});
    std::vector<std::uint32_t> wall, left, right;
    std::size_t tasks = 0;
    while (!stack.empty()) {
      if (++tasks > nodes.size()) throw InternalError("divide-conquer 3D Delaunay: more walls than tree nodes");
      Task task = std::move(stack.back());
      stack.pop_back();
      const KdNode& node = nodes[task.node];
      if (node.is_leaf() || node.end - node.begin <= kSmallestWall) {
        const Range range{node.begin, node.end, node.end};
        std::vector<std::uint32_t>& front = task.facets;
        while (!front.empty()) {
          const std::uint32_t h = front.back();
          front.pop_back();
          if (!is_open(h)) continue;
          advance(h);
          for (const std::uint32_t g : fresh_) (range.side(facet(g)) == Side::Outside ? deferred_ : front).push_back(g);
        }
        continue;
      }
      const Range range{node.begin, node.mid, node.end};
      wall.clear(), left.clear(), right.clear();
      auto sort_into = [&](std::uint32_t g) {
        switch (range.side(facet(g))) {
          case Side::Left: left.push_back(g); break;
          case Side::Right: right.push_back(g); break;
          case Side::Wall: wall.push_back(g); break;
          case Side::Outside: deferred_.push_back(g); break;
        }
      };
      for (const std::uint32_t g : task.facets)
        if (is_open(g)) sort_into(g);
      while (!wall.empty()) {
        const std::uint32_t h = wall.back();
        wall.pop_back();
        if (!is_open(h)) continue;
        advance(h);
        for (const std::uint32_t g : fresh_) sort_into(g);
      }
      // Left half first (pushed last).
      if (!right.empty()) stack.push_back({node.left + 1, right});
      if (!left.empty()) stack.push_back({node.left, left});
    }
    // Facets that left their half (see the file comment), over all points.
    while (!deferred_.empty()) {
      const std::uint32_t h = deferred_.back();
      deferred_.pop_back();
      if (!is_open(h)) continue;
      advance(h);
      deferred_.insert(deferred_.end(), fresh_.begin(), fresh_.end());
    }
    DTLAB_ASSERT(open_.size() == 0);
    link_ghosts();
  }

 private:
  std::array<std::uint32_t, 3> facet(std::uint32_t h) const noexcept {
    const auto& v = records_[h >> 2].vertex;
    const auto& f = kFacet[h & 3u];
    return {v[f[0]], v[f[1]], v[f[2]]};
  }
  bool is_open(std::uint32_t h) const noexcept { return records_[h >> 2].neighbour[h & 3u] == kNone; }
  void link(std::uint32_t g, std::uint32_t h) noexcept {
    records_[g >> 2].neighbour[g & 3u] = h;
    records_[h >> 2].neighbour[h & 3u] = g;
  }

  std::uint32_t new_tetrahedron(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    if (records_.size() >= limit_) {
      if (limit_ == T3::kMaxTetrahedra)  // a size limit of the input, not a bug
        throw InputError("the Delaunay tetrahedralization of these points needs more than " +
                         std::to_string(T3::kMaxTetrahedra) + " tetrahedra (32-bit facet handles)");
      throw InternalError("divide-conquer 3D Delaunay: the front built more than " + std::to_string(limit_) +
                          " tetrahedra");
    }
    records_.push_back({{a, b, c, d}, {kNone, kNone, kNone, kNone}});
    return static_cast<std::uint32_t>(records_.size() - 1);
  }

  // Opens facets 0..k-1 of new tetrahedron t: each is closed against its twin if that is open,
  // else recorded open and listed in fresh_.
  void open_facets(std::uint32_t t, std::uint32_t k) {
    for (std::uint32_t i = 0; i < k; ++i) {
      const auto v = facet(4 * t + i);
      const std::uint32_t twin = open_.take_or_insert(OpenFacets::key(v[0], v[1], v[2]), 4 * t + i);
      if (twin == OpenFacets::kAbsent) {
        fresh_.push_back(4 * t + i);
      } else {
        link(4 * t + i, twin);
      }
    }
  }

  // Make simplex across open facet h, listed (f0, f1, f2) by its tetrahedron: the new
  // tetrahedron (f0, f2, f1, p) on the other side, or a ghost (inf, f0, f1, f2) if no point lies
  // there. Its open facets go to fresh_. Returns the new tetrahedron.
  std::uint32_t advance(std::uint32_t h) {
    fresh_.clear();
    const auto f = facet(h);
    open_.erase(OpenFacets::key(f[0], f[1], f[2]));
    const std::uint32_t p = search_.apex(f[0], f[2], f[1]);
    if (p == dewall::kNone) {
      const std::uint32_t g = new_tetrahedron(kInf, f[0], f[1], f[2]);
      link(4 * g, h);
      ghosts_.push_back(g);
      return g;
    }
    const std::uint32_t t = new_tetrahedron(f[0], f[2], f[1], p);
    link(4 * t + 3, h);
    open_facets(t, 3);
    return t;
  }

  // The first tetrahedron, on a hull facet, then a visibility walk to the root's wall building
  // the tetrahedra it crosses. All their open facets become the root's front.
  std::uint32_t start() {
    const auto hull = dewall::first_hull_facet(P_);
    const std::uint32_t p = search_.apex(hull[0], hull[1], hull[2]);
    DTLAB_ASSERT(p != dewall::kNone);
    std::uint32_t t = new_tetrahedron(hull[0], hull[1], hull[2], p);
    fresh_.clear();
    open_facets(t, 4);
    root_facets_ = fresh_;
    const KdNode& root = tree_.nodes()[0];
    if (root.is_leaf()) return t;
    const std::uint32_t mid = root.mid;
    // Each step enters a tetrahedron sharing a facet, so the first one with vertices on both
    // sides of the wall is met on the way from one side to the other. The walk cannot cycle in a
    // (regular) Delaunay tetrahedralization (Edelsbrunner 1990); the bound backs that up.
    for (std::size_t steps = 0;; ++steps) {
      if (steps > limit_) throw InternalError("divide-conquer 3D Delaunay: the walk to the first wall did not end");
      const auto& v = records_[t].vertex;
      bool left = false, right = false;
      for (const std::uint32_t x : v) (x < mid ? left : right) = true;
      if (left && right) break;
      const Vec3& target = P_[right ? mid - 1 : mid];
      std::uint32_t next = kNone;
      for (std::uint32_t i = 0; i < 4 && next == kNone; ++i) {
        const auto& f = kFacet[i];
        if (orient3d(P_[v[f[0]]], P_[v[f[1]]], P_[v[f[2]]], target) == Sign::Negative) next = 4 * t + i;
      }
      // The target is no vertex of t, and no point lies on a Delaunay tetrahedron otherwise.
      DTLAB_ASSERT(next != kNone);
      if (is_open(next)) {
        t = advance(next);
        DTLAB_ASSERT(records_[t].vertex[0] != kInf);
        root_facets_.insert(root_facets_.end(), fresh_.begin(), fresh_.end());
      } else {
        t = records_[next >> 2].neighbour[next & 3u] >> 2;
      }
    }
    return t;
  }

  // Ghost facet i (1, 2, 3) holds kInfinite and hull edge (x, y); its twin is the ghost that
  // holds (y, x).
  void link_ghosts() {
    struct Edge {
      std::uint64_t key;
      std::uint32_t facet;
    };
    std::vector<Edge> edges;
    edges.reserve(3 * ghosts_.size());
    for (const std::uint32_t g : ghosts_)
      for (std::uint32_t i = 1; i < 4; ++i) {
        const auto v = facet(4 * g + i);  // (kInfinite, x, y)
        edges.push_back({std::uint64_t{v[1]} << 32 | v[2], 4 * g + i});
      }
    std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.key < b.key; });
    for (const Edge& e : edges) {
      const std::uint64_t reversed = e.key << 32 | e.key >> 32;
      const auto it = std::lower_bound(edges.begin(), edges.end(), reversed,
                                       [](const Edge& x, std::uint64_t key) { return x.key < key; });
      if (it == edges.end() || it->key != reversed)
        throw InternalError("divide-conquer 3D Delaunay: hull edge without a second hull facet");
      records_[e.facet >> 2].neighbour[e.facet & 3u] = it->facet;
    }
  }

  const KdTree& tree_;
  std::span<const Vec3> P_;
  std::vector<T3::Record>& records_;
  dewall::ApexSearch search_;
  OpenFacets open_;
  std::size_t limit_ = 0;
  std::vector<std::uint32_t> fresh_, root_facets_, deferred_, ghosts_;
};

}  // namespace

void delaunay3d_divide_conquer(PreparedPoints3& input, const Delaunay3dOptions& /*options*/,
                               Tetrahedralization3& tetrahedralization) {
  DTLAB_ASSERT(input.distinct.size() >= 4 && input.degenerate_message.empty());
  const KdTree tree(input.points, input.distinct);
  tetrahedralization.clear_tetrahedra();
  const std::size_t m = input.distinct.size();
  tetrahedralization.reserve_tetrahedra(std::min<std::size_t>(7 * m + m / 2 + 64, T3::kMaxTetrahedra));
  std::vector<T3::Record>& records = tetrahedralization.mutable_records();
  DeWall(tree, records).run();
  // Ranks back to input ids.
  const auto ids = tree.ids();
  for (T3::Record& r : records)
    for (std::uint32_t& v : r.vertex)
      if (v != kInf) v = ids[v];
}

}  // namespace dtlab
