// Insertion of new points into a Delaunay tetrahedralization, one at a time, for the Steiner
// points of constrained3d: the Bowyer-Watson cavity kernel of the delaunay3d variants
// (algorithms/delaunay3d/cavity_kernel.hpp; Bowyer 1981, Watson 1981, book §2.4 in 3D) run on
// the Tetrahedralization3 itself, with its conflict rule (perturbed in-sphere for finite
// tetrahedra; for ghosts, strictly beyond the hull facet, or on its plane and in conflict with
// the finite tetrahedron across it). The result is therefore the very tetrahedralization
// delaunay3d builds from all the points at once. The kernel leaves dead slots behind; compact()
// removes them once per batch rather than after every insertion.
#pragma once

#include <cstdint>

#include "algorithms/delaunay3d/cavity_kernel.hpp"
#include "kernel/vec.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

class DelaunayInserter {
 public:
  // tet: a perturbed Delaunay tetrahedralization meeting the contract of tetrahedralization3.hpp
  // (not degenerate: at least one finite tetrahedron). It must outlive the inserter and not be
  // modified by anyone else while the inserter is in use.
  explicit DelaunayInserter(Tetrahedralization3& tet);

  // Appends p to the points and inserts it; returns its vertex id. p must be in the supported
  // coordinate range (the caller checks). Throws InputError naming the vertex if p equals one
  // (then nothing changed). Afterwards the records may hold dead slots: call compact() before
  // reading the structure.
  std::uint32_t insert(const Vec3& p);

  // Makes the structure compact again (the contract of tetrahedralization3.hpp).
  void compact();

 private:
  Tetrahedralization3& tet_;
  CavityKernel kernel_;
  bool dirty_ = false;
};

}  // namespace dtlab
