// An exact decision of whether a small polyhedron has a tetrahedralization without Steiner
// points (book §3.5: Schönhardt's polyhedron has none), by exhaustive search over the
// tetrahedra on its vertices that lie inside it.
//
// Candidates: every four vertices that are not coplanar whose tetrahedron's interior misses
// the boundary and whose centroid is inside (parity of a ray with a symbolic perturbation).
// Interiors are compared by the separating axis theorem: two convex polytopes have disjoint
// interiors iff a plane normal to a face of either, or to an edge of each, weakly separates
// them. Everything is decided in exact rationals (GMP); no tolerance anywhere.
//
// Search: every boundary triangle needs the one candidate on its inner side; every face of a
// chosen tetrahedron that is not a boundary triangle needs a second chosen tetrahedron; the
// most constrained open face is branched on first. This finds every FACE-TO-FACE
// tetrahedralization; when every plane through four or more vertices leaves all vertices on
// one closed side (checked: otherwise InputError), two tetrahedra of any tetrahedralization
// can only touch along a whole common face, so the search is complete.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

struct ExhaustiveTetrahedralizationResult {
  bool exists = false;
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;  // one tetrahedralization when it exists
  std::size_t candidates = 0;                            // tetrahedra inside the polyhedron
  std::uint64_t nodes = 0;                               // search nodes visited
};

// points: the polyhedron's vertices (all used by faces); faces: a closed, consistently
// oriented triangulated surface bounding one polyhedron (check_plc-clean; not re-checked).
// Throws InputError for more than 16 vertices, when the search would not be complete (above),
// or when it visits more than node_limit nodes.
ExhaustiveTetrahedralizationResult find_tetrahedralization_without_steiner(
    std::span<const Vec3> points, std::span<const std::array<std::uint32_t, 3>> faces,
    std::uint64_t node_limit = 10'000'000);

}  // namespace dtlab
