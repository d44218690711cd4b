// A 3D Delaunay tetrahedralization that changes one point at a time: insert, remove, move (book
// §2, §8.3.4; the removal follows Devillers and Teillaud, "Perturbations for Delaunay and
// weighted Delaunay 3D triangulations", CGTA 2011, §5: the hole is filled with the Delaunay
// tetrahedralization of its vertices, restricted to the hole).
//
// Why "insert then remove gives back exactly the tetrahedralization without the point": every
// cospherical tie is broken by the kernel's one symbolic perturbation
// (kernel/predicates/perturbation.hpp), keyed by the lexicographic rank of each point's
// COORDINATES (x, then y, then z), not by its index or insertion time, so the perturbed Delaunay
// tetrahedralization is a function of the point set alone. Insertion (Bowyer-Watson cavity under
// insphere_perturbed, ghosts with the coplanar rule of algorithms/delaunay3d/cavity_kernel.hpp)
// and removal both decide with that predicate, so any sequence of changes ends in the
// tetrahedra delaunay3d() builds from scratch on the survivors, vertex ids aside;
// verify/tests/dynamic_delaunay3_test.cpp checks it against every registered variant.
//
// Removal of v: the tetrahedra of the survivors inside v's ball (the region R that v's finite
// tetrahedra cover, cut by the survivors' new hull where v was on the hull) have all their
// vertices on v's link, and are those of D, the tetrahedralization that delaunay3d() builds on
// the link's finite vertices (same perturbation), inside R. They are collected by a search in D
// that starts across each facet of the ball's boundary, on v's side, and crosses no boundary
// facet; a ghost of D it meets is a facet of the new hull and comes in as a ghost. When the
// link's vertices are coplanar (v a hull vertex above a flat link), D has no tetrahedron and
// each boundary facet becomes a hull facet. The new tetrahedra are glued to each other and to
// the rest by their facets' vertex triples.
//
// The structure is the shared Mesh3 (mesh/mesh3.hpp); D is a Tetrahedralization3 from
// delaunay3d() with the variant given at construction (one thread), a call that costs more than
// a tuned small-set routine would: about half of a removal's time, yet removal is no slower than
// CGAL's (README). Ids of removed vertices are reused by later insertions, as Mesh3's free list
// does.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "algorithms/common/dynamic_delaunay_base.hpp"
#include "algorithms/common/dynamic_delaunay_errors.hpp"
#include "algorithms/common/point_removal.hpp"
#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "kernel/vec.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab {

struct DynamicDelaunay3Stats {
  std::uint64_t inserted = 0;
  std::uint64_t removed = 0;
  std::uint64_t cavity_tetrahedra = 0;  // tetrahedra replaced by insertions
  std::uint64_t link_vertices = 0;      // finite link vertices of the removed vertices
  std::uint64_t flat_links = 0;         // removals of a hull vertex whose link is coplanar
};

class DynamicDelaunay3 : public DynamicDelaunayBase<DynamicDelaunay3, Mesh3, DynamicDelaunay3Stats, 4> {
 public:
  // The Delaunay tetrahedralization of `points` (vertex id = index), built by delaunay3d() with
  // `options`. DuplicatePointError for a repeated point (naming both indices),
  // DegenerateRemovalError when the points make no tetrahedron, InputError as delaunay3d().
  explicit DynamicDelaunay3(std::span<const Vec3> points, const Delaunay3dOptions& options = {});

  // Inserts p and returns its vertex id. DuplicatePointError (naming the vertex) if p is a live
  // vertex already; InputError for a coordinate out of the supported range.
  std::uint32_t insert(const Vec3& p);
  // Removes vertex v. UnknownVertexError if v is not live; DegenerateRemovalError, leaving the
  // tetrahedralization unchanged, if the other vertices are fewer than four or all coplanar.
  void remove(std::uint32_t v);

  // move, contains, vertex_count, mesh, stats, finite_elements: algorithms/common/dynamic_delaunay_base.hpp.
  std::uint64_t finite_tetrahedron_count() const noexcept { return finite_; }
  // The live finite tetrahedra, positively oriented, vertex ids.
  std::vector<std::array<std::uint32_t, 4>> finite_tetrahedra() const { return finite_elements(); }

 private:
  bool in_conflict(std::uint32_t t, const Vec3& p) const;
  std::uint32_t add(std::array<std::uint32_t, 4> tet);
  void glue(std::span<const std::uint32_t> handles);
  void remove_ball(std::uint32_t v);

  // The facets of the link's tetrahedralization by their sorted vertex triples: open addressing,
  // a stamp per slot so that reset() costs nothing but a possible growth.
  class FacetIndex {
   public:
    void reset(std::size_t entries);
    void insert(const std::array<std::uint32_t, 3>& key, std::uint32_t handle);
    std::uint32_t find(const std::array<std::uint32_t, 3>& key) const;  // one handle, or kNone

   private:
    struct Slot {
      std::array<std::uint32_t, 3> key;
      std::uint32_t handle;
      std::uint32_t stamp;
    };
    std::size_t slot_of(const std::array<std::uint32_t, 3>& key) const noexcept;
    std::vector<Slot> slots_;
    std::uint32_t stamp_ = 0;
  };

  Delaunay3dOptions link_options_;
  std::vector<std::uint32_t> cavity_, stack_, ball_, open_, outside_, stamp_;
  // Scratch of remove(): vertex -> link index, the link, its points, the boundary facets in link
  // numbering, D's facet index, boundary marks, kept tetrahedra and their search queue.
  std::vector<std::uint32_t> local_, link_, boundary_, made_, queue_;
  std::vector<Vec3> link_points_;
  std::vector<std::array<std::uint32_t, 3>> faces_;
  FacetIndex facets_;
  std::uint32_t epoch_ = 0;
};

// The Delaunay tetrahedra of `points` less the points `indices` (input ids, removed in that order),
// with the times of building and removing (algorithms/common/point_removal.hpp).
using Delaunay3dRemoval = PointRemoval<4, DynamicDelaunay3Stats>;
Delaunay3dRemoval delaunay3d_remove(std::span<const Vec3> points, std::span<const std::uint32_t> indices,
                                     const Delaunay3dOptions& options = {});

}  // namespace dtlab
