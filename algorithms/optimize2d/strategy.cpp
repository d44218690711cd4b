// The optimization strategy of book §8.6.3 in 2D: classify the triangles by Q_K, treat the bad
// ones worst first with the operator sequence their pathology calls for (a flat "cap" is cured
// by swapping its longest edge or moving its vertices, a topological defect by a swap and
// relocations judged together, a "needle" by collapsing its short edge:
// Frey and George, "Mesh Generation", §18.3), then apply each operator to the whole mesh (sizes
// by collapse and split toward a unit mesh, swaps, relocation sweeps), and repeat while a round
// still improves the worst or the mean quality significantly (§8.6.3's stopping criterion). A
// round runs the operators by name from their registry (registry.hpp), in options.sequence.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "algorithms/common/optimize_strategy.hpp"
#include "algorithms/optimize2d/local.hpp"
#include "algorithms/optimize2d/optimize2d.hpp"
#include "algorithms/optimize2d/registry.hpp"

namespace dtlab {

using optimize2d_detail::edge_length;
using optimize2d_detail::triangle_quality;

QualitySummary2 summarize_quality(const Mesh2& mesh) {
  QualitySummary2 s;
  double sum = 0.0;
  std::uint64_t finite = 0;
  for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    const double q = triangle_quality(mesh, t);
    ++s.triangles;
    s.worst = std::max(s.worst, q);
    if (std::isfinite(q)) {
      sum += q;
      ++finite;
    }
  }
  s.mean = finite > 0 ? sum / static_cast<double>(finite) : 0.0;
  return s;
}

// The bad triangles, worst first: for each, the operators of its pathology until one applies.
OperatorResult optimize2d_detail::treat_bad_triangles(Mesh2& mesh, const Optimize2dOptions& options,
                                                      const MetricField2& field, Optimize2dStats& stats) {
  auto quality = [&](std::uint32_t t) { return triangle_quality(mesh, t); };
  auto vertices = [&](std::uint32_t t) { return std::array{mesh.vertex(t, 0), mesh.vertex(t, 1), mesh.vertex(t, 2)}; };
  const auto bad = optimize_detail::bad_elements(mesh, mesh.triangle_capacity(), options.bad_quality, quality, vertices);
  for (const auto& b : bad) {
    const std::uint32_t t = b.t;
    if (!mesh.in_domain(t) || vertices(t) != b.v) continue;  // changed or freed by an earlier one
    // Edges by metric length, longest first: edge i is opposite vertex i.
    std::array<std::pair<double, std::uint32_t>, 3> edges;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      edges[i] = {edge_length(mesh, mesh.origin(h), mesh.destination(h)), h};
    }
    std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) {
      return x.first > y.first || (x.first == y.first && x.second < y.second);
    });
    bool done = false;
    if (options.swaps) {
      for (const auto& e : edges) {
        if (try_swap(mesh, e.second, options.swap_margin)) {
          ++stats.swaps;
          done = true;
          break;
        }
      }
    }
    if (done) continue;
    if (options.relocation) {
      for (const std::uint32_t v : b.v) {
        if (try_relocate(mesh, v, field, options.relocate)) {
          ++stats.relocations;
          done = true;
        }
      }
    }
    if (done) continue;
    if (options.swaps && options.relocation) {
      for (const auto& e : edges) {
        if (try_swap_relocate(mesh, e.second, field, options.relocate, options.swap_margin)) {
          ++stats.swap_relocations;
          done = true;
          break;
        }
      }
    }
    if (done || !options.collapses) continue;
    if (try_collapse(mesh, edges[2].second, options.collapse, CollapseCriterion::Improve)) ++stats.collapses;
  }
  return {};
}

namespace {

// The 2D part of the round loop (algorithms/common/optimize_strategy.hpp): a round's operators.
struct Rounds2 : optimize_detail::RoundState<Mesh2, Optimize2dOptions, MetricField2, Optimize2dStats> {
  static constexpr const char* kRoundStart = "optimize2d: at the start of a round";
  static constexpr const char* kName = "optimize2d";

  QualitySummary2 scan() const { return summarize_quality(mesh); }
  optimize_detail::RoundGoal goal(const QualitySummary2&) const { return {}; }
  void finish(const QualitySummary2& before, const QualitySummary2& after) {
    stats.triangles_before = before.triangles;
    stats.triangles_after = after.triangles;
  }

  std::vector<Optimize2dOperator> sequence;  // options.sequence's operators

  optimize_detail::RoundResult round(std::uint32_t, const QualitySummary2&) {
    const OperatorResult r = optimize_detail::run_operators<Optimize2dOperator>(
        sequence, options.interrupt, "optimize2d",
        [&](const Optimize2dOperator& op) { return op.pass(mesh, options, field, stats); });
    return {r.size_changes != 0, r.limit};
  }
};

}  // namespace

Optimize2dStats optimize2d(Mesh2& mesh, const Optimize2dOptions& options, const MetricField2& field) {
  const auto& operators = options.operators ? *options.operators : optimize2d_operators();
  auto sequence = optimize_detail::operator_sequence(operators, options.sequence);
  return optimize_detail::optimize_rounds(Rounds2{{mesh, options, field}, std::move(sequence)});
}

}  // namespace dtlab
