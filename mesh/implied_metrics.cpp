#include "mesh/implied_metrics.hpp"

#include <array>
#include <cstdint>
#include <span>

namespace dtlab {

namespace {

// The edges of an element, in the order the sums are taken (the order fixes the rounding).
constexpr std::array<std::array<std::size_t, 2>, 3> kTriangleEdges{{{0, 1}, {1, 2}, {2, 0}}};
constexpr std::array<std::array<std::size_t, 2>, 6> kTetrahedronEdges{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

template <class MetricT, class Point, std::size_t N, std::size_t E>
std::vector<MetricT> mean_edge_sizes(std::span<const Point> vertices, std::span<const std::array<std::uint32_t, N>> elements,
                                     const std::array<std::array<std::size_t, 2>, E>& edges) {
  std::vector<double> sum(vertices.size(), 0.0);
  std::vector<std::uint32_t> count(vertices.size(), 0);
  for (const auto& e : elements) {
    for (const auto& [i, j] : edges) {
      const std::uint32_t a = e[i], b = e[j];
      if (a >= vertices.size() || b >= vertices.size()) continue;
      const double l = norm(vertices[b] - vertices[a]);
      sum[a] += l;
      sum[b] += l;
      ++count[a];
      ++count[b];
    }
  }
  std::vector<MetricT> metrics(vertices.size());
  for (std::size_t v = 0; v < metrics.size(); ++v)
    if (count[v] > 0 && sum[v] > 0.0) metrics[v] = MetricT::isotropic(sum[v] / count[v]);
  return metrics;
}

}  // namespace

std::vector<Metric2> implied_metrics(const MeshData2& data) {
  return mean_edge_sizes<Metric2, Vec2, 3>(std::span<const Vec2>(data.vertices), std::span<const std::array<std::uint32_t, 3>>(data.triangles), kTriangleEdges);
}

std::vector<Metric3> implied_metrics(const MeshData3& data) {
  return mean_edge_sizes<Metric3, Vec3, 4>(std::span<const Vec3>(data.vertices), std::span<const std::array<std::uint32_t, 4>>(data.tetrahedra), kTetrahedronEdges);
}

}  // namespace dtlab
