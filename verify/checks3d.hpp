// Exact checkers for 3D Delaunay tetrahedralizations (mesh/tetrahedralization3.hpp): every
// variant, the fuzzers, the benchmarks and the CLI check their output the same way.
//
// Why these checks prove "the Delaunay tetrahedralization of the points" (book §2.1, the
// Delaunay lemma, and its 3D form in Edelsbrunner's "Geometry and Topology for Mesh
// Generation" §2): the structure is a closed 3-manifold (check_topology3: twins, every edge's
// tetrahedra one cycle, every vertex's link a sphere, one connected piece), so the finite
// tetrahedra form a 3-chain whose boundary is the hull surface S (the facets under the ghosts),
// a topological sphere. Every finite tetrahedron is positive (check_orientation3), and S is
// locally convex, folds nowhere and faces outwards (check_hull3); a locally convex immersed
// closed surface in R^3 bounds a convex body (van Heijenoort 1952), so the tetrahedra cover it
// with multiplicity = the winding number of S, which check_coverage3 measures twice: exactly
// one tetrahedron holds a point chosen strictly inside one of them, and the exact sum of the
// tetrahedra's volumes equals the exact volume S encloses. Every distinct point is a vertex
// (check_unreferenced3), so the body is the convex hull. If moreover every interior facet is
// locally Delaunay under the perturbed in-sphere test (check_empty_sphere3), the perturbed
// lifting is locally convex, hence convex, and the hull facets triangulate each flat hull face
// under the ghost rule of incremental.cpp (check_hull3): the result is the unique perturbed
// Delaunay tetrahedralization, which every dtlab variant must produce. What the local checks
// cannot see (a vertex star wound twice about its vertex) the point-degree test catches where
// the chosen point lies in the doubly covered part; the variants are compared set-wise anyway.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "kernel/vec.hpp"
#include "mesh/tetrahedralization3.hpp"
#include "verify/problem_report.hpp"

namespace dtlab {

using TetrahedronIds = std::array<std::uint32_t, 4>;

struct CheckReport3 : ProblemReport {  // ok, problems (each naming its item), problem_count
  // Counts filled in by the checks that compute them (0 where not computed).
  std::size_t points = 0;
  std::size_t tetrahedra = 0;        // finite
  std::size_t hull_facets = 0;       // ghosts
  std::size_t referenced_points = 0;
  std::size_t interior_facets = 0;   // facets between two finite tetrahedra
  std::size_t edges = 0;             // finite edges
  std::size_t hull_vertices = 0;
  std::size_t duplicates = 0;
  std::size_t insphere_tests = 0;

  // Appends other's problems; counts are taken from other where it computed them.
  void merge(const CheckReport3& other);
};

// Tetrahedralization3::check_topology (twins symmetric, over the same facet reversed, ids in
// range, kInfinite only at index 0), then: the tetrahedra around every edge form one cycle
// through facets, every vertex's link (the infinite vertex's included) has Euler
// characteristic 2, and all tetrahedra are connected through facets. With at least one
// tetrahedron, there is at least one finite one and no ghost faces a ghost across its hull facet.
CheckReport3 check_topology3(const Tetrahedralization3& tetrahedralization);

// Every finite tetrahedron strictly positive by the exact orient3d.
CheckReport3 check_orientation3(const Tetrahedralization3& tetrahedralization);

// For every facet between two finite tetrahedra, the apex of one is outside the sphere of the
// other by the exact, perturbed in-sphere test (the tie-break all variants share).
CheckReport3 check_empty_sphere3(const Tetrahedralization3& tetrahedralization);
// Constrained Delaunay over a list of tetrahedra (each positive: the ones a result keeps, so
// that the domain they cover need not be convex): every facet two of them share that
// `constrained` does not name is locally Delaunay in the sense that defines a CDT, the vertex
// across not strictly inside the sphere (exact in-sphere, no perturbation: a CDT may have
// cospherical vertices where input triangles fix the choice). By the constrained Delaunay lemma
// (every unconstrained interior facet locally Delaunay; Shewchuk 2008, "General-dimensional
// constrained Delaunay and constrained regular triangulations") that proves the tetrahedra a
// CDT of what they cover.
CheckReport3 check_constrained_delaunay3(std::span<const Vec3> points,
                                         std::span<const std::array<std::uint32_t, 4>> tetrahedra,
                                         const std::function<bool(std::array<std::uint32_t, 3>)>& constrained);

// The hull: the finite tetrahedron under each ghost lies strictly on the inner side of its
// hull facet; at each hull edge the apex of the adjacent hull facet is not strictly beyond this
// one (locally convex); where the two are coplanar, they lie on opposite sides of the edge (no
// fold) and the apex is not in conflict with the ghost under the ghost rule (perturbed
// in-sphere with the finite tetrahedron under the ghost, tetrahedralization3.hpp).
CheckReport3 check_hull3(const Tetrahedralization3& tetrahedralization);

// Exact coverage: one point strictly inside a finite tetrahedron lies in the closed region of no
// other, and the exact sum of 6 x volume over the finite tetrahedra equals the exact volume
// enclosed by the hull facets (sum of det(a - o, b - o, c - o) over the outward hull facets,
// o a fixed point), both in GMP integers.
CheckReport3 check_coverage3(const Tetrahedralization3& tetrahedralization);

// `duplicates` (indices into the points) are referenced by no tetrahedron and each coincides
// with a referenced point; every other point is referenced and no two of them coincide. With no
// tetrahedra at all, the other points must be coplanar (or fewer than four).
CheckReport3 check_unreferenced3(const Tetrahedralization3& tetrahedralization,
                                 std::span<const std::uint32_t> duplicates);

// All of the above, after checking that the coordinates are in the supported range and that
// tetrahedralization.points() equals `points`. The geometric checks run only on a structure
// that passes check_topology3's first part (Tetrahedralization3::check_topology).
CheckReport3 verify_delaunay3d(std::span<const Vec3> points, const Tetrahedralization3& tetrahedralization,
                               std::span<const std::uint32_t> duplicates = {});

// One name per positive tetrahedron: the even permutation that puts the smallest id first and
// the smallest of the other three second; then sorted. Equal for two variants iff they
// produced the same finite tetrahedra.
std::vector<TetrahedronIds> canonical_tetrahedron_set(std::span<const TetrahedronIds> tetrahedra);
std::vector<TetrahedronIds> canonical_tetrahedron_set(const Tetrahedralization3& tetrahedralization);

// {"ok":true,"problem_count":0,"counts":{...},"problems":[...]}
std::string to_json(const CheckReport3& report);
// One summary line, then one problem per line.
std::string to_text(const CheckReport3& report);

}  // namespace dtlab
