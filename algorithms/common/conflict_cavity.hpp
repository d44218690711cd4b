// The cavity of Bowyer-Watson insertion (book §2.4; George & Borouchaki), written once for the
// dynamic Delaunay structures of both dimensions (DynamicDelaunay2 on Mesh2, DynamicDelaunay3
// on Mesh3): from `start`, in conflict with the new point, the elements in conflict reached
// across facets (a ball under a genuine perturbation), and the facet handles on its boundary
// (inside the cavity, their twin outside).
#pragma once

#include <cstdint>
#include <vector>

#include "kernel/error.hpp"

namespace dtlab {

// Mesh: twin(h), facet handle h = kFacets * element + i. in_conflict(element) decides;
// stamp has an entry per element slot; `epoch` marks the cavity and epoch + 1 the elements
// found outside it (the caller takes a fresh even epoch per search). At most `bound` elements.
template <std::uint32_t kFacets, class Mesh, class InConflict>
void conflict_cavity(const Mesh& mesh, std::uint32_t start, InConflict&& in_conflict, std::vector<std::uint32_t>& stamp,
                     std::uint32_t epoch, std::size_t bound, std::vector<std::uint32_t>& cavity,
                     std::vector<std::uint32_t>& stack, std::vector<std::uint32_t>& boundary) {
  cavity.clear();
  boundary.clear();
  stack.assign(1, start);
  stamp[start] = epoch;
  while (!stack.empty()) {
    const std::uint32_t t = stack.back();
    stack.pop_back();
    cavity.push_back(t);
    if (cavity.size() > bound) throw InternalError("conflict cavity: more elements than the mesh holds");
    for (std::uint32_t h = kFacets * t; h < kFacets * t + kFacets; ++h) {
      const std::uint32_t u = mesh.twin(h) / kFacets;
      if (stamp[u] == epoch) continue;
      if (stamp[u] != epoch + 1 && in_conflict(u)) {
        stamp[u] = epoch;
        stack.push_back(u);
      } else {
        stamp[u] = epoch + 1;
        boundary.push_back(h);
      }
    }
  }
}

}  // namespace dtlab
