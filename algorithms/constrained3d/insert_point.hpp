// Insertion of new points into a Delaunay tetrahedralization, one at a time, for the Steiner
// points of constrained3d: Bowyer-Watson (Bowyer 1981, Watson 1981; book §2.4 in 3D) on
// Tetrahedralization3, with the conflict rule of the delaunay3d variants (tetrahedralization3.hpp
// and algorithms/delaunay3d/registry.hpp: perturbed in-sphere for finite tetrahedra; for ghosts,
// strictly beyond the hull facet, or on its plane and in conflict with the finite tetrahedron
// across it). The result is therefore the very tetrahedralization delaunay3d builds from all the
// points at once. Written on Tetrahedralization3 itself rather than on the incremental
// variant's kernel so that the structure stays compact after every insertion (the recovery
// reads it between insertions).
#pragma once

#include <cstdint>
#include <vector>

#include "kernel/vec.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

class DelaunayInserter {
 public:
  // tet: a perturbed Delaunay tetrahedralization meeting the contract of tetrahedralization3.hpp
  // (not degenerate: at least one finite tetrahedron).
  explicit DelaunayInserter(Tetrahedralization3& tet);

  // Appends p to the points and inserts it; returns its vertex id. p must be in the supported
  // coordinate range (the caller checks). Throws InputError naming the vertex if p equals one.
  std::uint32_t insert(const Vec3& p);

 private:
  std::uint32_t locate(const Vec3& p) const;
  bool conflicts(std::uint32_t t, const Vec3& p) const;
  void remove_slot(std::uint32_t t);

  Tetrahedralization3& tet_;
  std::uint32_t last_ = 0;
  std::vector<std::uint32_t> cavity_, new_, mark_;
  std::uint32_t stamp_ = 0;
};

}  // namespace dtlab
