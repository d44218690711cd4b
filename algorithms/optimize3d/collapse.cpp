// Edge collapse of book §8.3.5 in 3D (vertex suppression by edge reduction): the free end x of
// edge xy is removed, every tetrahedron of its ball not holding y takes y in x's place, and the
// shell of xy disappears. When every new tetrahedron is positive (exact orient3d), y sees every
// facet of the ball's boundary from inside, so the new tetrahedra tile the old ball exactly.
#include <algorithm>
#include <array>
#include <limits>
#include <tuple>
#include <vector>

#include "algorithms/optimize3d/local.hpp"
#include "algorithms/optimize3d/operators.hpp"

namespace dtlab {

using namespace optimize3d_detail;

namespace {

struct Candidate {
  std::uint32_t removed = Mesh3::kNone;
  std::vector<std::uint32_t> ball;
  std::vector<NewTetrahedron> fresh;
  double before = 0.0, after = std::numeric_limits<double>::infinity();
};

// Simulates removing x onto y; false when invalid.
bool simulate(const Mesh3& mesh, std::uint32_t x, std::uint32_t y, const Collapse3Options& options, Candidate& c) {
  c.removed = Mesh3::kNone;
  c.before = 0.0;
  c.after = std::numeric_limits<double>::infinity();
  if (!is_free_vertex(mesh, x, c.ball)) return false;
  bool has_edge = false;
  c.fresh.clear();
  // The vertices of y's ball, gathered at the first long new edge: find_edge(y, w) without a
  // search of the ball for each.
  thread_local std::vector<std::uint32_t> y_ball, y_neighbours;  // (buffers kept across calls)
  y_neighbours.clear();
  bool gathered = false;
  auto is_edge = [&](std::uint32_t w) {
    if (!gathered) {
      mesh.ball(y, y_ball);
      for (const std::uint32_t t : y_ball)
        for (const std::uint32_t z : mesh.tetrahedron(t)) y_neighbours.push_back(z);
      std::sort(y_neighbours.begin(), y_neighbours.end());
      gathered = true;
    }
    return std::binary_search(y_neighbours.begin(), y_neighbours.end(), w);
  };
  for (const std::uint32_t t : c.ball) {
    auto v = mesh.tetrahedron(t);
    if (std::find(v.begin(), v.end(), y) != v.end()) {
      has_edge = true;
      continue;
    }
    for (auto& w : v) {
      if (w == x) {
        w = y;
      } else if (edge_length(mesh, y, w) > options.long_length && !is_edge(w)) {
        return false;
      }
    }
    if (!positive(mesh, v[0], v[1], v[2], v[3])) return false;
    c.fresh.push_back({v, mesh.ref(t)});
  }
  if (!has_edge || c.fresh.empty()) return false;
  c.removed = x;
  c.before = worst_quality(mesh, c.ball);
  c.after = worst_quality(mesh, std::span<const NewTetrahedron>(c.fresh));
  return true;
}

}  // namespace

bool try_collapse3(Mesh3& mesh, std::uint32_t u, std::uint32_t v, const Collapse3Options& options,
                   Collapse3Criterion criterion) {
  if (u == v || u >= mesh.vertex_capacity() || v >= mesh.vertex_capacity() || mesh.is_dead_vertex(u) ||
      mesh.is_dead_vertex(v) || mesh.is_constrained_edge(u, v))
    return false;
  // The candidates' buffers live across calls (collapses are tried by the thousand).
  thread_local Candidate first, second;
  Candidate* best = &first;
  Candidate* other = &second;
  const bool a = simulate(mesh, v, u, options, *best);
  const bool b = simulate(mesh, u, v, options, *other);
  if (!a && !b) return false;
  if (!a || (b && other->after < best->after)) std::swap(best, other);
  const bool accept = criterion == Collapse3Criterion::Improve
                          ? best->after < best->before * (1.0 - options.margin)
                          : best->after <= std::max(best->before, options.quality_limit);
  if (!accept) return false;
  thread_local std::vector<std::uint32_t> slots;
  replace_tetrahedra(mesh, best->ball, best->fresh, slots);
  mesh.remove_vertex(best->removed);
  return true;
}

std::uint64_t collapse_pass3(Mesh3& mesh, const Collapse3Options& options) {
  return optimize3d_detail::collapse_pass(mesh, options, {});
}

std::uint64_t optimize3d_detail::collapse_pass(Mesh3& mesh, const Collapse3Options& options, Region region) {
  std::vector<std::tuple<double, std::uint32_t, std::uint32_t>> edges;
  for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    const auto v = mesh.tetrahedron(t);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const std::uint32_t a = std::min(v[i], v[j]), b = std::max(v[i], v[j]);
        // Only edges with a free end can collapse.
        if ((mesh.flags(a) & (Mesh3::kFixed | Mesh3::kOnBoundary)) && (mesh.flags(b) & (Mesh3::kFixed | Mesh3::kOnBoundary)))
          continue;
        if (!in_region(region, a) || !in_region(region, b)) continue;
        const double l = edge_length(mesh, a, b);
        if (l < options.short_length) edges.emplace_back(l, a, b);
      }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::uint64_t done = 0;
  for (const auto& [l, a, b] : edges) {
    if (mesh.is_dead_vertex(a) || mesh.is_dead_vertex(b)) continue;
    if (edge_length(mesh, a, b) >= options.short_length) continue;  // a relocation may have moved an end
    done += try_collapse3(mesh, a, b, options, Collapse3Criterion::NotWorse) ? 1 : 0;
  }
  return done;
}

}  // namespace dtlab
