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

#include "algorithms/constrained2d/constrained2d.hpp"
#include "algorithms/mesh2d/control_space.hpp"
#include "algorithms/optimize2d/optimize2d.hpp"
#include "mesh/io/mesh_data.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab {

// The input: a planar straight line graph whose segments are the boundary discretisation, as
// constrained2d takes it (mesh/problems/constrained2.hpp).
using Mesh2dInput = ConstrainedInput2;

template <class Entry>
class Registry;  // algorithms/common/registry.hpp
struct FieldPointMethod2;  // registry.hpp

struct Mesh2dOptions {
  // Field point placement, a name from mesh2d_methods() (registry.hpp): "edge" (the edge method,
  // §5 / §7.5-§7.7) or "front" (advancing-front placement, §5.8 / §7.8); looked up in `methods`
  // when given.
  std::string method = "edge";
  const Registry<FieldPointMethod2>* methods = nullptr;
  // The size specification; null: the classical case (sizes from the boundary discretisation),
  // unless `input_metrics` holds one metric per input point: then the control space is the
  // empty mesh with these metrics (a crossing point of the empty mesh takes the interpolation
  // of its segments' ends).
  const ControlSpace2* control = nullptr;
  std::span<const Metric2> input_metrics;
  MetricInterpolation interpolation = MetricInterpolation::Sizes;
  bool optimize = true;
  Optimize2dOptions optimization;  // step 5 (algorithms/optimize2d)
  // With a size or metric given, the input segments longer than sqrt 2 in the metric are cut
  // anew in it (boundary_resample.cpp), so that the size holds on the boundary too and a domain
  // with no interior edge is still refined; keep_boundary keeps them as given (the mesh's quality
  // near a long segment is then that segment's: `messages` counts them). Not in the classical
  // case, whose sizes come from the segments themselves.
  bool keep_boundary = false;
  // A field point closer than this (metric length, in the metric at the point) to a vertex that
  // would become its neighbour is filtered out.
  double filter_distance = 0.7;
  // Edges longer than this in the metric get field points.
  double split_length = 1.4142135623730951;
  // Bounds, each with a named error when reached: passes of the field point loop, and vertices
  // in all (a multiple of the input's points plus an absolute floor).
  std::uint32_t max_passes = 200;
  std::uint64_t max_vertices = 200'000'000;
  // The triangles the size or metric may ask for, estimated before any is made from the metric's
  // complexity (algorithms/common/element_estimate.hpp): past it, InputError with the estimate,
  // and the vertex bound is lowered to it. 0: half this machine's memory at
  // element_estimate::kBytesPerTriangle. Not checked in the classical case.
  std::uint64_t max_elements = 0;
  // Numbering of points and segments in messages (the input file's: Medit 1, .poly its own).
  std::uint32_t first_number = 0;
  // Asked between the phases and at each pass of the field point loop (kernel/interrupt.hpp);
  // yes: Interrupted. The optimization asks its own check, or this one when it has none.
  InterruptCheck interrupt{};
};

struct Mesh2dStats {
  double seconds_empty_mesh = 0, seconds_control_space = 0, seconds_field_points = 0, seconds_optimization = 0;
  double seconds = 0;  // the whole call
  std::uint32_t passes = 0;
  std::uint64_t field_points = 0;          // inserted
  std::uint64_t filtered = 0;              // candidates rejected as too close
  std::uint64_t not_inserted = 0;          // candidates outside the domain or on an edge that cannot open
  std::uint64_t cavity_corrections = 0;    // triangles taken out of cavities (star-shapedness, §2.6.3)
  std::uint64_t input_points = 0, segments = 0;
  std::uint64_t boundary_points = 0;  // cut points added on the input segments
  std::uint64_t long_boundary_segments = 0;  // kept longer than sqrt 2 in the metric (keep_boundary)
  double estimated_triangles = 0;            // the up-front estimate (0 in the classical case)
  // Optimization counts (algorithms/optimize2d), filled when it ran.
  std::uint64_t swaps = 0, relocations = 0, collapses = 0, splits = 0;
  std::uint32_t optimization_rounds = 0;
};

struct Mesh2dResult {
  Mesh2 mesh;          // the whole structure, exterior included
  MeshData2 output;    // the domain: vertices, boundary edges with their markers, triangles with regions
  std::vector<std::uint32_t> output_vertex_ids;  // the slot in `mesh` of each output vertex
  std::vector<Metric2> output_metrics;           // the metric at each output vertex
  Mesh2dStats stats;
  std::vector<std::string> messages;  // from the empty mesh (duplicates, crossings ...)
};

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
