// Every triangulation of a convex polygon, enumerated: the candidate retriangulations of a shell
// (book §8.3.3). Removing the edge (a, b) of a shell of n tetrahedra leaves the polygon of its n
// other vertices; each triangulation T of that polygon gives the 2(n - 2) tetrahedra
// {t + a, t + b : t in T}. There are Cat(n - 1) of them (book's numbering, Table 8.1), built
// from C(n, 3) distinct triangles.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace dtlab {

using PolygonTriangle = std::array<std::uint8_t, 3>;  // polygon vertex indices, increasing

// Calls `visit` once per triangulation of the convex polygon 0, 1, ..., n-1 (n - 2 triangles
// each, vertices increasing). n must be in [3, 24] (Cat(22) ~ 6.6e11 triangulations bound the
// useful range far below that); throws InputError otherwise.
void for_each_polygon_triangulation(int n, const std::function<void(const std::vector<PolygonTriangle>&)>& visit);

// The first triangulation, in for_each_polygon_triangulation's order, whose triangles all pass
// triangle_ok and that accept takes; empty if none. A triangle that fails triangle_ok is not
// descended into, so every triangulation holding it is skipped unvisited (the search of a shell's
// valid retriangulations, where most triangles are invalid, visits few).
std::vector<PolygonTriangle> find_polygon_triangulation(int n, const std::function<bool(const PolygonTriangle&)>& triangle_ok,
                                                        const std::function<bool(const std::vector<PolygonTriangle>&)>& accept);

struct PolygonTriangulationCounts {
  std::uint64_t triangulations = 0;     // N_n
  std::uint64_t distinct_triangles = 0; // Tr_n
};

// Enumerates (n <= 16 by default in callers: 2.6 million triangulations) and counts.
PolygonTriangulationCounts count_polygon_triangulations(int n);

// Cat(n) = (2n - 2)! / (n! (n - 1)!) in the book's numbering (Cat(2) = 1, Cat(3) = 2), exact for n <= 30.
std::uint64_t catalan_book(int n);

}  // namespace dtlab
