// Items grouped by a vertex of each (a counting sort): the items at vertex v are
// order[start[v]] ... order[start[v + 1] - 1], in increasing item number. O(items + vertices),
// no hash table; vertex order keeps an item's neighbours near it in memory. Used to number a
// surface's edges (constrained3d's build_constraints) and to look a surface up in a mesh
// (find_in_mesh).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/error.hpp"

namespace dtlab {

struct VertexBuckets {
  std::vector<std::uint32_t> start;  // vertices + 1 offsets into order
  std::vector<std::uint32_t> order;  // item numbers
};

// vertex_of(k) for k in [0, items): a vertex id below `vertices` (else InternalError).
template <class VertexOf>
VertexBuckets vertex_buckets(std::size_t vertices, std::size_t items, VertexOf&& vertex_of) {
  VertexBuckets b;
  b.start.assign(vertices + 1, 0);
  for (std::size_t k = 0; k < items; ++k) {
    const std::size_t v = vertex_of(k);
    if (v >= vertices) throw InternalError("vertex_buckets: vertex " + std::to_string(v) + " out of range");
    ++b.start[v + 1];
  }
  for (std::size_t v = 0; v < vertices; ++v) b.start[v + 1] += b.start[v];
  std::vector<std::uint32_t> fill(b.start.begin(), b.start.end() - 1);
  b.order.resize(items);
  for (std::size_t k = 0; k < items; ++k) b.order[fill[vertex_of(k)]++] = static_cast<std::uint32_t>(k);
  return b;
}

}  // namespace dtlab
