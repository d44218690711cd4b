// The point structure of variant "divide-conquer" (DeWall, Cignoni, Montani, Scopigno, CAD 1998):
// a kd-tree that is both the hierarchy of walls (each node split at the median of its longest
// axis) and the accelerator of DeWall's "make simplex" search. DeWall used a uniform grid; a
// kd-tree with point bounding boxes does the same expanding search but adapts to clustered input,
// where a grid cell can hold most of the points.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab::dewall {

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;

// Points are numbered by rank in kd order: the points of a node are the ranks [begin, end), and
// a split node's children are [begin, mid) and [mid, end).
struct KdNode {
  Vec3 low, high;  // bounding box of the node's points (their own coordinates, so exact)
  std::uint32_t begin = 0, mid = 0, end = 0;  // mid: where the right child begins (end for a leaf)
  std::uint32_t left = kNone;                  // children left and left + 1; kNone for a leaf

  bool is_leaf() const noexcept { return left == kNone; }
};

class KdTree {
 public:
  static constexpr std::uint32_t kLeafSize = 16;

  // The distinct points `distinct` (input ids) of `input`, sorted into kd order. A node is split
  // at the median of its longest axis, comparing (that axis, the next, the one after)
  // lexicographically, so that equal coordinates still split into two halves that a plane
  // separates (a symbolically tilted one).
  KdTree(std::span<const Vec3> input, std::span<const std::uint32_t> distinct);

  std::span<const Vec3> points() const noexcept { return points_; }  // by rank
  std::span<const std::uint32_t> ids() const noexcept { return ids_; }  // rank -> input id
  std::span<const KdNode> nodes() const noexcept { return nodes_; }     // nodes()[0] is the root

  // The region of node k: the ancestors' split planes bound it (closed: a point on a split
  // plane can be on either side); every point outside the node lies outside its interior.
  const std::array<Vec3, 2>& cell(std::uint32_t k) const noexcept { return cells_[k]; }
  std::uint32_t parent(std::uint32_t k) const noexcept { return parents_[k]; }
  int split_axis(std::uint32_t k) const noexcept { return axes_[k]; }
  std::uint32_t leaf_of(std::uint32_t rank) const noexcept { return leaf_of_[rank]; }

 private:
  std::vector<Vec3> points_;
  std::vector<std::uint32_t> ids_;
  std::vector<KdNode> nodes_;
  std::vector<std::array<Vec3, 2>> cells_;
  std::vector<std::uint32_t> parents_;
  std::vector<std::uint8_t> axes_;
  std::vector<std::uint32_t> leaf_of_;
};

// DeWall's make simplex. For a facet (a, b, c) of a Delaunay tetrahedron, the apex of the Delaunay
// tetrahedron on its positive side (orient3d(a, b, c, p) > 0): the point p on that side whose
// perturbed sphere (a, b, c, p) holds no other point of that side, or kNone when no point is on
// that side (a hull facet). Decided by orient3d and insphere_perturbed only; floating-point
// spheres with proven error bounds only prune the search.
class ApexSearch {
 public:
  explicit ApexSearch(const KdTree& tree) : tree_(tree) {}
  std::uint32_t apex(std::uint32_t a, std::uint32_t b, std::uint32_t c);

  std::uint64_t nodes_visited() const noexcept { return nodes_visited_; }

 private:
  struct Query;
  void explore(std::uint32_t subtree, Query& query);

  const KdTree& tree_;
  std::vector<std::uint32_t> stack_;
  std::uint64_t nodes_visited_ = 0;
};

}  // namespace dtlab::dewall
