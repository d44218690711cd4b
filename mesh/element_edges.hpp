// The edges of a simplicial mesh, each once: (a, b) with a < b, in increasing order. One helper
// for every caller that walks a mesh's edges (the metric gradation in dtlab metric and dtlab
// adapt, 2D and 3D).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace dtlab {

template <std::size_t K>
std::vector<std::array<std::uint32_t, 2>> element_edges(std::span<const std::array<std::uint32_t, K>> elements) {
  std::vector<std::array<std::uint32_t, 2>> edges;
  edges.reserve(elements.size() * K * (K - 1) / 2);
  for (const auto& e : elements)
    for (std::size_t i = 0; i < K; ++i)
      for (std::size_t j = i + 1; j < K; ++j) edges.push_back({std::min(e[i], e[j]), std::max(e[i], e[j])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace dtlab
