// Variant "incremental": the reduced incremental method in 3D, George & Borouchaki §2.4-2.6.
// Each point goes in by the Delaunay kernel (cavity_kernel.hpp: walk, cavity by adjacency, ball),
// one after the other in BRIO order, each round in Hilbert order (Amenta, Choi, Rote 2003), the
// walk starting from the last insertion.
#include <cstdint>
#include <utility>
#include <vector>

#include "algorithms/delaunay3d/cavity_kernel.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "kernel/error.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

void delaunay3d_incremental(PreparedPoints3& input, const Delaunay3dOptions& /*options*/,
                            Tetrahedralization3& tetrahedralization) {
  using T3 = Tetrahedralization3;
  std::vector<Vec3>& points = tetrahedralization.mutable_points();
  InsertionOrder order(input);
  input.release_distinct();  // 4 bytes a point off the peak
  order.reorder(points);
  const std::size_t m = order.distinct_count();

  std::vector<T3::Record>& records = tetrahedralization.mutable_records();
  tetrahedralization.clear_tetrahedra();
  // About 6.7 tetrahedra per point for uniform points; memory reserved but never written costs
  // nothing, so reserve above that.
  tetrahedralization.reserve_tetrahedra(std::min<std::size_t>(7 * m + m / 2 + 64, T3::kMaxTetrahedra));

  CavityKernel kernel(points.data(), records);
  kernel.set_static_bounds(static_bounds3(std::span<const Vec3>(points.data(), m)));
  kernel.reserve_vertices(m);
  if (order.first_simplex_positive()) {
    kernel.start(0, 1, 2, 3);
  } else {
    kernel.start(0, 1, 3, 2);
  }
  for (std::size_t r = 4; r < m; ++r) kernel.insert(static_cast<std::uint32_t>(r));
  std::vector<std::uint32_t> dead;
  kernel.release_slots(dead);
  compact_tetrahedra(records, dead);
  std::move(order).restore(points, records);
}

}  // namespace dtlab
