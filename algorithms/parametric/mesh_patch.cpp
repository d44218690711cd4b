// mesh_patch_surface: boundary sides cut in the metric, charts meshed in 2D, mapped by sigma
// (mesh_patch.hpp, book §6.3).
#include "algorithms/parametric/mesh_patch.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <string>
#include <utility>

#include "algorithms/mesh2d/control_space.hpp"
#include "algorithms/mesh2d/mesh2d.hpp"
#include "kernel/error.hpp"

namespace dtlab {
namespace {

// The metric length density of side k of a chart at s.
double density(const PatchChart3& chart, std::uint32_t k, double s, const SurfaceMetricSpec& spec) {
  const Vec2 uv = chart.side_point(k, s);
  return parameter_metric(chart.patch.evaluate(uv), spec).length(chart.side_derivative(k, s));
}

// Gauss-Legendre, 3 points, on [a, b].
template <class F>
double gauss3(const F& f, double a, double b) {
  constexpr double x = 0.77459666924148337704, w0 = 8.0 / 9.0, w1 = 5.0 / 9.0;
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  return h * (w0 * f(c) + w1 * (f(c - h * x) + f(c + h * x)));
}

// The interior s of the points that cut side k into sub-arcs of equal metric length, their number
// the rounding of the side's length (at least 1, 3 for a closed side).
std::vector<double> cut_side(const PatchChart3& chart, std::uint32_t chart_index, std::uint32_t k,
                             const SurfaceMeshOptions& options) {
  const std::uint32_t cells = std::max<std::uint32_t>(options.side_cells, 8);
  auto f = [&](double s) { return density(chart, k, s, options.metric); };
  std::vector<double> cumulative(cells + 1, 0.0);
  for (std::uint32_t i = 0; i < cells; ++i)
    cumulative[i + 1] = cumulative[i] + gauss3(f, static_cast<double>(i) / cells, static_cast<double>(i + 1) / cells);
  const double length = cumulative.back();
  if (!std::isfinite(length))
    throw InputError("surface mesh: side " + std::to_string(k) + " of chart " + std::to_string(chart_index) +
                     " has no finite length in the metric");
  const double rounded = std::max(chart.disc ? 3.0 : 1.0, std::round(length));
  if (rounded > options.max_side_points)
    throw InputError("surface mesh: side " + std::to_string(k) + " of chart " + std::to_string(chart_index) + " asks for " +
                     std::to_string(rounded) + " points (bound " + std::to_string(options.max_side_points) + ")");
  const auto n = static_cast<std::uint32_t>(rounded);
  std::vector<double> s_values;
  for (std::uint32_t i = 1; i < n; ++i) {
    const double target = length * i / n;
    const auto cell = static_cast<std::uint32_t>(
        std::clamp<std::ptrdiff_t>(std::upper_bound(cumulative.begin(), cumulative.end(), target) - cumulative.begin() - 1, 0, cells - 1));
    const double a = static_cast<double>(cell) / cells, b = static_cast<double>(cell + 1) / cells;
    const double within = target - cumulative[cell], cell_length = cumulative[cell + 1] - cumulative[cell];
    double s = cell_length > 0.0 ? a + (b - a) * within / cell_length : a;
    for (int newton = 0; newton < 4; ++newton) {  // bounded: the density varies little in a cell
      const double g = gauss3(f, a, s) - within, fs = f(s);
      if (!(fs > 0.0)) break;
      s = std::clamp(s - g / fs, a, b);
    }
    s_values.push_back(s);
  }
  return s_values;
}

// The control space of a chart (§6.3.1): a grid of its parameter box, two triangles a cell, with
// the exact metric at its vertices.
ControlSpace2 chart_control_space(const PatchChart3& chart, const SurfaceMeshOptions& options) {
  const std::uint32_t cells = std::max<std::uint32_t>(options.background_cells, 2);
  MeshData2 grid;
  std::vector<Metric2> metrics;
  for (std::uint32_t j = 0; j <= cells; ++j) {
    for (std::uint32_t i = 0; i <= cells; ++i) {
      const Vec2 uv{chart.lo.x + (chart.hi.x - chart.lo.x) * i / cells, chart.lo.y + (chart.hi.y - chart.lo.y) * j / cells};
      grid.vertices.push_back(uv);
      metrics.push_back(parameter_metric(chart.patch.evaluate(uv), options.metric));
    }
  }
  for (std::uint32_t j = 0; j < cells; ++j) {
    for (std::uint32_t i = 0; i < cells; ++i) {
      const std::uint32_t a = j * (cells + 1) + i, b = a + 1, d = a + cells + 1, e = d + 1;
      grid.triangles.push_back({a, b, e});
      grid.triangles.push_back({a, e, d});
    }
  }
  return ControlSpace2(grid, std::move(metrics), options.interpolation);
}

struct UnionFind {
  std::vector<std::uint32_t> parent;
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// The points of one side, shared by both charts of a seam: s in the owner's side, the vertices.
struct SidePoints {
  std::vector<double> s;
  std::vector<std::uint32_t> vertex;
};

std::pair<std::uint64_t, std::uint64_t> key(const Vec2& p) { return {std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y)}; }

// Every edge of the surface in one triangle each way at most (two on a seam, one on a free side):
// two edges joining the same vertices, or a seam taken the same way twice, would be a broken
// surface; the charts' layout (patch_surface3.hpp) rules it out, and this says so if it did not.
void check_edges(const MeshData3& out) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> directed;
  for (std::size_t t = 0; t < out.triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = out.triangles[t][i], b = out.triangles[t][(i + 1) % 3];
      if (++directed[{a, b}] > 1)
        throw InternalError("surface mesh: the edge of vertices " + std::to_string(a + 1) + " and " + std::to_string(b + 1) +
                            " is in two triangles the same way (triangle " + std::to_string(t + 1) + ")");
    }
  }
}

}  // namespace

SurfaceMeshResult mesh_patch_surface(const PatchSurface3& surface, const SurfaceMeshOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  options.metric.check();
  const auto& charts = surface.charts();
  const auto chart_count = static_cast<std::uint32_t>(charts.size());
  SurfaceMeshResult result;
  MeshData3& out = result.surface;

  // Corners: (chart, corner) slots, glued by the seams (corner k of A is the end of B's side).
  std::vector<std::uint32_t> first_corner(chart_count + 1, 0);
  for (std::uint32_t c = 0; c < chart_count; ++c) first_corner[c + 1] = first_corner[c] + charts[c].side_count();
  UnionFind corners{std::vector<std::uint32_t>(first_corner.back())};
  std::iota(corners.parent.begin(), corners.parent.end(), 0u);
  auto corner_slot = [&](std::uint32_t c, std::uint32_t k) { return first_corner[c] + k % charts[c].side_count(); };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::uint32_t, std::uint32_t>> borrowed;  // B side -> A side
  for (const PatchSeam3& seam : surface.seams()) {
    corners.join(corner_slot(seam.chart_a, seam.side_a), corner_slot(seam.chart_b, seam.side_b + 1));
    corners.join(corner_slot(seam.chart_a, seam.side_a + 1), corner_slot(seam.chart_b, seam.side_b));
    borrowed[{seam.chart_b, seam.side_b}] = {seam.chart_a, seam.side_a};
  }
  std::vector<std::uint32_t> corner_vertex(first_corner.back(), 0xFFFFFFFFu);
  for (std::uint32_t c = 0; c < chart_count; ++c) {
    for (std::uint32_t k = 0; k < charts[c].side_count(); ++k) {
      const std::uint32_t root = corners.find(corner_slot(c, k));
      if (corner_vertex[root] == 0xFFFFFFFFu) {
        corner_vertex[root] = static_cast<std::uint32_t>(out.vertices.size());
        out.vertices.push_back(charts[c].patch.point(charts[c].side_point(k, 0.0)));
      }
    }
  }

  // Sides: the owners cut theirs, the seams' second charts take them reversed.
  std::map<std::pair<std::uint32_t, std::uint32_t>, SidePoints> sides;
  for (std::uint32_t c = 0; c < chart_count; ++c) {
    for (std::uint32_t k = 0; k < charts[c].side_count(); ++k) {
      if (borrowed.contains({c, k})) continue;
      SidePoints& side = sides[{c, k}];
      side.s = cut_side(charts[c], c, k, options);
      for (double s : side.s) {
        side.vertex.push_back(static_cast<std::uint32_t>(out.vertices.size()));
        out.vertices.push_back(charts[c].patch.point(charts[c].side_point(k, s)));
      }
    }
  }
  for (const auto& [b, a] : borrowed) {
    const SidePoints& from = sides.at(a);
    SidePoints& side = sides[b];
    for (std::size_t i = from.s.size(); i-- > 0;) {
      side.s.push_back(1.0 - from.s[i]);
      side.vertex.push_back(from.vertex[i]);
    }
  }
  // Free sides are the surface's boundary: written as Edges.
  for (std::uint32_t c = 0; c < chart_count; ++c) {
    for (std::uint32_t k = 0; k < charts[c].side_count(); ++k) {
      bool glued = borrowed.contains({c, k});
      for (const PatchSeam3& seam : surface.seams()) glued = glued || (seam.chart_a == c && seam.side_a == k);
      if (glued) continue;
      const SidePoints& side = sides.at({c, k});
      std::vector<std::uint32_t> chain{corner_vertex[corners.find(corner_slot(c, k))]};
      chain.insert(chain.end(), side.vertex.begin(), side.vertex.end());
      chain.push_back(corner_vertex[corners.find(corner_slot(c, k + 1))]);
      for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
        out.edges.push_back({chain[i], chain[i + 1]});
        out.edge_refs.push_back(static_cast<int>(4 * c + k + 1));
      }
    }
  }

  // Each chart in 2D.
  for (std::uint32_t c = 0; c < chart_count; ++c) {
    const PatchChart3& chart = charts[c];
    std::vector<Vec2> points;
    std::vector<std::array<std::uint32_t, 2>> segments;
    std::vector<int> markers;
    std::vector<std::uint32_t> boundary_vertex;
    for (std::uint32_t k = 0; k < chart.side_count(); ++k) {
      points.push_back(chart.side_point(k, 0.0));
      boundary_vertex.push_back(corner_vertex[corners.find(corner_slot(c, k))]);
      const SidePoints& side = sides.at({c, k});
      for (std::size_t i = 0; i < side.s.size(); ++i) {
        points.push_back(chart.side_point(k, side.s[i]));
        boundary_vertex.push_back(side.vertex[i]);
        markers.push_back(static_cast<int>(k + 1));
      }
      markers.push_back(static_cast<int>(k + 1));
    }
    const auto n = static_cast<std::uint32_t>(points.size());
    for (std::uint32_t i = 0; i < n; ++i) segments.push_back({i, (i + 1) % n});
    const Mesh2dInput input{.points = points, .segments = segments, .segment_markers = markers, .holes = {}, .regions = {}};

    const ControlSpace2 control = chart_control_space(chart, options);
    Mesh2dOptions mesh_options;
    mesh_options.control = &control;
    mesh_options.keep_boundary = true;
    mesh_options.optimize = options.optimize;
    mesh_options.method = options.method;
    mesh_options.interpolation = options.interpolation;
    mesh_options.max_elements = options.max_elements;
    Mesh2dResult meshed;
    try {
      meshed = mesh2d(input, mesh_options);
    } catch (const InputError& e) {
      throw InputError(surface.name() + " chart " + std::to_string(c) + ": " + e.what(), e.items());
    }

    // Map to the surface: boundary points by their exact parameters, the others new vertices.
    std::map<std::pair<std::uint64_t, std::uint64_t>, std::uint32_t> on_boundary;
    for (std::uint32_t i = 0; i < n; ++i) on_boundary[key(points[i])] = boundary_vertex[i];
    ChartMesh chart_mesh;
    chart_mesh.parameters = meshed.output;
    for (const Vec2& uv : meshed.output.vertices) {
      const PatchDerivatives d = chart.patch.evaluate(uv);
      chart_mesh.metrics.push_back(parameter_metric(d, options.metric));
      const auto found = on_boundary.find(key(uv));
      if (found != on_boundary.end()) {
        chart_mesh.vertex.push_back(found->second);
      } else {
        chart_mesh.vertex.push_back(static_cast<std::uint32_t>(out.vertices.size()));
        out.vertices.push_back(d.point);
      }
    }
    for (const auto& t : meshed.output.triangles) {
      out.triangles.push_back({chart_mesh.vertex[t[0]], chart_mesh.vertex[t[1]], chart_mesh.vertex[t[2]]});
      out.triangle_refs.push_back(static_cast<int>(c + 1));
    }
    result.charts.push_back(std::move(chart_mesh));
  }
  out.vertex_refs.assign(out.vertices.size(), 0);
  check_edges(out);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace dtlab
