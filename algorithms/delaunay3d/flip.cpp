// Variant "flip" of the 3D Delaunay tetrahedralization: incremental insertion by topological
// flipping, Joe, "Construction of three-dimensional Delaunay triangulations using local
// transformations" (CAGD 1991) and Edelsbrunner & Shah, "Incremental topological flipping works
// for regular triangulations" (Algorithmica 1996). Each point splits the tetrahedra holding it
// and 2->3 / 3->2 / 4->4 flips restore the Delaunay property (flip_insertion.hpp), ghosts
// included (flip_orientation.hpp). Insertion order as in "incremental": BRIO rounds in Hilbert
// order (Amenta, Choi, Rote 2003), each walk starting from the last insertion.
#include <algorithm>
#include <span>
#include <utility>
#include <vector>

#include "algorithms/delaunay3d/flip_insertion.hpp"
#include "algorithms/delaunay3d/prepare.hpp"
#include "algorithms/permute_in_place.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "algorithms/spatial_sort.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

void delaunay3d_flip(PreparedPoints3& input, const Delaunay3dOptions& /*options*/,
                     Tetrahedralization3& tetrahedralization) {
  using T3 = Tetrahedralization3;
  std::vector<Vec3>& points = tetrahedralization.mutable_points();
  DTLAB_ASSERT(points.size() == input.points.size());
  std::vector<std::uint32_t> order = brio_order_of_sorted(input.distinct, input.seed);
  const std::size_t m = order.size();

  // The first four points of the order that span space go first; then vertex ids are insertion
  // ranks while the variant runs, which keeps consecutive insertions close in memory.
  const auto simplex = first_simplex(input.points, order);
  DTLAB_ASSERT(m >= 4 && simplex[3] < m);
  std::swap(order[2], order[simplex[2]]);
  std::swap(order[3], order[simplex[3]]);
  // In place, since input.points may be this very array (registry.hpp); the duplicates, never
  // inserted, go after the distinct points.
  if (input.duplicates.size() + m != points.size())
    throw InternalError("3D Delaunay flip: distinct and duplicate points do not partition the input");
  order.insert(order.end(), input.duplicates.begin(), input.duplicates.end());
  permute_in_place(std::span<Vec3>(points), order);
  const Sign orientation = orient3d(points[0], points[1], points[2], points[3]);
  DTLAB_ASSERT(orientation != Sign::Zero);

  std::vector<T3::Record>& records = tetrahedralization.mutable_records();
  tetrahedralization.clear_tetrahedra();
  // About 6.7 tetrahedra per uniform point; reserved memory that is never written costs nothing.
  tetrahedralization.reserve_tetrahedra(std::min<std::size_t>(7 * m + m / 2 + 64, T3::kMaxTetrahedra));

  const std::array<std::uint32_t, 4> first =
      orientation == Sign::Positive ? std::array<std::uint32_t, 4>{0, 1, 2, 3} : std::array<std::uint32_t, 4>{0, 1, 3, 2};
  FlipInserter inserter(points.data(), records, first);
  inserter.start();
  for (std::size_t r = 4; r < m; ++r) inserter.insert(static_cast<std::uint32_t>(r));
  inserter.finish();

  // Back to input ids and input order.
  for (T3::Record& rec : records)
    for (std::uint32_t& v : rec.vertex)
      if (v != T3::kInfinite) v = order[v];
  move_to_destinations(std::span<Vec3>(points), std::span<std::uint32_t>(order));  // order is spent
}

}  // namespace dtlab
