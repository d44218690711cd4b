#include "algorithms/delaunay3d/prepare.hpp"

#include <algorithm>
#include <array>

#include "algorithms/spatial_sort.hpp"
#include "kernel/intersections.hpp"
#include "kernel/predicates.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

std::array<std::size_t, 4> first_simplex(std::span<const Vec3> points, std::span<const std::uint32_t> ids) {
  const std::size_t n = ids.size();
  std::array<std::size_t, 4> out{0, 1, n, n};
  if (n < 3) return {0, std::min<std::size_t>(1, n), n, n};
  const Vec3& a = points[ids[0]];
  const Vec3& b = points[ids[1]];
  std::size_t k = 2;
  while (k < n && collinear3(a, b, points[ids[k]])) ++k;
  out[2] = k;
  if (k == n) return out;
  const Vec3& c = points[ids[k]];
  std::size_t l = k + 1;
  while (l < n && orient3d(a, b, c, points[ids[l]]) == Sign::Zero) ++l;
  out[3] = l;
  return out;
}

PreparedPoints3 prepare_points3(std::span<const Vec3> points, std::uint64_t seed, WorkerTeam* team) {
  PreparedPoints3 out = prepare_distinct(points, seed, Tetrahedralization3::kMaxPoints, "a 3D tetrahedralization", 4,
                                         "tetrahedra", team, [](std::span<const Vec3> p, WorkerTeam* t) {
                                           return distinct_in_hilbert_order(p, t);
                                         });
  if (!out.degenerate_message.empty()) return out;
  const std::vector<std::uint32_t>& ids = out.distinct;
  const std::size_t m = ids.size();
  const auto simplex = first_simplex(points, ids);
  if (simplex[2] == m) {
    out.degenerate_message =
        "all points collinear (" + std::to_string(m) + " distinct points on one line): no tetrahedra";
  } else if (simplex[3] == m) {
    out.degenerate_message =
        "all points coplanar (" + std::to_string(m) + " distinct points in one plane): no tetrahedra";
  }
  return out;
}

}  // namespace dtlab
