// Mesh generation in 2D governed by a control space (book §5, laid out as §7.12 lays out the
// 3D scheme; the reference text lost most of chapter 5, so the steps follow Borouchaki, George,
// Hecht, Laug, Saltel 1997, "Delaunay mesh generation governed by metric specifications", parts
// I and II, and George, Hecht, Saltel 1991):
//   1. the empty mesh: the constrained Delaunay triangulation of the boundary, regions coloured,
//      exterior kept (empty_mesh.cpp);
//   2. the control space: classical (sizes from the boundary discretisation interpolated on the
//      empty mesh, classical_sizes.cpp), or a size or metric map on a background mesh
//      (control_space.hpp): one code path;
//   3. field points by the edge method, filtered in the metric, iterated to saturation
//      (edge_points.cpp);
//   4. insertion by the constrained, anisotropic Delaunay kernel (delaunay_kernel.hpp);
//   5. optimization (algorithms/optimize2d), then the exterior removed.
//
//   dtlab::Mesh2dResult r = dtlab::mesh2d({.points = pts, .segments = segs}, {});
//   write_medit2("out.mesh", r.output);
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "algorithms/common/mesh_pipeline.hpp"
#include "algorithms/common/registry.hpp"
#include "algorithms/constrained2d/constrained2d.hpp"
#include "algorithms/mesh2d/control_space.hpp"
#include "algorithms/optimize2d/optimize2d.hpp"
#include "mesh/io/mesh_data.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab {

// The input: a planar straight line graph whose segments are the boundary discretisation, as
// constrained2d takes it (mesh/problems/constrained2.hpp).
using Mesh2dInput = ConstrainedInput2;

struct Mesh2dOptions;
struct Mesh2dStats;
// A field point method (registry.hpp).
using FieldPointMethod2 = NamedEntry<void(Mesh2&, const ControlSpace2&, const Mesh2dOptions&, Mesh2dStats&)>;

// The 2D mesher's types and defaults (algorithms/common/mesh_pipeline.hpp).
struct Mesh2dTraits {
  using Method = FieldPointMethod2;
  using ControlSpace = ControlSpace2;
  using Optimization = Optimize2dOptions;  // step 5 (algorithms/optimize2d)
  static constexpr std::uint64_t kMaxVertices = 200'000'000;
  static Optimization optimization() { return {}; }
};

// The meshers' options (mesh_pipeline.hpp; "front" is §5.8, the boundary cut resample_boundary.cpp,
// the element bound at element_estimate::kBytesPerTriangle) and 2D's own.
struct Mesh2dOptions : MesherOptions<Mesh2dTraits> {
  // With no `control`: when `input_metrics` holds one metric per input point, the control space
  // is the empty mesh with these metrics (a crossing point of the empty mesh takes the
  // interpolation of its segments' ends).
  std::span<const Metric2> input_metrics;
  MetricInterpolation interpolation = MetricInterpolation::Sizes;
  // Numbering of points and segments in messages (the input file's: Medit 1, .poly its own).
  std::uint32_t first_number = 0;
};

struct Mesh2dStats : MesherStats {
  std::uint64_t segments = 0;
  std::uint64_t long_boundary_segments = 0;  // kept longer than sqrt 2 in the metric (keep_boundary)
  double estimated_triangles = 0;            // the up-front estimate (0 in the classical case)
  std::uint64_t swaps = 0;                   // optimization (algorithms/optimize2d)
};

using Mesh2dResult = MesherResult<Mesh2, MeshData2, Metric2, Mesh2dStats>;

// Throws InputError (items 0-based) for bad input: as constrained2d, plus a domain with no
// triangle, an open boundary (a segment endpoint of degree 1 with the domain on both sides), an
// unknown method, or a bound reached (named).
Mesh2dResult mesh2d(const Mesh2dInput& input, const Mesh2dOptions& options = {});

// The pieces, for tests and for the other meshers.
// 1. The empty mesh from a constrained triangulation: every triangle of the CDT, the domain's with
//    their region, the others kExterior; constrained edges with their markers.
Mesh2 empty_mesh(const Constrained2dResult& cdt);
// 2. Classical sizes: at each vertex, the mean length of its constrained edges (of all its edges
//    for a vertex on none); the control space is the empty mesh with these sizes.
ControlSpace2 classical_control_space(const Mesh2& empty);
// The empty mesh with one metric per input point (the first `metrics.size()` vertex slots);
// the crossing points after them interpolate their constrained neighbours' metrics.
ControlSpace2 input_control_space(const Mesh2& empty, std::span<const Metric2> metrics, MetricInterpolation mode);
// The boundary cut in the metric: the input points first, then the cut points; every input segment
// longer than sqrt 2 in the metric replaced by sub-segments of length close to 1 (at most sqrt 2),
// in order, with its marker; the shorter ones kept. `long_segments` counts the segments longer
// than sqrt 2 (those cut).
struct ResampledBoundary {
  std::vector<Vec2> points;
  std::vector<std::array<std::uint32_t, 2>> segments;
  std::vector<int> markers;
  std::uint64_t long_segments = 0;
};
ResampledBoundary resample_boundary(const Mesh2dInput& input, const ControlSpace2& control, const Mesh2dOptions& options);
// 3.+4. The edge method: field points inserted until saturation. Adds to `stats`.
void insert_edge_points(Mesh2& mesh, const ControlSpace2& control, const Mesh2dOptions& options, Mesh2dStats& stats);
// 3.+4. The advancing-front method (front_points.cpp): points placed from the front, inserted at once.
void insert_front_points(Mesh2& mesh, const ControlSpace2& control, const Mesh2dOptions& options, Mesh2dStats& stats);

}  // namespace dtlab
