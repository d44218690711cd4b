// The Schönhardt family of polyhedra that cannot be tetrahedralized without Steiner points
// (book §3.5; Schönhardt 1928, Rambau 2005 for twisted prisms, Bagemihl 1948 for every number
// of vertices, Chazelle 1984 for the Θ(n²) lower bound), each as a closed triangulated
// surface: points and triangles, counter-clockwise seen from outside (outward normals), every
// coordinate a double.
//
// Twisted n-gonal prism (n >= 3), drawn once:
//
//   top    t_k = (r cos(φ_k + θ), r sin(φ_k + θ), h)      φ_k = 2πk / n,  θ = twist
//   bottom b_k = (r cos φ_k,      r sin φ_k,      0)       vertex ids: b_k = k, t_k = n + k
//
//        t_k ------ t_{k+1}      side k is the quadrilateral b_k b_{k+1} t_{k+1} t_k, split by
//         |         /  |         a diagonal. ReflexDiagonal (Schönhardt) takes b_k t_{k+1}, the
//         |      /     |         longer one, which a positive twist pulls inside: triangles
//         |   /        |         (b_k, b_{k+1}, t_{k+1}) and (b_k, t_{k+1}, t_k). ConvexDiagonal
//        b_k ------ b_{k+1}      takes b_{k+1} t_k: the convex hull's faces.
//
//   The reflex diagonals run cyclically (each side's rises the same way round), which is why
//   even the untwisted prism (θ = 0, planar sides) with them has no tetrahedralization: of the
//   eight diagonal patterns of a triangular prism only the two cyclic ones have none.
//   bottom and top: fans from b_0 and t_0. 2n vertices, 4n - 4 triangles. The twisted triangular
//   prism with ReflexDiagonal and 0 < θ < 60° is Schönhardt's polyhedron; for an n-gon the
//   side diagonals stay reflex for 0 < θ < 180°/n. The coordinates are the doubles that
//   std::cos / std::sin give (not correctly rounded): the polyhedron IS those doubles.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

struct ClosedSurface3 {
  std::vector<Vec3> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // outward, counter-clockwise from outside
};

enum class PrismDiagonal { ReflexDiagonal, ConvexDiagonal };

struct TwistedPrismOptions {
  int sides = 3;               // n >= 3
  double twist_degrees = 30;   // θ; 0 gives the untwisted (convex) prism
  int layers = 1;              // a stack: layer ℓ's top is layer ℓ + 1's bottom, twisted by θ again
  double radius = 1.0;
  double layer_height = 1.0;
  Vec3 offset{0, 0, 0};        // added to every point (after rounding each term: exact when representable)
  PrismDiagonal diagonal = PrismDiagonal::ReflexDiagonal;
};

// The twisted prism (or stack of them). Vertex id of ring ℓ (0 = bottom), corner k: ℓ n + k.
// Throws InputError for sides < 3, layers < 1, a non-positive radius or layer height.
ClosedSurface3 twisted_prism(const TwistedPrismOptions& options);

// Schönhardt's polyhedron: twisted_prism with 3 sides, one layer, ReflexDiagonal.
ClosedSurface3 schonhardt_polyhedron(double twist_degrees);

// A Bagemihl polyhedron: for every n >= 6, a polyhedron with n vertices on which no
// tetrahedron lies inside it, so it has no tetrahedralization without Steiner points
// (Bagemihl 1948 showed such polyhedra exist for every n; his own coordinates were not at hand,
// so the construction is ours). Schönhardt's polyhedron (twist θ) with its convex side edge
// b_2 t_2 replaced by a chain of m = n - 6 points bent into the solid:
//
//   c_j = b_2 + s (t_2 - b_2) + bend 4 s (1 - s) u + bend s (1 - s) (2 s - 1) w,  s = j / (m + 1)
//
// u: the unit vector from the edge's midpoint to the axis point (0, 0, 1/2); w: the unit normal
// of the plane of the edge and u. The curve is an affine image of (s, s², s³), so no four of
// b_2, c_1..c_m, t_2 are coplanar (the exhaustive search needs that). The surface's graph is a
// bipyramid over the (n-2)-gon b_0 b_2 c_1..c_m t_2 t_1 with apexes b_1 and t_0 (the two
// triangles at b_2 t_2 become fans from them): it has no K4, so a tetrahedron inside would need
// a segment between two non-adjacent vertices inside, and every such segment leaves the solid:
// the chain's dents push the chords between its points out, and the twist keeps the segments
// from a chain point to b_0 and t_1 out as it keeps b_0 t_2 and b_2 t_1 out. Checked exactly
// for n = 6..16 (verify/tests/constrained3d_test.cpp: no tetrahedron on the vertices inside);
// the margins shrink like 1/n, and the bend must shrink with a small twist (at 5 degrees 0.05
// keeps the property up to n = 16 and 0.1 does not). Vertex ids: Schönhardt's 0..5
// (twisted_prism's), then c_1..c_m.
// Throws InputError for n < 6, a twist outside (0, 60) degrees or a bend outside (0, 1/2].
ClosedSurface3 bagemihl_polyhedron(int vertices, double twist_degrees = 30, double bend = 0.1);

// Chazelle's polyhedron with n notches on each side: the box [0, n+1] x [0, n+1] x [0, 4]
// with n wedges cut from the bottom (edges parallel to y at x = 1..n, tips at height
// 2 - gap/2) and n from the top (parallel to x at y = 1..n, tips at 2 + gap/2); each wedge is
// 1/2 wide at its base. The thin layer between the two families of tips forces Θ(n²) Steiner
// points in any tetrahedralization (Chazelle 1984). Every coordinate is a dyadic rational
// (gap a power of two), so volumes and orientations are exact in doubles' rationals.
// Throws InputError for n < 1 or a gap that is not in (0, 1].
ClosedSurface3 chazelle_polyhedron(int n, double gap = 1.0 / 16);

}  // namespace dtlab
