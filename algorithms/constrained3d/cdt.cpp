// Method "cdt": a constrained Delaunay tetrahedralization of the domain (every region the output
// keeps): no tetrahedron's circumsphere holds strictly inside a vertex that the tetrahedron
// sees (Shewchuk 2008, "General-dimensional constrained Delaunay and constrained regular
// triangulations"; book §3.5-§3.7). Two constructions, the first preferred:
//
// A. Recover, then flip (fewer Steiner points): method "recover" makes every constraint a face
//    or edge, and Lawson's flips with constraints (FlipRecovery::make_constrained_delaunay) make
//    every face that is no constraint locally Delaunay where they can; by the constrained
//    Delaunay lemma the result is then a CDT. Faces of kept regions that stay not locally
//    Delaunay are blamed on a constraint edge piece: the one their flip would remove, or (only
//    where no face has such a piece) the longest one of their two tetrahedra. Those pieces are
//    split (as in "conforming") in the Delaunay tetrahedralization and A starts again, at most
//    kFlipRounds times, and not once the faces left grow two rounds in a row or recover needed
//    more Steiner points than there are input edges (cascades, as on Chazelle's polyhedron).
//    Coplanar input triangles whose pair is not Delaunay in their plane make such blocks: they
//    must stay faces, so no flip can help there.
// B. Shewchuk 2002 ("Constrained Delaunay tetrahedralizations and provably good boundary
//    recovery"), where A fails: a CDT exists once every segment is strongly Delaunay, which
//    with the symbolic perturbation every edge of the (unique) Delaunay tetrahedralization is:
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
//    B puts every Steiner point on an input edge: the facets get none.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algorithms/constrained3d/flip_recovery.hpp"
#include "algorithms/constrained3d/recovery.hpp"
#include "algorithms/constrained3d/regions.hpp"
#include "kernel/error.hpp"

namespace dtlab {

void constrained3d_recover(Constrained3dContext& context);  // recover.cpp

namespace {

constexpr int kRounds = 8;
constexpr int kFlipRounds = 16;

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

// Per tetrahedron of c.mesh: 1 where the output drops it (the exterior, unless it is kept), so
// that its faces need not be constrained Delaunay. pieces: facet_piece_keys(c), the walls.
std::vector<std::uint8_t> dropped_tetrahedra(const Constrained3dContext& c,
                                             std::span<const std::array<std::uint32_t, 3>> pieces) {
  std::vector<std::uint8_t> dropped(c.mesh.tetrahedron_count(), 0);
  if (c.keep_exterior) return dropped;
  const TetrahedronComponents comp = tetrahedron_components(c.mesh, pieces);
  for (std::uint32_t t = 0; t < dropped.size(); ++t) dropped[t] = comp.component[t] == comp.exterior;
  return dropped;
}

// Construction A above. True with c the result; false with `why` (c unchanged) where recover
// fails, a face is stuck with no constraint piece to blame, the stuck faces grow two rounds in a
// row, recover needs more Steiner points than there are input edges, or kFlipRounds pass.
bool recover_then_flip(Constrained3dContext& c, std::string& why) {
  using Clock = std::chrono::steady_clock;
  // The Delaunay tetrahedralization with the splits made so far; c itself until the first.
  std::optional<Constrained3dContext> split;
  std::size_t previous = 0;  // faces left by the last round
  int growing = 0;           // rounds in a row that left more faces than the one before
  for (int round = 0; round < kFlipRounds; ++round) {
    Constrained3dContext work = split ? *split : c;
    // Recover may cascade for minutes before it ends (CGAL's anchor.off): held to one Steiner
    // point more than there are input edges, where A gives up below anyway.
    work.steiner_limit = static_cast<std::uint32_t>(std::min<std::size_t>(c.steiner_limit, work.edges.size() + 1));
    try {
      constrained3d_recover(work);
    } catch (const InputError& e) {
      why = std::string("recover failed: ") + e.what();
      return false;
    }
    work.steiner_limit = c.steiner_limit;
    const auto begin = Clock::now();
    std::vector<std::array<std::uint32_t, 3>> pieces = facet_piece_keys(work);
    std::vector<std::uint8_t> dropped = dropped_tetrahedra(work, pieces);
    FlipRecovery recovery(work.mesh, edge_piece_keys(work), std::move(pieces));
    const auto left = recovery.make_constrained_delaunay(std::uint64_t{64} * work.mesh.tetrahedron_count() + 4096,
                                                         std::move(dropped));
    recovery.finish();
    work.face_seconds += std::chrono::duration<double>(Clock::now() - begin).count();
    if (left.empty()) {
      c = std::move(work);
      c.constrained_delaunay = true;
      return true;
    }
    // Splits that keep making more blocked faces cascade (Chazelle's polyhedron), and so has
    // recover where it needed more points than there are input edges: B instead.
    growing = round > 0 && left.size() > previous ? growing + 1 : 0;
    previous = left.size();
    if (growing == 2) {
      why = "the faces not locally Delaunay grew two rounds in a row, to " + std::to_string(left.size());
      return false;
    }
    if (work.steiner.size() > work.edges.size()) {
      why = "recover needed " + std::to_string(work.steiner.size()) + " Steiner points for " +
            std::to_string(work.edges.size()) + " input edges, and " + std::to_string(left.size()) +
            " face(s) are still not locally Delaunay";
      return false;
    }
    // The blamed pieces: direct blames where there are any.
    const bool any_direct = std::any_of(left.begin(), left.end(), [](const auto& f) { return f.direct; });
    std::vector<std::uint64_t> blamed;
    for (const auto& f : left)
      if (f.blocking_edge[0] != Tetrahedralization3::kNone && f.direct == any_direct)
        blamed.push_back(MeshIndex::key(f.blocking_edge[0], f.blocking_edge[1]));
    if (blamed.empty()) {
      const auto& f = left.front().face;
      why = std::to_string(left.size()) + " face(s) not locally Delaunay that no flip can change and no constraint " +
            "piece is near, the first (" + std::to_string(f[0] + 1) + ", " + std::to_string(f[1] + 1) + ", " +
            std::to_string(f[2] + 1) + ")";
      return false;
    }
    std::sort(blamed.begin(), blamed.end());
    std::vector<EdgeSplit> splits;
    for (std::uint32_t e = 0; e < work.edges.size(); ++e) {
      const auto& chain = work.edges[e].chain;
      for (std::uint32_t i = 0; i + 1 < chain.size(); ++i)
        if (std::binary_search(blamed.begin(), blamed.end(), MeshIndex::key(chain[i], chain[i + 1])))
          splits.push_back({e, edge_split_parameter(work, e, i)});
    }
    if (!split) split = c;
    split->rounds = work.rounds;
    split->edge_seconds = work.edge_seconds, split->face_seconds = work.face_seconds;
    try {
      SteinerInserter(*split).insert(splits, {});
    } catch (const InputError& e) {
      why = std::string("splitting the blocking pieces failed: ") + e.what();
      return false;
    }
  }
  why = "faces not locally Delaunay after " + std::to_string(kFlipRounds) + " rounds of splits";
  return false;
}

}  // namespace

void constrained3d_cdt(Constrained3dContext& c) {
  std::string why;
  if (recover_then_flip(c, why)) return;
  c.messages.push_back("cdt: recover and flips gave no constrained Delaunay tetrahedralization (" + why +
                       "); segments split until they are Delaunay (Shewchuk 2002) instead");
  why.clear();
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point from) { return std::chrono::duration<double>(Clock::now() - from).count(); };
  SteinerInserter inserter(c);
  for (int round = 0; round < kRounds; ++round) {
    ++c.rounds;
    auto start = Clock::now();
    make_segments_delaunay(c, inserter);
    c.edge_seconds += seconds(start);
    start = Clock::now();
    Tetrahedralization3 work = c.mesh;
    std::vector<std::uint64_t> protected_edges = edge_piece_keys(c);
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
