#include "algorithms/delaunay3d/prepare.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>

#include "algorithms/spatial_sort.hpp"
#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
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
  if (points.size() > Tetrahedralization3::kMaxPoints)
    throw InputError(std::to_string(points.size()) + " points: more than the " +
                     std::to_string(Tetrahedralization3::kMaxPoints) + " a 3D tetrahedralization can index");
  check_coordinates(points, "point", team);

  PreparedPoints3 out;
  out.points = points;
  out.seed = seed;
  DistinctPoints split = distinct_in_hilbert_order(points, team);
  out.distinct = std::move(split.distinct);
  out.duplicates = std::move(split.duplicates);
  out.duplicate_of = std::move(split.duplicate_of);
  std::vector<std::uint32_t>& ids = out.distinct;

  const std::size_t m = ids.size();
  if (m < 4) {
    out.degenerate_message = "fewer than 4 distinct points (" + std::to_string(m) + " distinct among " +
                             std::to_string(points.size()) + "): no tetrahedra";
    return out;
  }
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
