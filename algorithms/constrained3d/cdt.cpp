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
//    split (as in "conforming") where they are, in the flipped tetrahedralization, and the flips
//    go on around the splits (flip_with_splits_in_place: one recovery in all); where a split
//    cannot be made there, they are split in the Delaunay tetrahedralization and A starts again
//    from recovery (recover_then_flip). Either stops after kFlipRounds rounds, once the faces
//    left grow two rounds in a row, or once recover needed more Steiner points than there are
//    input edges (cascades, as on Chazelle's polyhedron).
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

#include "algorithms/constrained3d/recovery/flip_recovery.hpp"
#include "algorithms/constrained3d/recovery/recovery.hpp"
#include "algorithms/constrained3d/regions.hpp"
#include "kernel/error.hpp"

namespace dtlab {

namespace {

constexpr int kRounds = 8;
constexpr int kFlipRounds = 16;
constexpr int kGrowingRoundsInPlace = 2;

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

// Method recover on `work`; true if it succeeds, false with `why` if it throws. Recover may
// cascade for minutes before it ends (CGAL's anchor.off): held to one Steiner point more than
// there are input edges, where construction A gives up anyway. `limit` is restored after.
// `delaunay`: as constrained3d_recover takes it.
bool recover_held(Constrained3dContext& work, std::uint32_t limit, std::string& why,
                  const Tetrahedralization3* delaunay = nullptr) {
  work.steiner_limit = static_cast<std::uint32_t>(std::min<std::size_t>(limit, work.edges.size() + 1));
  try {
    constrained3d_recover(work, delaunay);
  } catch (const InputError& e) {
    why = std::string("recover failed: ") + e.what();
    return false;
  }
  work.steiner_limit = limit;
  return true;
}

// The constraint pieces that the faces left by Lawson's flips blame (MeshIndex keys, sorted,
// distinct): direct blames where there are any. Empty, with `why`, if none names one.
std::vector<std::uint64_t> blamed_pieces(const std::vector<FlipRecovery::NotLocallyDelaunay>& left, std::string& why) {
  const bool any_direct = std::any_of(left.begin(), left.end(), [](const auto& f) { return f.direct; });
  std::vector<std::uint64_t> blamed;
  for (const auto& f : left)
    if (f.blocking_edge[0] != Tetrahedralization3::kNone && f.direct == any_direct)
      blamed.push_back(MeshIndex::key(f.blocking_edge[0], f.blocking_edge[1]));
  std::sort(blamed.begin(), blamed.end());
  blamed.erase(std::unique(blamed.begin(), blamed.end()), blamed.end());
  if (blamed.empty()) {
    const auto& f = left.front().face;
    why = std::to_string(left.size()) + " face(s) not locally Delaunay that no flip can change and no constraint " +
          "piece is near, the first (" + std::to_string(f[0] + 1) + ", " + std::to_string(f[1] + 1) + ", " +
          std::to_string(f[2] + 1) + ")";
  }
  return blamed;
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
    if (!recover_held(work, c.steiner_limit, why)) return false;
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
    const std::vector<std::uint64_t> blamed = blamed_pieces(left, why);
    if (blamed.empty()) return false;
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

// Construction A with its splits made in place (preferred: one recovery, not one a round):
// recover once, then rounds of Lawson's flips, each blamed piece split where it is, in the
// tetrahedralization the flips left (FlipRecovery::split_edge_at; the pieces of its triangles
// split with it, so they stay faces), and flips again. One FlipRecovery serves every round, so
// the regions are found once: a flip's tetrahedra are kept (flips stay in kept regions), a
// split's take the region of the one they come from. Only tetrahedra with a vertex that changed
// are flipped: in the first round a vertex of a tetrahedron recovery made (elsewhere the mesh is
// the Delaunay tetrahedralization), then a split point or a vertex of a face left; every other
// face is locally Delaunay already, its two tetrahedra unchanged since it was. False with `why` (c
// unchanged) where a split cannot be made so (a tetrahedron made would not be positive) or as
// recover_then_flip stops; that one, from the Delaunay tetrahedralization, is tried next.
// c is worked on in place: where this fails it goes back to the Delaunay tetrahedralization with
// no Steiner point (reset_to_delaunay; copying the whole context, a vector or two per edge, cost
// as much as the recovery of a surface that needs none), or to a copy where it had some already.
bool flip_with_splits_in_place(Constrained3dContext& c, std::string& why) {
  using Clock = std::chrono::steady_clock;
  const bool fresh = c.steiner.empty();
  Tetrahedralization3 delaunay;
  std::optional<Constrained3dContext> copy;
  if (fresh) {
    delaunay = c.mesh;
  } else {
    copy = c;
  }
  const std::uint32_t rounds = c.rounds, rounding_checks_failed = c.rounding_checks_failed, limit = c.steiner_limit;
  const double edge_seconds = c.edge_seconds, face_seconds = c.face_seconds;
  const std::size_t messages = c.messages.size();
  const auto restore = [&] {
    if (fresh) {
      reset_to_delaunay(c, std::move(delaunay));
    } else {
      c = std::move(*copy);
    }
    c.rounds = rounds, c.rounding_checks_failed = rounding_checks_failed, c.steiner_limit = limit;
    c.edge_seconds = edge_seconds, c.face_seconds = face_seconds;
    c.messages.resize(messages);
  };
  Constrained3dContext& work = c;
  if (!recover_held(work, c.steiner_limit, why, fresh ? &delaunay : nullptr)) {
    restore();
    return false;
  }
  const auto begin = Clock::now();
  std::vector<std::vector<std::uint32_t>> facets_of(work.edges.size());  // the triangles at each edge
  for (std::uint32_t f = 0; f < work.facets.size(); ++f)
    for (const std::uint32_t e : work.facets[f].edges) facets_of[e].push_back(f);
  std::vector<std::array<std::uint32_t, 3>> walls = facet_piece_keys(work);
  std::vector<std::uint8_t> exterior = dropped_tetrahedra(work, walls);  // by slot
  FlipRecovery recovery(work.mesh, edge_piece_keys(work), std::move(walls));
  const auto stop = [&](std::string reason) {
    recovery.finish();
    restore();
    why = std::move(reason);
    return false;
  };
  // Only tetrahedra with a vertex here are flipped: first those recovery changed (the rest is
  // still the Delaunay tetrahedralization), then the split points and the faces left.
  std::vector<std::uint8_t> touched = work.changed;
  std::vector<std::array<std::uint32_t, 2>> children;
  std::size_t previous = 0;
  int growing = 0;
  for (int round = 0; round < kFlipRounds; ++round) {
    ++work.rounds;
    std::vector<std::uint8_t> skip = exterior;
    skip.resize(recovery.slots(), 0);
    for (std::uint32_t t = 0; t < skip.size(); ++t) {
      if (skip[t] || recovery.is_dead(t)) continue;
      bool near = false;
      for (const std::uint32_t v : recovery.record(t).vertex) near = near || (v < touched.size() && touched[v]);
      skip[t] = !near;
    }
    const std::vector<std::uint8_t> skip_in = skip;
    const auto left = recovery.make_constrained_delaunay(std::uint64_t{64} * recovery.slots() + 4096, std::move(skip));
    // Slots the flips filled hold kept tetrahedra now.
    const auto& skip_out = recovery.lawson_skip();
    exterior.resize(recovery.slots(), 0);
    for (std::uint32_t t = 0; t < exterior.size(); ++t)
      if (t >= skip_in.size() || (skip_in[t] && !skip_out[t])) exterior[t] = 0;
    if (left.empty()) {
      recovery.finish();
      work.face_seconds += std::chrono::duration<double>(Clock::now() - begin).count();
      c.constrained_delaunay = true;
      return true;
    }
    growing = round > 0 && left.size() > previous ? growing + 1 : 0;
    previous = left.size();
    if (growing == kGrowingRoundsInPlace)
      return stop("the faces not locally Delaunay grew " + std::to_string(kGrowingRoundsInPlace) +
                  " rounds in a row, to " + std::to_string(left.size()));
    if (work.steiner.size() > work.edges.size())
      return stop(std::to_string(work.steiner.size()) + " Steiner points for " + std::to_string(work.edges.size()) +
                  " input edges, and " + std::to_string(left.size()) + " face(s) still not locally Delaunay");
    const std::vector<std::uint64_t> blamed = blamed_pieces(left, why);
    if (blamed.empty()) return stop(why);
    touched.assign(work.mesh.point_count(), 0);
    for (const auto& f : left)
      for (const std::uint32_t v : f.face) touched[v] = 1;
    // Each blamed piece split in the tetrahedralization, and in the pieces of its triangles.
    std::vector<std::uint32_t> edge_of;  // the input edge of each blamed piece
    for (std::uint32_t e = 0; e < work.edges.size(); ++e) {
      const auto& chain = work.edges[e].chain;
      for (std::size_t i = 0; i + 1 < chain.size(); ++i)
        if (std::binary_search(blamed.begin(), blamed.end(), MeshIndex::key(chain[i], chain[i + 1])))
          edge_of.push_back(e);
    }
    std::array<std::uint32_t, 2> piece{};
    SteinerInserter inserter(work);
    inserter.set_placement([&](const Vec3& p, std::uint32_t) {
      children.clear();
      return recovery.split_edge_at(piece[0], piece[1], p, &children);
    });
    for (const std::uint32_t e : edge_of) {
      const auto& chain = work.edges[e].chain;
      std::size_t i = 0;
      while (i + 1 < chain.size() && !std::binary_search(blamed.begin(), blamed.end(), MeshIndex::key(chain[i], chain[i + 1])))
        ++i;
      if (i + 1 == chain.size()) continue;  // (a second blamed piece of e, met already)
      piece = {chain[i], chain[i + 1]};
      // Where the point (rounded off the piece) would make a tetrahedron of the piece's shell
      // flat or negative, others along the piece: 1/4, 1/8 and 1/16 of it either way.
      const double t = edge_split_parameter(work, e, i), lo = work.edges[e].t[i], hi = work.edges[e].t[i + 1];
      std::string failure;
      bool placed = false;
      for (int k = 0; k < 7 && !placed; ++k) {
        const double w = k == 0 ? 0.0 : std::ldexp(k % 2 ? 1.0 : -1.0, -(k + 3) / 2);
        const double tk = t + w * (hi - lo);
        if (!(lo < tk && tk < hi)) continue;
        try {
          placed = inserter.insert({{e, tk}}, {}) == 1;
        } catch (const InputError& x) {
          failure = x.what();
        }
      }
      if (!placed) return stop("a split could not be made in place: " + failure);
      // The new tetrahedra take their parents' region (read first: slots are reused).
      std::vector<std::uint8_t> region(children.size());
      for (std::size_t k = 0; k < children.size(); ++k) region[k] = exterior[children[k][1]];
      exterior.resize(recovery.slots(), 0);
      for (std::size_t k = 0; k < children.size(); ++k) exterior[children[k][0]] = region[k];
      const auto p = static_cast<std::uint32_t>(work.mesh.point_count() - 1);
      touched.resize(p + 1, 0);
      touched[p] = 1;
      recovery.protect_edge(piece[0], p);
      recovery.protect_edge(p, piece[1]);
      for (const std::uint32_t f : facets_of[e]) {
        auto& tris = work.facets[f].pieces;
        const std::size_t count = tris.size();
        for (std::size_t k = 0; k < count; ++k)
          for (int r = 0; r < 3; ++r) {
            const std::uint32_t u = tris[k][r], v = tris[k][(r + 1) % 3];
            if (MeshIndex::key(u, v) != MeshIndex::key(piece[0], piece[1])) continue;
            auto second = tris[k];
            tris[k][(r + 1) % 3] = p;  // (u, p, w) and (p, v, w): the triangle's turn kept
            second[r] = p;
            tris.push_back(second);
            recovery.protect_face(tris[k][0], tris[k][1], tris[k][2]);
            recovery.protect_face(second[0], second[1], second[2]);
            break;
          }
        work.facets[f].pieces_vertex_count = facet_vertex_count(work, f);
      }
    }
  }
  return stop("faces not locally Delaunay after " + std::to_string(kFlipRounds) + " rounds of splits");
}

}  // namespace

void constrained3d_cdt(Constrained3dContext& c) {
  std::string why, why_in_place;
  if (flip_with_splits_in_place(c, why_in_place)) return;
  if (recover_then_flip(c, why)) return;
  c.messages.push_back("cdt: recover and flips gave no constrained Delaunay tetrahedralization (in place: " +
                       why_in_place + "; from the Delaunay tetrahedralization: " + why +
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
