// Field points by the edge method (book §7.5-§7.7, which "follows exactly the framework of
// chapter 5"; Borouchaki, George, Hecht, Laug, Saltel 1997, part I, §4): every internal edge
// longer than split_length in the metric is cut into n = round(l) sub-edges of metric length
// close to 1, the sizes progressing geometrically from one end to the other (so the sub-edges
// match their ends' sizes smoothly); each candidate is inserted at once by the Delaunay kernel
// unless it lies closer than filter_distance (in the metric) to a vertex of its cavity, the
// vertices that would become its neighbours, among them its nearest one: the filter needs no
// grid. Passes repeat over the new mesh until no candidate is accepted (saturation).
#include <algorithm>
#include <cmath>
#include <string>

#include "algorithms/mesh2d/delaunay_kernel.hpp"
#include "algorithms/mesh2d/edge_cuts.hpp"
#include "algorithms/mesh2d/mesh2d.hpp"
#include "kernel/error.hpp"
#include "kernel/interrupt.hpp"

namespace dtlab {

namespace {

struct Candidate {
  double length;
  std::uint32_t a, b;
};

}  // namespace

void insert_edge_points(Mesh2& mesh, const ControlSpace2& control, const Mesh2dOptions& options, Mesh2dStats& stats) {
  DelaunayKernel2 kernel(mesh);
  std::vector<Candidate> candidates;
  std::vector<double> cuts;
  std::uint32_t hint = ControlSpace2::kNoHint;
  for (std::uint32_t pass = 0;; ++pass) {
    mesh_pipeline::check_pass("mesh2d", "edge method", pass, options, stats);
    candidates.clear();
    for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) {
      if (!mesh.in_domain(t)) continue;
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t h = Mesh2::half_edge(t, i);
        if (mesh.is_constrained(h)) continue;
        const std::uint32_t g = mesh.twin(h);
        if (g < h && mesh.in_domain(Mesh2::triangle_of(g))) continue;  // each internal edge once
        const std::uint32_t a = mesh.origin(h), b = mesh.destination(h);
        const double l = edge_length(mesh.point(a), mesh.metric(a), mesh.point(b), mesh.metric(b));
        if (l > options.split_length) candidates.push_back({l, a, b});
      }
    }
    if (candidates.empty()) break;
    // Longest first, ties by vertex ids: deterministic, and long edges shape the mesh first.
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
      if (x.length != y.length) return x.length > y.length;
      if (x.a != y.a) return x.a < y.a;
      return x.b < y.b;
    });
    std::uint64_t inserted = 0;
    for (const Candidate& c : candidates) {
      if (mesh.is_dead_vertex(c.a) || mesh.is_dead_vertex(c.b)) continue;
      cut_edge(mesh, c.a, c.b, c.length, cuts, [&](const Vec2& p) {
        // The walk may pass through the exterior (c.a's triangle may be there); p itself lies on
        // an internal edge, so in the domain.
        const Mesh2::Location loc = mesh.locate(p, mesh.vertex_triangle(c.a));
        if (loc.where == Mesh2::Where::Outside || loc.where == Mesh2::Where::Vertex ||
            !mesh.in_domain(loc.triangle)) {
          ++stats.not_inserted;
          return;
        }
        const Metric2 mp = control.metric_at(p, hint);
        if (!kernel.find_cavity(p, mp, loc.triangle)) {
          ++stats.not_inserted;
          return;
        }
        if (kernel.nearest_cavity_vertex(p, mp) < options.filter_distance) {
          ++stats.filtered;
          return;
        }
        if (mesh.live_vertex_count() >= options.max_vertices) {
          throw InputError("mesh2d: the mesh reached the vertex bound of " + std::to_string(options.max_vertices) +
                           " (is the size far smaller than the domain?)");
        }
        kernel.commit(p, mp);
        ++inserted;
      });
    }
    stats.field_points += inserted;
    stats.passes = pass + 1;
    if (inserted == 0) break;
  }
  stats.cavity_corrections += kernel.corrections();
}

}  // namespace dtlab
