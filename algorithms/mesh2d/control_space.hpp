// The control space of book §5 / §7.4 (George, Borouchaki): a background mesh with a metric at
// each of its vertices, interpolated (on the sizes, kernel/metric.hpp) at any point of the
// domain. One code path for the three cases of the book: classical (sizes from the boundary
// discretisation, interpolated on the empty mesh), isotropic (a size map h^-2 I) and
// anisotropic (a metric map).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "kernel/metric.hpp"
#include "kernel/vec.hpp"
#include "mesh/element_grid.hpp"
#include "mesh/io/mesh_data.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab {

class ControlSpace2 {
 public:
  // A background mesh (its triangles) and one metric per vertex. Throws InputError naming the
  // vertex whose metric is not positive definite, or when the counts differ, or when the
  // background has no triangle.
  ControlSpace2(const MeshData2& background, std::vector<Metric2> metrics,
                MetricInterpolation mode = MetricInterpolation::Sizes);
  // The same on a Mesh2 (the empty mesh in the classical case): one metric per vertex slot.
  ControlSpace2(Mesh2 background, std::vector<Metric2> metrics, MetricInterpolation mode = MetricInterpolation::Sizes);

  // The metric at p: located in the background by a walk from `hint` (a triangle of the
  // background, updated to where p was found; start with kNoHint), interpolated from the
  // vertices of the triangle holding p with its barycentric weights. A walk that leaves the
  // domain through a hole or a concavity is settled by the triangles of p's bucket
  // (mesh/element_grid.hpp); a point outside the background takes the metric at the nearest point
  // of the triangle the walk stopped at.
  static constexpr std::uint32_t kNoHint = 0xFFFFFFFFu;
  // The same metric everywhere: a background of two triangles over the box [lo, hi] (a point
  // outside it takes the same metric all the same).
  static ControlSpace2 uniform(const Metric2& metric, const Vec2& lo, const Vec2& hi);
  // A uniform size h (the metric h^-2 I) over the box of `points` grown by 1 on each side, as
  // `dtlab mesh --size` and Python's size= give it; InputError unless h is positive and finite
  // and there is a point.
  static ControlSpace2 uniform_size(std::span<const Vec2> points, double h);
  Metric2 metric_at(const Vec2& p, std::uint32_t& hint) const;

  const Mesh2& background() const noexcept { return mesh_; }
  const std::vector<Metric2>& vertex_metrics() const noexcept { return metrics_; }

 private:
  void validate() const;

  Mesh2 mesh_;
  std::vector<Metric2> metrics_;
  MetricInterpolation mode_;
  std::uint32_t start_ = kNoHint;  // a live finite triangle to walk from
  ElementGrid<Vec2> grid_;         // the live finite triangles by bucket
};

}  // namespace dtlab
