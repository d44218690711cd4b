// Method "cdt": a constrained Delaunay tetrahedralization (Shewchuk 2002, "Constrained Delaunay
// tetrahedralizations and provably good boundary recovery"; book §3.5-§3.7). A CDT of a PLC
// exists when every segment is strongly Delaunay; with the symbolic perturbation every edge of
// the (unique) Delaunay tetrahedralization is, so:
//  1. Segments: the Delaunay tetrahedralization of the vertices, and every missing edge piece
//     split (concentric shells, as in "conforming") until each is an edge of it.
//  2. Facets, on a copy: each input triangle whose pieces the Delaunay tetrahedralization
//     already holds keeps them; every other one gets the Delaunay triangulation of its vertices
//     in its plane (facet_delaunay_pieces) inserted by cavity retriangulation
//     (FlipRecovery::insert_facet: the tetrahedra it crosses removed and gift-wrapped again on
//     both sides of it). Facets inserted into a CDT leave a CDT.
//  3. Where a facet's cavity cannot be filled, or its filling is not constrained Delaunay
//     against its surroundings (the theorem above is about exact planar facets; rounded Steiner
//     points make them slightly non-planar), its longest boundary piece is
//     split and the round starts again from step 1. After kRounds such rounds the method hands
//     over to "recover" and says so (the result is then not constrained Delaunay).
// Every Steiner point is on an input edge: the facets get none.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "algorithms/constrained3d/flip_recovery.hpp"
#include "algorithms/constrained3d/recovery.hpp"
#include "kernel/error.hpp"

namespace dtlab {

void constrained3d_recover(Constrained3dContext& context);  // recover.cpp

namespace {

constexpr int kRounds = 8;

// Splits every missing edge piece until the Delaunay tetrahedralization holds them all; each
// pass adds a point, so the Steiner limit (the inserter's InputError) bounds the passes.
void make_segments_delaunay(Constrained3dContext& c, SteinerInserter& inserter) {
  for (;;) {
    const MeshIndex index(c.mesh);
    std::vector<EdgeSplit> splits;
    for (std::uint32_t e = 0; e < c.edges.size(); ++e) {
      const auto& chain = c.edges[e].chain;
      for (std::size_t i = 0; i + 1 < chain.size(); ++i)
        if (!index.has_edge(chain[i], chain[i + 1])) splits.push_back({e, edge_split_parameter(c, e, i)});
    }
    if (splits.empty()) return;
    inserter.insert(splits, {});
  }
}

// The longest boundary piece of facet f, as an edge split request.
EdgeSplit longest_boundary_split(const Constrained3dContext& c, std::uint32_t f) {
  const auto p = c.mesh.points();
  double best = -1;
  EdgeSplit split;
  for (const std::uint32_t e : c.facets[f].edges) {
    const auto& chain = c.edges[e].chain;
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      const Vec3 d = p[chain[i + 1]] - p[chain[i]];
      const double length = dot(d, d);
      if (length > best) best = length, split = {e, edge_split_parameter(c, e, i)};
    }
  }
  return split;
}

}  // namespace

void constrained3d_cdt(Constrained3dContext& c) {
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point from) { return std::chrono::duration<double>(Clock::now() - from).count(); };
  SteinerInserter inserter(c);
  std::string why;
  for (int round = 0; round < kRounds; ++round) {
    ++c.rounds;
    auto start = Clock::now();
    make_segments_delaunay(c, inserter);
    c.edge_seconds += seconds(start);
    start = Clock::now();
    Tetrahedralization3 work = c.mesh;
    std::vector<std::uint64_t> protected_edges;
    for (const ConstraintEdge3& e : c.edges)
      for (std::size_t i = 0; i + 1 < e.chain.size(); ++i) protected_edges.push_back(MeshIndex::key(e.chain[i], e.chain[i + 1]));
    std::sort(protected_edges.begin(), protected_edges.end());
    // Triangles the Delaunay tetrahedralization already holds keep their pieces, protected.
    const MeshIndex index(c.mesh);
    std::vector<std::array<std::uint32_t, 3>> held;
    std::vector<std::uint32_t> missing;
    std::vector<std::array<std::uint32_t, 2>> unused;
    for (std::uint32_t f = 0; f < c.facets.size(); ++f) {
      unused.clear();
      if (facet_still_covered(c, f, index) || cover_facet(c, f, index, unused)) {
        for (auto k : c.facets[f].pieces) {
          std::sort(k.begin(), k.end());
          held.push_back(k);
        }
      } else {
        missing.push_back(f);
      }
    }
    std::sort(held.begin(), held.end());
    FlipRecovery recovery(work, std::move(protected_edges), std::move(held));
    std::vector<EdgeSplit> splits;
    for (const std::uint32_t f : missing) {
      std::vector<std::array<std::uint32_t, 3>> pieces = facet_delaunay_pieces(c, f);
      std::string reason;
      if (recovery.insert_facet(pieces, reason)) {
        c.facets[f].pieces = std::move(pieces);
        c.facets[f].pieces_vertex_count = facet_vertex_count(c, f);
      } else {
        splits.push_back(longest_boundary_split(c, f));
        why = "triangle " + std::to_string(f + 1) + ": " + reason;
      }
    }
    recovery.finish();
    c.face_seconds += seconds(start);
    if (splits.empty()) {
      c.mesh = std::move(work);
      c.constrained_delaunay = true;
      c.rounding_checks_failed = inserter.rounding_checks_failed();
      return;
    }
    inserter.insert(splits, {});
  }
  c.rounding_checks_failed = inserter.rounding_checks_failed();
  for (auto& f : c.facets) f.pieces.clear();
  c.messages.push_back("cdt: no constrained Delaunay filling after " + std::to_string(kRounds) + " rounds (" + why +
                       "); recovered as by method recover instead, so the result is not constrained Delaunay");
  constrained3d_recover(c);
}

}  // namespace dtlab
