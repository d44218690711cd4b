// The working tetrahedralization of variant "flip" (flip.cpp): the records of
// Tetrahedralization3, a free list of dead slots, and one operation that every step of the
// variant is made of, replace(): a small set of tetrahedra goes, a set of new ones covering the
// same region comes, and the new facets are linked to each other and to the old region's outer
// facets by matching their vertex triples. A 1->4, 2->6 or n->2n split and a 2->3, 3->2 or 4->4
// flip (Joe 1991; Edelsbrunner & Shah 1996) differ only in which tetrahedra they list. The
// frequent moves (1->4, 2->3, 3->2, 4->4) also have direct versions (flip_moves.cpp) that link
// by the known structure instead of matching, and so cost a few stores each.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

class FlipMesh {
 public:
  using Record = Tetrahedralization3::Record;
  using Tuple = std::array<std::uint32_t, 4>;

  explicit FlipMesh(std::vector<Record>& records);
  // Works on an existing tetrahedralization's records (compact, as tetrahedralization3.hpp
  // requires): they are moved and flipped in place; finish() makes them compact again.
  struct Adopt {};
  FlipMesh(std::vector<Record>& records, Adopt);

  // Raw view of the records; valid until the next replace().
  const Record* records() const noexcept { return r_; }
  // Slots in use, dead ones included: every tetrahedron id is below it.
  std::size_t slots() const noexcept { return count_; }
  std::size_t live_count() const noexcept { return count_ - free_.size(); }
  bool is_dead(std::uint32_t t) const noexcept { return r_[t].vertex[0] == Tetrahedralization3::kNone; }

  // Removes the tetrahedra `old` and adds `fresh` (each positive; kInfinite may stand anywhere,
  // it is moved to index 0 by an even permutation). The outer facets of `old` (those whose twin
  // is not in `old`) must be exactly the facets of `fresh` that no other fresh tetrahedron
  // shares; otherwise InternalError. The ids of the new tetrahedra go to `ids`, in `fresh`
  // order. Old slots are reused first.
  void replace(std::span<const std::uint32_t> old, std::span<const Tuple> fresh, std::vector<std::uint32_t>& ids);

  // Topological moves; the caller has checked the geometry. Each writes the new tetrahedra's ids
  // to `ids`, reusing the old slots.
  //   split14: t becomes (facet i of t as listed, p) for i = 0..3.
  void split14(std::uint32_t t, std::uint32_t p, std::vector<std::uint32_t>& ids);
  //   flip23: t1 = (v0, v1, v2, p) and t2 = (v0, v2, v1, d) (up to even permutations) become
  //   (v[k], v[k+1], d, p) for k = 0, 1, 2.
  void flip23(std::uint32_t t1, std::uint32_t t2, const std::array<std::uint32_t, 3>& v, std::uint32_t p,
              std::uint32_t d, std::vector<std::uint32_t>& ids);
  //   flip32: t1 = (e0, e1, f, p), t2 = (e0, e1, f, d), t3 = (e0, e1, p, d) (as vertex sets)
  //   become (f, d, p, e0) and (d, f, p, e1).
  void flip32(std::uint32_t t1, std::uint32_t t2, std::uint32_t t3, std::uint32_t e0, std::uint32_t e1,
              std::uint32_t f, std::uint32_t p, std::uint32_t d, std::vector<std::uint32_t>& ids);
  //   flip44: t1 = (e0, e1, f, p), t2 = (e0, e1, f, d), t3 = (e0, e1, d, x), t4 = (e0, e1, p, x)
  //   (as vertex sets) become (e1, f, d, p), (f, e0, d, p), (e0, x, d, p), (x, e1, d, p).
  void flip44(std::uint32_t t1, std::uint32_t t2, std::uint32_t t3, std::uint32_t t4, std::uint32_t e0,
              std::uint32_t e1, std::uint32_t f, std::uint32_t x, std::uint32_t p, std::uint32_t d,
              std::vector<std::uint32_t>& ids);

  // Removes the dead slots by moving the last live tetrahedra into them; the records vector
  // then holds exactly the live tetrahedra.
  void finish();

 private:
  struct FacetEntry {
    std::array<std::uint32_t, 3> key;  // the facet's vertex ids, sorted
    std::uint32_t handle;               // a new facet, or the outer twin of an old one
    bool outer;
  };

  std::uint32_t new_slot();
  void grow(std::size_t k);
  void release(std::uint32_t t);
  // Writes positive tuple v into slot t with kInfinite moved to index 0; returns the mask m such
  // that the vertex at index j of v is now at index j ^ m.
  std::uint32_t write(std::uint32_t t, const Tuple& v) noexcept;
  void link(std::uint32_t g, std::uint32_t h) noexcept {
    r_[g >> 2].neighbour[g & 3u] = h;
    r_[h >> 2].neighbour[h & 3u] = g;
  }
  // The twin of t's facet opposite its vertex v.
  std::uint32_t twin_opposite(std::uint32_t t, std::uint32_t v) const noexcept;

  std::vector<Record>& records_;
  Record* r_ = nullptr;
  std::size_t count_ = 0;
  std::vector<std::uint32_t> free_;
  std::vector<FacetEntry> entries_;
  std::vector<std::uint32_t> old_sorted_;
};

}  // namespace dtlab
