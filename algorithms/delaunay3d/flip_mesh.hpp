// The working tetrahedralization of variant "flip" (flip.cpp): the records of
// Tetrahedralization3, a free list of dead slots, and one operation that every step of the
// variant is made of, replace(): a small set of tetrahedra goes, a set of new ones covering the
// same region comes, and the new facets are linked to each other and to the old region's outer
// facets by matching their vertex triples. A 1->4, 2->6 or n->2n split and a 2->3, 3->2 or 4->4
// flip (Joe 1991; Edelsbrunner & Shah 1996) differ only in which tetrahedra they list.
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

  std::vector<Record>& records_;
  Record* r_ = nullptr;
  std::size_t count_ = 0;
  std::vector<std::uint32_t> free_;
  std::vector<FacetEntry> entries_;
  std::vector<std::uint32_t> old_sorted_;
};

}  // namespace dtlab
