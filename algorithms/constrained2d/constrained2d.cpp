// constrained2d(): input validation (segment endpoints, zero-length and duplicate segments),
// the Delaunay triangulation of the points (delaunay2d, "incremental"), the chosen method
// (registry.hpp), the domain (domain.hpp) and the result lists.
#include "algorithms/constrained2d/constrained2d.hpp"

#include <algorithm>
#include <chrono>
#include <tuple>

#include "algorithms/constrained2d/domain.hpp"
#include "algorithms/constrained2d/registry.hpp"
#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "kernel/error.hpp"

namespace dtlab {

Constrained2dResult constrained2d(const ConstrainedInput2& input, const Constrained2dOptions& options) {
  const Constrained2dMethod& method = constrained2d_methods().at(options.method);
  const PredicateStats before = predicate_stats();
  const auto start = std::chrono::steady_clock::now();
  const std::size_t n = input.points.size();
  const auto number = [&options](std::uint64_t i) { return std::to_string(i + options.first_number); };
  if (!input.segment_markers.empty() && input.segment_markers.size() != input.segments.size())
    throw InputError("segment markers: " + std::to_string(input.segment_markers.size()) + " markers for " +
                     std::to_string(input.segments.size()) + " segments");
  for (std::size_t k = 0; k < input.segments.size(); ++k)
    for (const std::uint32_t v : input.segments[k])
      if (v >= n)
        throw InputError("segment " + number(k) + ": endpoint " + number(v) + " is out of range (" +
                             std::to_string(n) + " points, numbered from " + number(0) + ")",
                         {k});

  Delaunay2dResult delaunay = delaunay2d(input.points, {.algorithm = "incremental", .seed = options.seed});
  Constrained2dResult result;
  result.input_point_count = static_cast<std::uint32_t>(n);

  // Endpoints onto the kept copy of duplicate points; zero length refused; duplicates dropped.
  std::vector<std::uint32_t> keep(n);
  for (std::uint32_t v = 0; v < n; ++v) keep[v] = v;
  for (std::size_t k = 0; k < delaunay.duplicates.size(); ++k) keep[delaunay.duplicates[k]] = delaunay.duplicate_of[k];
  std::vector<std::array<std::uint32_t, 3>> keyed;  // (low, high, input index)
  keyed.reserve(input.segments.size());
  for (std::size_t k = 0; k < input.segments.size(); ++k) {
    const auto [a0, b0] = input.segments[k];
    const std::uint32_t a = keep[a0], b = keep[b0];
    if (a == b)
      throw InputError("segment " + number(k) + " has zero length (endpoints " + number(a0) + " and " +
                           number(b0) + (a0 == b0 ? " are the same point)" : " have equal coordinates)"),
                       {k});
    keyed.push_back({std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(k)});
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::array<std::uint32_t, 2>> segments;
  std::vector<std::uint32_t> ids;
  std::vector<std::uint32_t> kept;  // input indices
  std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicate_of;  // (dropped segment, the one kept)
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    if (k > 0 && keyed[k][0] == keyed[k - 1][0] && keyed[k][1] == keyed[k - 1][1]) {
      std::size_t first = k - 1;
      while (first > 0 && keyed[first - 1][0] == keyed[k][0] && keyed[first - 1][1] == keyed[k][1]) --first;
      if (result.messages.size() < Constrained2dResult::kMaxMessages)
        result.messages.push_back("segment " + number(keyed[k][2]) + " duplicates segment " +
                                  number(keyed[first][2]) + ": kept " + number(keyed[first][2]));
      ++result.message_count;
      duplicate_of.emplace_back(keyed[k][2], keyed[first][2]);
      continue;
    }
    kept.push_back(keyed[k][2]);
  }
  std::sort(kept.begin(), kept.end());
  for (const std::uint32_t k : kept) {
    segments.push_back({keep[input.segments[k][0]], keep[input.segments[k][1]]});
    ids.push_back(k);
  }
  if (!delaunay.duplicates.empty()) {
    result.messages.push_back(std::to_string(delaunay.duplicates.size()) +
                              " duplicate point(s) dropped; segments use the first copy");
    ++result.message_count;
  }

  result.triangulation = std::move(delaunay.triangulation);
  result.degenerate_message = std::move(delaunay.degenerate_message);
  if (result.degenerate_message.empty()) {
    ConstrainedMesh2 mesh(result.triangulation);
    const Constrained2dContext run{.mesh = mesh, .segments = segments, .ids = ids, .options = options, .result = result};
    method.run(run);
    result.flips = static_cast<std::uint32_t>(mesh.flip_count());
    build_domain(run, input.holes, input.regions);
    const Triangulation2& tri = result.triangulation;
    const auto marker = [&](std::uint32_t s) { return input.segment_markers.empty() ? 0 : input.segment_markers[s]; };
    const auto size = static_cast<std::uint32_t>(tri.vertices().size());
    for (std::uint32_t h = 0; h < size; ++h) {
      const std::uint32_t s = mesh.constraint(h);
      if (h > tri.twin(h) || s == ConstrainedMesh2::kNone) continue;
      const std::uint32_t a = tri.origin(h), b = tri.destination(h);
      result.constrained_edges.push_back({std::min(a, b), std::max(a, b), s, marker(s), h});
    }
    std::sort(result.constrained_edges.begin(), result.constrained_edges.end(),
              [](const ConstrainedEdge2& x, const ConstrainedEdge2& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
    for (const auto& [a, b, s] : mesh.shared_constraints()) result.shared_edges.push_back({a, b, s, marker(s)});
    // A dropped duplicate covers the edges of the segment kept for it.
    if (!duplicate_of.empty()) {
      std::vector<std::vector<std::array<std::uint32_t, 2>>> edges_of(input.segments.size());
      for (const auto* list : {&result.constrained_edges, &result.shared_edges})
        for (const ConstrainedEdge2& e : *list) edges_of[e.segment].push_back({e.a, e.b});
      for (const auto& [dropped, kept_one] : duplicate_of)
        for (const auto& [a, b] : edges_of[kept_one]) result.shared_edges.push_back({a, b, dropped, marker(dropped)});
    }
    std::sort(result.shared_edges.begin(), result.shared_edges.end(), [](const ConstrainedEdge2& x, const ConstrainedEdge2& y) {
      return std::tie(x.a, x.b, x.segment) < std::tie(y.a, y.b, y.segment);
    });
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.predicate_stats = predicate_stats() - before;
  return result;
}

}  // namespace dtlab
