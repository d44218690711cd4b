// Method "recover": the book's boundary recovery (§3.5.3), in two ways. In place
// (recover_in_place.cpp): flips, and Steiner points split into the transformed tetrahedralization.
// By rounds, where that gets stuck: the Delaunay tetrahedralization of the vertices, then each
// round, on a copy of it: every missing edge piece recovered by flips along
// its pipe, then every missing triangle (one with no Steiner point on it) by removing the edges
// that cross it (flip_recovery.hpp). What the transformations cannot recover gets Steiner
// points as in "conforming" (edge pieces split on concentric shells; triangles refined, with
// Ruppert's rule), inserted into the Delaunay tetrahedralization, and the round starts again
// from it; once a round leaves nothing missing, its transformed copy is the result. Steiner
// points therefore go only where flips fail (Schönhardt's polyhedron and its kin), and they stay
// exact points of the input (constrained3d.hpp). Every round adds a point or ends, so the
// Steiner limit bounds the rounds.
#include <algorithm>
#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/constrained3d/recovery/flip_recovery.hpp"
#include "algorithms/constrained3d/recovery/recovery.hpp"
#include "kernel/error.hpp"

namespace dtlab {

// The rounds above (Steiner points into the Delaunay tetrahedralization, flips on a copy).
// `on_many` is called once, when the Steiner points first outnumber the input's edges and
// triangles together.
void recover_by_rounds(Constrained3dContext& c, const std::function<void()>& on_many) {
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point from) { return std::chrono::duration<double>(Clock::now() - from).count(); };
  SteinerInserter inserter(c);
  bool called = false;
  const auto check = [&] {
    if (!called && c.steiner.size() > c.edges.size() + c.facets.size()) called = true, on_many();
  };
  for (;;) {
    ++c.rounds;
    auto start = Clock::now();
    Tetrahedralization3 flipped = c.mesh;
    std::vector<std::uint64_t> protected_edges = edge_piece_keys(c);
    std::vector<std::array<std::uint32_t, 3>> protected_faces;
    std::vector<std::uint8_t> single(c.facets.size(), 0);  // triangles with no Steiner point
    for (std::uint32_t f = 0; f < c.facets.size(); ++f) {
      if (facet_vertex_count(c, f) != 3) continue;
      single[f] = 1;
      auto k = c.facets[f].corners;
      std::sort(k.begin(), k.end());
      protected_faces.push_back(k);
    }
    std::sort(protected_faces.begin(), protected_faces.end());
    FlipRecovery recovery(flipped, std::move(protected_edges), std::move(protected_faces));
    std::vector<std::uint8_t> changed;
    recovery.record_changes(&changed);

    std::vector<EdgeSplit> splits;
    std::vector<FacetPoint> points;
    // One attempt each: further passes here made Chazelle's polyhedron (n = 4) run out of doubles.
    for (const MissingPiece& m : edge_pieces_flips_cannot_make(c, recovery, 0))
      splits.push_back({m.edge, edge_split_parameter(c, m.edge, m.index)});
    c.edge_seconds += seconds(start);
    if (!splits.empty()) {
      inserter.insert(splits, points);
      check();
      continue;
    }
    start = Clock::now();
    for (std::uint32_t f = 0; f < c.facets.size(); ++f) {
      if (!single[f]) continue;
      const auto& [a, b, cc] = c.facets[f].corners;
      if (!recovery.has_face(a, b, cc)) recovery.recover_face(a, b, cc);
    }
    recovery.finish();
    const MeshIndex index(flipped);
    request_missing_facet_points(c, index, splits, points);
    if (splits.empty() && points.empty()) {
      c.mesh = std::move(flipped);
      c.changed = std::move(changed);
      c.face_seconds += seconds(start);
      break;
    }
    const std::size_t added = inserter.insert(splits, points);
    c.face_seconds += seconds(start);
    if (added == 0) inserter.throw_stuck();
    check();
  }
  c.rounding_checks_failed = inserter.rounding_checks_failed();
}

std::string recover_in_place(Constrained3dContext& c);  // recover_in_place.cpp
void constrained3d_conforming(Constrained3dContext& c);  // conforming.cpp

void reset_to_delaunay(Constrained3dContext& c, Tetrahedralization3 delaunay) {
  c.mesh = std::move(delaunay);
  c.changed.clear();
  c.steiner.clear();
  for (ConstraintEdge3& e : c.edges) e.chain = {e.a, e.b}, e.t = {0.0, 1.0};
  for (ConstraintFacet3& f : c.facets) {
    f.interior.clear(), f.interior_st.clear(), f.pieces.clear();
    f.pieces_vertex_count = 0;
  }
}

void constrained3d_recover(Constrained3dContext& c) { constrained3d_recover(c, nullptr); }

void constrained3d_recover(Constrained3dContext& c, const Tetrahedralization3* delaunay) {
  // First with every Steiner point placed into the transformed tetrahedralization (TetGen's way,
  // fewer points); where that gets stuck, the rounds from the Delaunay tetrahedralization.
  // What to go back to: from the input's state (no Steiner point yet) only the tetrahedralization
  // is copied (or the caller's copy, `delaunay`, taken) and the chains are reset after, since
  // copying every edge's vectors costs as much as building them; otherwise (method cdt hands
  // over after its splits) the whole context.
  const bool fresh = c.steiner.empty();
  Tetrahedralization3 saved_mesh;
  Constrained3dContext saved;
  if (fresh) {
    if (delaunay == nullptr) saved_mesh = c.mesh;
  } else {
    saved = c;
  }
  std::string why;
  try {
    why = recover_in_place(c);
    if (why.empty()) return;
  } catch (const InputError& e) {
    why = e.what();
  }
  if (fresh) {
    reset_to_delaunay(c, delaunay == nullptr ? std::move(saved_mesh) : *delaunay);
  } else {
    c = std::move(saved);
  }
  c.messages.push_back("recover: in place recovery gave up (" + why +
                       "); Steiner points inserted into the Delaunay tetrahedralization between rounds of flips");
  // The rounds can cascade (points on a flat face of the hull, each rounded a little off it:
  // CGAL's anchor.off ran for hours). Once they need more points than the input has edges and
  // triangles, method conforming runs on the input as well, and its point count bounds the
  // rounds: where they would reach it, or fail, its result is taken.
  // Where conforming fails too, the rounds go on to the Steiner limit as before.
  Constrained3dContext input = c;
  std::optional<Constrained3dContext> conforming;
  bool conforming_failed = false;
  const std::uint32_t limit = c.steiner_limit;
  const auto run_conforming = [&] {  // once; true if conforming has a result
    if (!conforming && !conforming_failed) {
      try {
        Constrained3dContext other = input;
        constrained3d_conforming(other);
        conforming = std::move(other);
      } catch (const InputError&) {
        conforming_failed = true;
      }
    }
    return conforming.has_value();
  };
  try {
    recover_by_rounds(c, [&] {
      if (run_conforming())
        c.steiner_limit = static_cast<std::uint32_t>(std::min<std::size_t>(limit, conforming->steiner.size()));
    });
  } catch (const InputError& e) {
    if (!run_conforming()) throw;
    c = std::move(*conforming);
    c.messages.push_back(std::string("recover: the rounds stopped (") + e.what() + "); the result of method conforming (" +
                         std::to_string(c.steiner.size()) + " Steiner points) instead");
    return;
  }
  c.steiner_limit = limit;
}

}  // namespace dtlab
