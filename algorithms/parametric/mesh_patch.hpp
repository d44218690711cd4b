// Parametric surface meshing (book §6.3): each chart's parameter domain is meshed by the 2D
// anisotropic generator (algorithms/mesh2d) under the metric of surface_metric.hpp, then mapped
// onto the surface by sigma (§6.3.6). The control space is a background grid of the chart's
// parameter box with the exact metric at its vertices (§6.3.1: "the metric map is defined, by means
// of interpolation, using the discrete metric map associated with the vertices of a given mesh of
// Q"). The boundary (§6.3.4): each side is cut into sub-arcs of equal length in the metric, their
// number the rounding of the side's metric length (the rule of mesh_curve, algorithms/surface/
// curve3.hpp, on a curve of the parameter plane); a seam is cut once, by the first chart that
// holds it, and the other takes its points (one vertex each), so the surface is conforming and a
// closed surface closed. The mesher keeps these boundaries (Mesh2dOptions::keep_boundary).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/surface/patch_surface3.hpp"
#include "algorithms/surface/surface_metric.hpp"
#include "kernel/metric.hpp"
#include "mesh/io/mesh_data.hpp"
#include "mesh/io/mesh_data3.hpp"

namespace dtlab {

struct SurfaceMeshOptions {
  SurfaceMetricSpec metric;
  std::uint32_t background_cells = 64;   // the control space's grid, per direction and chart
  std::uint32_t side_cells = 256;        // quadrature cells for a side's metric length
  std::uint32_t max_side_points = 1'000'000;  // a side cut in more: InputError naming it
  bool optimize = true;
  std::string method = "edge";          // Mesh2dOptions::method (edge, front)
  MetricInterpolation interpolation = MetricInterpolation::Sizes;  // the control space's
  std::uint64_t max_elements = 0;        // Mesh2dOptions::max_elements
};

struct ChartMesh {
  MeshData2 parameters;                 // the chart's mesh in its parameter space
  std::vector<Metric2> metrics;         // the exact metric (surface_metric.hpp) at each of its vertices
  std::vector<std::uint32_t> vertex;    // the surface vertex of each
};

struct SurfaceMeshResult {
  MeshData3 surface;       // Vertices, Triangles (ref: chart + 1), Edges on free sides (ref: chart side + 1)
  std::vector<ChartMesh> charts;
  double seconds = 0;
};

// InputError for a bad metric spec (SurfaceMetricSpec::check), a side cut in more points than
// the bound, or a chart the 2D mesher refuses (its message, with the chart named).
SurfaceMeshResult mesh_patch_surface(const PatchSurface3& surface, const SurfaceMeshOptions& options);

}  // namespace dtlab
