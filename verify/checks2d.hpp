// Exact checkers for 2D Delaunay triangulations given as plain arrays: points, and triangles as
// counter-clockwise triples of 0-based point indices. Independent of any mesh structure, so
// every variant, the fuzzers, the benchmarks and the CLI check their output the same way.
//
// Why these checks prove "the Delaunay triangulation of the points" (book §2.1, the Delaunay
// lemma): if every triangle is strictly counter-clockwise (check_orientation2), every edge is
// shared by at most two triangles in opposite directions (check_topology2), and the unpaired
// edges are exactly the convex hull's edges, counter-clockwise, collinear hull points included
// (check_hull_coverage2), then the triangles' boundary chain is the hull polygon, so each point
// inside the hull is covered by exactly one triangle (the degree of the map equals the winding
// number, 1) and the total area equals the hull's — exactly, without computing it. If moreover
// every interior edge is locally Delaunay under the perturbed incircle (check_empty_circle2),
// the perturbed lifting is locally convex, hence convex, and the triangulation is the unique
// perturbed Delaunay triangulation that every dtlab variant must produce. check_unreferenced
// adds that every point except the declared duplicates is a vertex.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/vec.hpp"
#include "verify/problem_report.hpp"

namespace dtlab {

using TriangleIds = std::array<std::uint32_t, 3>;

struct CheckReport2 : ProblemReport {  // ok, problems (each naming its item), problem_count
  // Counts filled in by the checks that compute them (0 where not computed).
  std::size_t points = 0;
  std::size_t triangles = 0;
  std::size_t referenced_points = 0;
  std::size_t interior_edges = 0;
  std::size_t boundary_edges = 0;
  std::size_t hull_points = 0;  // convex hull vertices including collinear ones on hull edges
  std::size_t duplicates = 0;
  std::size_t incircle_tests = 0;

  // Appends other's problems; counts are taken from other where it computed them.
  void merge(const CheckReport2& other);
};

// Vertex ids valid and distinct; every edge in at most two triangles, in opposite directions;
// each vertex's triangles form one fan (manifold); the triangles form one connected disk:
// triangles = 2 n' - 2 - h for n' referenced vertices and h boundary vertices.
CheckReport2 check_topology2(std::span<const Vec2> points, std::span<const TriangleIds> triangles);

// Every triangle strictly counter-clockwise by the exact orient2d.
CheckReport2 check_orientation2(std::span<const Vec2> points, std::span<const TriangleIds> triangles);

// For every edge shared by two triangles, the vertex of the second opposite the edge is not
// inside the circumcircle of the first by the exact, perturbed incircle (the tie-break all
// variants share). Reports each offending edge.
CheckReport2 check_empty_circle2(std::span<const Vec2> points, std::span<const TriangleIds> triangles);

// The unpaired (boundary) edges are exactly the counter-clockwise convex hull edges of the
// referenced points, every point lying on a hull edge being a hull vertex.
CheckReport2 check_hull_coverage2(std::span<const Vec2> points, std::span<const TriangleIds> triangles);

// `duplicates` (indices into points) are referenced by no triangle and each coincides with a
// referenced point; every other point is referenced, and no two of them coincide. With no
// triangles at all, the other points must be collinear (or fewer than three).
CheckReport2 check_unreferenced(std::span<const Vec2> points, std::span<const TriangleIds> triangles,
                                std::span<const std::uint32_t> duplicates);

// All of the above (after checking the coordinates are in the supported range).
CheckReport2 verify_delaunay2d(std::span<const Vec2> points, std::span<const TriangleIds> triangles,
                               std::span<const std::uint32_t> duplicates = {});

// Each triangle rotated to start at its smallest id (orientation kept), then sorted: equal for
// two variants iff they produced the same triangles.
std::vector<TriangleIds> canonical_triangle_set(std::span<const TriangleIds> triangles);

// {"ok":true,"problem_count":0,"counts":{...},"problems":[...]}
std::string to_json(const CheckReport2& report);
// One summary line, then one problem per line.
std::string to_text(const CheckReport2& report);

}  // namespace dtlab
