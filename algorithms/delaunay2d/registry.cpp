#include "algorithms/delaunay2d/registry.hpp"

namespace dtlab {

// Each variant's run function lives in its own file.
void delaunay2d_incremental(const PreparedPoints2& input, Triangulation2& triangulation);
void delaunay2d_divide_conquer(const PreparedPoints2& input, Triangulation2& triangulation);
void delaunay2d_sweep(const PreparedPoints2& input, Triangulation2& triangulation);
void delaunay2d_flip(const PreparedPoints2& input, Triangulation2& triangulation);

const Registry<Delaunay2dVariant>& delaunay2d_variants() {
  static const Registry<Delaunay2dVariant> variants{
      "2D Delaunay algorithm",
      {Delaunay2dVariant{"incremental",
                      "reduced incremental method (Delaunay kernel, book §2.4-2.6): BRIO/Hilbert order, "
                      "visibility walk from the last insertion, cavity grown by adjacency",
                      &delaunay2d_incremental},
    Delaunay2dVariant{"divide-conquer",
                      "divide and conquer (Lee & Schachter; Guibas & Stolfi merge by lower tangent and rising "
                      "bubble; Dwyer's alternating cuts) on a flat quad-edge structure",
                      &delaunay2d_divide_conquer},
    Delaunay2dVariant{"sweep",
                      "sweep-hull (Sinclair's s-hull): points by exact distance from a centre, each joined to "
                      "the hull edges it strictly sees (angle hash), then Lawson flips of the edges opposite it",
                      &delaunay2d_sweep},
    Delaunay2dVariant{"flip",
                      "Lawson flips (book §2, Theorem 2.2): lexicographic fan sweep by orient2d alone, then "
                      "every edge not locally Delaunay flipped",
                      &delaunay2d_flip}}};
  return variants;
}

}  // namespace dtlab
