// Method "conforming": boundary recovery by Steiner points only, the simplest robust form of
// book §3.5.3, as in conforming Delaunay tetrahedralization (Murphy, Mount, Gable 2001; Cohen-
// Steiner, Colin de Verdière, Yvinec 2004). The mesh stays the Delaunay tetrahedralization of
// all its vertices; each round first splits every missing edge piece (concentric shells), and
// only when every edge is a chain of mesh edges refines the triangles whose pieces are not all
// mesh faces (circumcentres; encroached boundary pieces split first). Every round adds a point,
// so the Steiner limit bounds the rounds.
#include <chrono>
#include <string>
#include <vector>

#include "algorithms/constrained3d/recovery/recovery.hpp"
#include "kernel/error.hpp"

namespace dtlab {

void constrained3d_conforming(Constrained3dContext& c) {
  using Clock = std::chrono::steady_clock;
  SteinerInserter inserter(c);
  for (;;) {
    ++c.rounds;
    auto start = Clock::now();
    const MeshIndex index(c.mesh);
    std::vector<EdgeSplit> splits;
    std::vector<FacetPoint> points;
    for (std::uint32_t e = 0; e < c.edges.size(); ++e) {
      const auto& chain = c.edges[e].chain;
      for (std::size_t i = 0; i + 1 < chain.size(); ++i)
        if (!index.has_edge(chain[i], chain[i + 1])) splits.push_back({e, edge_split_parameter(c, e, i)});
    }
    if (!splits.empty()) {
      inserter.insert(splits, points);
      c.edge_seconds += std::chrono::duration<double>(Clock::now() - start).count();
      continue;
    }
    c.edge_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    start = Clock::now();
    request_missing_facet_points(c, index, splits, points);
    const std::size_t added = splits.empty() && points.empty() ? 0 : inserter.insert(splits, points);
    c.face_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    if (splits.empty() && points.empty()) break;
    if (added == 0) inserter.throw_stuck();
  }
  c.rounding_checks_failed = inserter.rounding_checks_failed();
}

}  // namespace dtlab
