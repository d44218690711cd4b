// A 2D Delaunay triangulation that changes one point at a time: insert, remove, move (book §2,
// §8.3.4; O. Devillers, "On deletion in Delaunay triangulations", IJCGA 2002).
//
// Why "insert then remove gives back exactly the triangulation without the point": dtlab breaks
// every cocircular tie by one symbolic perturbation (kernel/predicates/perturbation.hpp), a
// lifting of each point to |p|^2 + eps^r(p) where r(p) is the rank of p in lexicographic order
// of its COORDINATES (x, then y), not its index or insertion time. The perturbed Delaunay
// triangulation is therefore a function of the point set alone: every registered variant
// builds it, and so must any history of insertions and removals. Insertion (Bowyer-Watson
// cavity, incircle_perturbed) and removal (below) take every decision with that same predicate,
// so the triangles after any sequence equal those of delaunay2d() on the survivors, vertex ids
// aside; verify/tests/dynamic_delaunay2_test.cpp checks it against every registered variant.
//
// Removal: the triangles of the survivors inside the hole left by v are the Delaunay triangles
// of the hole's polygon (its edges are Delaunay edges of the survivors, so the constrained and
// the unconstrained triangulation agree there). They are found as ears: (x, y, z) consecutive on
// the polygon is clipped when it is convex and no other polygon vertex is in conflict with it
// under incircle_perturbed; the perturbed triangulation is unique, so every clipped ear is one
// of its triangles and an ear always exists (a polygon's triangulation has two). A vertex on
// the hull has kInfinite in its polygon; an ear through kInfinite is a ghost, in conflict with
// a point as mesh/triangulation2.hpp says (beyond its hull edge, or strictly inside it).
//
// The structure is the shared Mesh2 (mesh/mesh2.hpp: free lists, vertex -> triangle, the nav2
// walk); ids of removed vertices are reused by later insertions, as Mesh2's free list does.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "algorithms/common/dynamic_delaunay_base.hpp"
#include "algorithms/common/dynamic_delaunay_errors.hpp"
#include "algorithms/common/point_removal.hpp"
#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "kernel/vec.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab {

struct DynamicDelaunay2Stats {
  std::uint64_t inserted = 0;
  std::uint64_t removed = 0;
  std::uint64_t cavity_triangles = 0;  // triangles replaced by insertions
  std::uint64_t ear_tests = 0;         // candidate ears tested by removals
};

class DynamicDelaunay2 : public DynamicDelaunayBase<DynamicDelaunay2, Mesh2, DynamicDelaunay2Stats, 3> {
 public:
  // The Delaunay triangulation of `points` (vertex id = index), built by delaunay2d() with
  // `options` (its variant). DuplicatePointError for a repeated point (naming both indices),
  // DegenerateRemovalError when the points make no triangle, InputError as delaunay2d().
  explicit DynamicDelaunay2(std::span<const Vec2> points, const Delaunay2dOptions& options = {});

  // Inserts p and returns its vertex id. DuplicatePointError (naming the vertex) if p is a
  // live vertex already; InputError for a coordinate out of the supported range.
  std::uint32_t insert(const Vec2& p);
  // Removes vertex v. UnknownVertexError if v is not live; DegenerateRemovalError, leaving the
  // triangulation unchanged, if the other vertices are fewer than three or all collinear.
  void remove(std::uint32_t v);

  // move, contains, vertex_count, mesh, stats, finite_elements: algorithms/common/dynamic_delaunay_base.hpp.
  std::uint64_t finite_triangle_count() const noexcept { return finite_; }
  // The live finite triangles, counter-clockwise, vertex ids.
  std::vector<std::array<std::uint32_t, 3>> finite_triangles() const { return finite_elements(); }

 private:
  bool in_conflict(std::uint32_t t, const Vec2& p) const;
  bool is_delaunay_ear(const std::vector<std::uint32_t>& polygon, std::size_t i);
  std::uint32_t add(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  void check_removable(std::uint32_t v, const std::vector<std::uint32_t>& ball) const;

  // Scratch, kept between calls.
  std::vector<std::uint32_t> cavity_, stack_, handles_, ball_, polygon_, outside_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t epoch_ = 0;
};

// The Delaunay triangles of `points` less the points `indices` (input ids, removed in that order),
// with the times of building and removing (algorithms/common/point_removal.hpp).
using Delaunay2dRemoval = PointRemoval<3, DynamicDelaunay2Stats>;
Delaunay2dRemoval delaunay2d_remove(std::span<const Vec2> points, std::span<const std::uint32_t> indices,
                                     const Delaunay2dOptions& options = {});

}  // namespace dtlab
