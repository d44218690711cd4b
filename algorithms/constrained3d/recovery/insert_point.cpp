// Delaunay insertion into an existing tetrahedralization through the shared cavity kernel
// (insert_point.hpp).
#include "algorithms/constrained3d/recovery/insert_point.hpp"

#include <string>
#include <vector>

#include "kernel/error.hpp"

namespace dtlab {

namespace {
using T3 = Tetrahedralization3;
}  // namespace

DelaunayInserter::DelaunayInserter(Tetrahedralization3& tet)
    : tet_(tet), kernel_(tet.points().data(), tet.mutable_records()) {
  DTLAB_ASSERT(tet.finite_tetrahedron_count() > 0);
}

std::uint32_t DelaunayInserter::insert(const Vec3& p) {
  auto& points = tet_.mutable_points();
  points.push_back(p);
  const std::uint32_t pid = static_cast<std::uint32_t>(points.size() - 1);
  kernel_.set_points(points.data());
  // The walk ends in a tetrahedron whose closed region holds p (or a ghost p is beyond): if p
  // is a vertex, it is one of that tetrahedron's.
  const std::uint32_t base = kernel_.locate(pid);
  for (const std::uint32_t v : tet_.records()[base].vertex)
    if (v != T3::kInfinite && points[v] == p) {
      points.pop_back();
      throw InputError("Delaunay insertion: the new point equals vertex " + std::to_string(v), {v});
    }
  kernel_.set_last(base);
  kernel_.insert(pid);
  dirty_ = true;
  return pid;
}

void DelaunayInserter::compact() {
  if (!dirty_) return;
  std::vector<std::uint32_t> dead;
  kernel_.release_slots(dead);
  auto& records = tet_.mutable_records();
  compact_tetrahedra(records, dead);
  kernel_.refresh_views();
  if (kernel_.last() >= records.size()) kernel_.set_last(0);
  dirty_ = false;
}

}  // namespace dtlab
