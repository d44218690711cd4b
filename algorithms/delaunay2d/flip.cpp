// Variant "flip": Lawson's algorithm, George & Borouchaki §2 (Theorem 2.2; Lawson 1977). Any
// triangulation of the points, here a lexicographic fan sweep built with orient2d alone
// (flip_sweep.hpp), is turned into the Delaunay one by flipping each edge that is not locally
// Delaunay under incircle_perturbed (flip_lawson.hpp). Simple and robust, but the sweep's long
// thin triangles cost many flips: a baseline to measure the incremental method against.
#include <algorithm>
#include <vector>

#include "algorithms/delaunay2d/flip_lawson.hpp"
#include "algorithms/delaunay2d/flip_sweep.hpp"
#include "algorithms/delaunay2d/prepare.hpp"
#include "kernel/error.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

void delaunay2d_flip(const PreparedPoints2& input, Triangulation2& triangulation) {
  std::vector<Vec2>& points = triangulation.mutable_points();
  DTLAB_ASSERT(points.size() == input.points.size());
  const std::size_t m = input.distinct.size();
  DTLAB_ASSERT(m >= 3);

  // Lexicographic order; while the algorithm runs, vertex ids are ranks in it.
  struct Keyed {
    Vec2 p;
    std::uint32_t id;
  };
  std::vector<Keyed> sorted(m);
  for (std::size_t r = 0; r < m; ++r) sorted[r] = {input.points[input.distinct[r]], input.distinct[r]};
  std::sort(sorted.begin(), sorted.end(), [](const Keyed& a, const Keyed& b) { return a.p < b.p; });
  for (std::size_t r = 0; r < m; ++r) points[r] = sorted[r].p;

  const std::size_t capacity = 2 * m - 2;  // triangles, ghosts included
  std::vector<std::uint32_t>& vertices = triangulation.mutable_vertices();
  std::vector<std::uint32_t>& neighbours = triangulation.mutable_neighbours();
  vertices.assign(3 * capacity, Triangulation2::kNone);
  neighbours.assign(3 * capacity, Triangulation2::kNone);
  sweep_triangulate2(points.data(), m, vertices.data(), neighbours.data());
  lawson_flip2(points.data(), m, vertices.data(), neighbours.data(), capacity);

  // Back to input ids and input order.
  for (std::uint32_t& v : vertices)
    if (v != Triangulation2::kInfinite) v = sorted[v].id;
  std::copy(input.points.begin(), input.points.end(), points.begin());
}

}  // namespace dtlab
