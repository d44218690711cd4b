// The control space of book §7.4 (and §5): a background tetrahedral mesh with a metric at each of
// its vertices, interpolated (on the sizes, kernel/metric.hpp) at any point of the domain. One
// code path for the book's three cases: classical (sizes from the surface discretisation,
// interpolated P1 on the empty mesh), isotropic (a size map h^-2 I) and anisotropic (a metric
// map), the last two read from Medit .sol on a background mesh.
//
// The background is a Mesh3 (as ControlSpace2's is a Mesh2) holding the vertex metrics; one from
// a file need not be convex: its boundary is closed by ghosts, which the walk does not enter.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "kernel/metric.hpp"
#include "kernel/vec.hpp"
#include "mesh/element_grid.hpp"
#include "mesh/io/mesh_data3.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab {

class ControlSpace3 {
 public:
  // Start a walk anywhere.
  static constexpr std::uint32_t kNoHint = 0xFFFFFFFFu;

  // A background mesh (its tetrahedra, positive) and one metric per vertex. Throws InputError
  // when the background has no tetrahedron, when the counts differ, naming a tetrahedron with a
  // vertex out of range or not positive (exact orient3d), a facet of more than two tetrahedra, a
  // boundary that is not a closed 2-manifold (mesh/tetrahedralization3_build.hpp), or the vertex
  // whose metric is not positive definite (numbered from 1 in the message, 0-based in items()).
  ControlSpace3(const MeshData3& background, std::vector<Metric3> metrics,
                MetricInterpolation mode = MetricInterpolation::Sizes);
  // The finite live tetrahedra of a Mesh3 (the empty mesh, exterior included, in the classical
  // case: a copy, frozen while the mesh is refined) with one metric per vertex slot.
  ControlSpace3(Mesh3 background, std::vector<Metric3> metrics,
                MetricInterpolation mode = MetricInterpolation::Sizes);

  // The same metric everywhere: a background of six tetrahedra over the box [lo, hi] (a point
  // outside it takes the same metric all the same).
  static ControlSpace3 uniform(const Metric3& metric, const Vec3& lo, const Vec3& hi);
  // A uniform size h (the metric h^-2 I) over the box of `points` grown by 1 on each side, as
  // `dtlab mesh --size` and Python's size= give it; InputError unless h is positive and finite
  // and there is a point.
  static ControlSpace3 uniform_size(std::span<const Vec3> points, double h);

  // The metric at p: located by a visibility walk (exact orient3d) from `hint` (a background
  // tetrahedron, updated to where p was found), interpolated from the vertices of the
  // tetrahedron holding p with its barycentric weights. A walk that leaves the domain through a
  // hole or a concavity (the cylinder of the UGAWG cube-cylinder) is settled by the tetrahedra
  // of p's bucket (mesh/element_grid.hpp); a point outside the background takes the metric at the
  // nearest point, up to clamping, of the tetrahedron the walk stopped at.
  Metric3 metric_at(const Vec3& p, std::uint32_t& hint) const;

  // The background, its metrics at its vertices.
  const Mesh3& background() const noexcept { return mesh_; }
  // The largest size (h = lambda_min^-1/2) over the vertex metrics' median: a typical length of
  // the space, for grids.
  double median_largest_size() const;

 private:
  void build(const std::vector<Metric3>& metrics);
  bool contains(std::uint32_t t, const Vec3& p) const;

  Mesh3 mesh_;
  std::vector<std::uint8_t> uniform_;  // per tetrahedron slot: finite, its four metrics equal
  std::uint32_t start_ = kNoHint;      // the first finite live tetrahedron
  std::uint64_t walk_bound_ = 0;       // the finite live tetrahedra, and 64
  bool constant_ = false;              // one metric at every vertex of every tetrahedron
  MetricInterpolation mode_ = MetricInterpolation::Sizes;
  ElementGrid<Vec3> grid_;  // the finite live tetrahedra by bucket
};

}  // namespace dtlab
