#include "algorithms/delaunay3d/registry.hpp"

namespace dtlab {

// Each variant's run function lives in its own file.
void delaunay3d_incremental(PreparedPoints3& input, const Delaunay3dOptions& options,
                            Tetrahedralization3& tetrahedralization);
void delaunay3d_flip(PreparedPoints3& input, const Delaunay3dOptions& options,
                     Tetrahedralization3& tetrahedralization);
void delaunay3d_divide_conquer(PreparedPoints3& input, const Delaunay3dOptions& options,
                               Tetrahedralization3& tetrahedralization);
void delaunay3d_parallel(PreparedPoints3& input, const Delaunay3dOptions& options,
                         Tetrahedralization3& tetrahedralization);

const Registry<Delaunay3dVariant>& delaunay3d_variants() {
  static const Registry<Delaunay3dVariant> entries{
      "3D Delaunay algorithm",
      {Delaunay3dVariant{"incremental",
                      "reduced incremental method (Delaunay kernel, book §2.4-2.6): BRIO/Hilbert order, "
                      "visibility walk from the last insertion, cavity grown by adjacency, ball joined to its "
                      "boundary, deleted tetrahedra recycled",
                      &delaunay3d_incremental},
    Delaunay3dVariant{"flip",
                      "insertion by a 1->4 split (2->6 on a facet, n->2n on an edge) followed by 2->3 / 3->2 / 4->4 flips on "
                      "the perturbed in-sphere test (Joe 1991; Edelsbrunner-Shah 1996)",
                      &delaunay3d_flip},
    Delaunay3dVariant{"divide-conquer", "divide and conquer (DeWall, Cignoni-Montani-Scopigno 1998)",
                      &delaunay3d_divide_conquer},
    Delaunay3dVariant{"parallel",
                      "Delaunay kernel on several threads (--threads): each owns a slab of space (x, then y, then z "
                      "cuts), insertions whose walk or cavity leaves it deferred (after Marot-Pellerin-Remacle 2019)",
                      &delaunay3d_parallel, true}}};
  return entries;
}

}  // namespace dtlab
