// Recovery of missing constraint edges and triangles by local transformations, without Steiner
// points (book §3.5.3, "edge recovery" and "face recovery"; the shell transformation of §8.3.3):
// 2->3 flips and edge removals (n -> 2n - 4: the shell of an edge retriangulated, 3 -> 2 its
// smallest case) on a tetrahedralization that is no longer Delaunay afterwards.
//
//  - Edge uv: walked from u (then from v) through its pipe (§1.7). The first tetrahedron, at u,
//    is left through a face or an edge: a face is flipped 2->3 when u and the apex beyond it see
//    each other through it; an edge is removed with its shell's polygon fanned from u. Either
//    way the pipe loses a tetrahedron at u, so the walk ends: with uv an edge, or at a
//    transformation that is not valid (a reflex pipe, as in Schönhardt's polyhedron). Where
//    allowed (allow_link_removals), an edge whose shell has no valid retriangulation first loses
//    an edge of its link (a second level of flips, as in TetGen's flipnm; Si 2015).
//  - Triangle abc (its edges present): the edges crossing its open interior are removed one at
//    a time, each by a retriangulation of its shell whose new edges cross it nowhere; a removal
//    destroys only faces through the edge it removes, so triangles recovered before stay. With
//    no edge crossing it (and its edges present), abc is a face.
// Every new tetrahedron is checked positive with exact orient3d (no perturbation: flat ones are
// refused). Protected edges and faces (the constraints already present) are never removed.
// Each call is bounded; giving up is an answer (the caller then inserts Steiner points).
#pragma once

#include <array>
#include <cstdint>
#include <set>
#include <span>
#include <string>
#include <unordered_set>
#include <vector>

#include "algorithms/delaunay3d/flip_mesh.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

class FlipRecovery {
 public:
  // mesh: compact, as tetrahedralization3.hpp requires; it is transformed in place and is only a
  // valid Tetrahedralization3 again after finish(). protected_edges: MeshIndex::key(u, v) of
  // the constraint edges (sorted); protected_faces: the constraint triangles' sorted vertex
  // triples (sorted).
  FlipRecovery(Tetrahedralization3& mesh, std::vector<std::uint64_t> protected_edges,
               std::vector<std::array<std::uint32_t, 3>> protected_faces);

  bool has_edge(std::uint32_t u, std::uint32_t v);
  bool has_face(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  // Makes uv an edge if the walks above can; true if it is one afterwards.
  bool recover_edge(std::uint32_t u, std::uint32_t v);
  // After recover_edge(u, v) failed: the face of the mesh where the walk from u (or else from v)
  // stopped, which the segment crosses or touches (kNone if it found none).
  std::array<std::uint32_t, 3> blocking_face() const noexcept { return block_; }
  // A mesh edge ab in a plane with uv that uv, leaving u, crosses at an interior point (the edge
  // opposite u of a face (u, a, b) in that plane: flip_recovery_coplanar.cpp); {kNone, kNone}
  // if there is none (uv leaves u through the open interior of tetrahedra, or through a vertex).
  // On a flat part of the hull no flip removes such an edge, and crossing_edge (edges through a
  // triangle's plane) does not see it.
  std::array<std::uint32_t, 2> coplanar_edge_crossing(std::uint32_t u, std::uint32_t v);
  // An edge crossing the open triangle abc ({kNone, kNone} if none).
  std::array<std::uint32_t, 2> crossing_edge(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  // Makes abc a face if removing the edges that cross it can; true if it is one afterwards.
  bool recover_face(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  // Makes the triangles `pieces` (a triangulated facet: its boundary edges present, its
  // diagonals inside) faces by retriangulating their cavity, the tetrahedra that the facet
  // crosses (flip_recovery_facet.cpp): removed, then refilled by gift-wrapping on both sides of
  // the pieces (gift_wrapping.hpp). Constrained Delaunay when the tetrahedralization was, and
  // the facet's boundary edges are (Shewchuk 2002); false with `why` (nothing changed) when the
  // cavity reaches the hull or a protected edge, or has no such filling. Protects the pieces.
  bool insert_facet(std::span<const std::array<std::uint32_t, 3>> pieces, std::string& why);
  // Inserts p as a new vertex (appended to the points) by splitting what holds it, without
  // flips: a tetrahedron 1 -> 4, a face 2 -> 6, an edge n -> 2n, located by a search from the
  // ball of vertex `near`. Returns its id, or kNone (nothing changed) where p is outside the hull,
  // on a ghost, equal to a vertex, or inside a protected face or edge.
  std::uint32_t insert_point(const Vec3& p, std::uint32_t near);
  // Inserts p, placed where segment uv crosses face abc (where uv's walk stopped:
  // blocking_face), by splitting the face's two finite tetrahedra 2 -> 6: the face is gone. Rounded,
  // p lies a hair to one side of abc, and insert_point's 1 -> 4 split of the tetrahedron holding
  // it would keep abc beside p as a flat tetrahedron, which uv's remaining piece crosses at p
  // itself, past any flip: Chazelle's polyhedron (n = 8) split such a piece towards p until
  // doubles ran out. Returns p's id, or kNone (nothing changed) where uv does not cross abc's
  // open interior, abc is protected or on the hull, or a new tetrahedron would not be positive.
  // (Not the same for a crossed edge: splitting it puts the points of many edges crossing one
  // line on that line, and the triangles later needed between them are flat.)
  std::uint32_t split_crossed_face(std::uint32_t u, std::uint32_t v, const std::array<std::uint32_t, 3>& abc,
                                   const Vec3& p);
  // Splits edge ab at p (appended to the points), a protected one included: every tetrahedron of
  // its shell in two (method cdt splits a constraint piece of its constrained tetrahedralization
  // so). Returns p's id, or kNone (nothing changed) where ab is no edge or a tetrahedron made
  // would not be positive (p off ab by more than rounding). The protections are the caller's to
  // renew: ab's stay. `children`, if given, gets (new tetrahedron, the one of the shell it came
  // from) pairs, slot ids.
  std::uint32_t split_edge_at(std::uint32_t a, std::uint32_t b, const Vec3& p,
                              std::vector<std::array<std::uint32_t, 2>>* children = nullptr);
  // Lets edge recovery remove link edges first where an edge's shell has no retriangulation
  // (remove_edge_after_link below): far fewer Steiner points (fandisk 64 -> 34, twisted prisms 1
  // each), at the cost of changing the mesh where it still fails.
  void allow_link_removals(bool allow) noexcept { deep_ = allow; }
  // From now on every vertex of a tetrahedron the transformations make gets marks[v] = 1 (the
  // vector grows as needed): elsewhere the mesh is as given (method cdt's flips start there).
  void record_changes(std::vector<std::uint8_t>* marks) noexcept { marks_ = marks; }
  // Adds a constraint to the protected ones (after recovering it).
  void protect_edge(std::uint32_t u, std::uint32_t v);
  void protect_face(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  // Takes back a protection that protect_edge or protect_face added (one of the constructor's
  // lists stays protected): a triangulation of a facet that is being made again.
  void unprotect_edge(std::uint32_t u, std::uint32_t v);
  bool is_protected_edge(std::uint32_t u, std::uint32_t v) const;
  void unprotect_face(std::uint32_t a, std::uint32_t b, std::uint32_t c);

  // Lawson's flips with constraints (flip_recovery_lawson.cpp): every face between two finite
  // tetrahedra that is no protected face and not locally Delaunay (perturbed insphere, as
  // checks3d.hpp decides it) is flipped 2->3, 3->2 or 4->4 where the flip is valid and removes
  // no protected edge or face, until none is left or none of those left can be flipped.
  // Returns the faces left: none means every unprotected face is locally Delaunay, so the
  // tetrahedralization is constrained Delaunay (the constrained Delaunay lemma, Shewchuk 2008).
  // Each flip lowers the lifted tetrahedralization, so the pass ends; `max_flips` backs that up
  // (the faces still queued are then among those left).
  struct NotLocallyDelaunay {
    std::array<std::uint32_t, 3> face;           // sorted vertex ids
    // The protected edge its flip would remove (direct), else the longest protected edge of its
    // two tetrahedra; kNone if they have none.
    std::array<std::uint32_t, 2> blocking_edge;
    bool direct;
  };
  // skip[t] = 1 leaves tetrahedron t's faces alone (t a record index of the mesh as given): the
  // regions that do not matter, bounded by protected faces, or tetrahedra whose faces are known
  // to be locally Delaunay (a face between a skipped and a tested one is tested).
  std::vector<NotLocallyDelaunay> make_constrained_delaunay(std::uint64_t max_flips, std::vector<std::uint8_t> skip = {});
  // After make_constrained_delaunay: its skip, by slot, with 0 for every tetrahedron its flips
  // made (slots() entries; valid until the next call or change).
  const std::vector<std::uint8_t>& lawson_skip() const noexcept { return lawson_skip_; }
  // Slots in use (every tetrahedron id is below it) and whether one is free, before finish().
  std::size_t slots() const noexcept { return flips_mesh_.slots(); }
  bool is_dead(std::uint32_t t) const noexcept { return flips_mesh_.is_dead(t); }
  const Tetrahedralization3::Record& record(std::uint32_t t) const noexcept { return records_[t]; }

  void finish();
  std::uint64_t flips() const noexcept { return flips_; }
  std::uint64_t edge_removals() const noexcept { return removals_; }

 private:
  using Tuple = FlipMesh::Tuple;
  const Vec3& P(std::uint32_t v) const noexcept { return mesh_.points()[v]; }
  bool alive(std::uint32_t t) const noexcept { return records_[t].vertex[0] != Tetrahedralization3::kNone; }
  // A finite tetrahedron holding u and v (kNone if none): a search of u's ball.
  std::uint32_t tetrahedron_with(std::uint32_t u, std::uint32_t v, std::uint32_t w = Tetrahedralization3::kNone);
  void ball_of(std::uint32_t u, std::vector<std::uint32_t>& out);
  // nav3::search_ball from vertex_tet_[u] (which must be set), with this recovery's marks.
  template <class Visit>
  std::uint32_t search_ball_of(std::uint32_t u, std::vector<std::uint32_t>& list, Visit&& visit);
  // A tetrahedron insert_point or split_edge_at makes is valid: positive, or a ghost whose hull
  // facet is a proper triangle (a point on the hull's surface leaves the hull as it was).
  bool proper(const FlipMesh::Tuple& t) const;
  bool is_protected_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) const;
  // One step of the walk of uv from u: true if the mesh changed.
  bool advance(std::uint32_t u, std::uint32_t v);
  bool flip23(std::uint32_t t, std::uint32_t u_index);
  // Removes edge (e0, e1) of finite tetrahedron t by the first valid retriangulation of its
  // shell's polygon that `accept` takes (ring vertices, triangles); false if none.
  template <class Accept>
  bool remove_edge(std::uint32_t t, std::uint32_t e0, std::uint32_t e1, Accept&& accept);
  // Where remove_edge(t, e0, e1, accept) found no retriangulation: a link edge (e0 or e1 to a
  // vertex of the shell) removed by any valid retriangulation of its own shell, then e0e1 tried
  // again (a second level of flips, as TetGen's flipnm), for each link edge until one is removed.
  // True if the mesh changed (t may be gone then); a link removal stays even where e0e1 does not
  // go, and each costs one of link_budget_, which recover_edge sets.
  template <class Accept>
  bool remove_edge_after_link(std::uint32_t t, std::uint32_t e0, std::uint32_t e1, Accept&& accept);
  void replaced(std::span<const std::uint32_t> ids);
  // The 3->2 (shell_size 3) or 4->4 (shell_size 4: p, d, e0, e1 coplanar) flip about edge
  // (e0, e1) of t that removes the face between apexes p and d (edge pd comes in); false where
  // the shell has another size, a protection forbids it or a new tetrahedron would not be
  // positive.
  bool flip_about_edge(std::uint32_t t, std::uint32_t e0, std::uint32_t e1, std::uint32_t p, std::uint32_t d,
                       std::size_t shell_size);
  // Lawson's step on face h (4 t + i) of a live tetrahedron: true if it flipped (the new
  // tetrahedra in ids_), false with `blocked` set when the face is not locally Delaunay and
  // cannot be flipped (blocking_edge and direct_blame then as NotLocallyDelaunay says).
  bool lawson_step(std::uint32_t h, bool& blocked, std::array<std::uint32_t, 2>& blocking_edge, bool& direct_blame);
  // Edges crossing the open triangle abc, each once with a tetrahedron holding it.
  void crossing_edges(std::uint32_t a, std::uint32_t b, std::uint32_t c,
                      std::vector<std::array<std::uint32_t, 3>>& out);
  // Whether mesh edge pq must go for the facet with these pieces to be faces (insert_facet).
  bool conflicts_with_facet(std::uint32_t p, std::uint32_t q, std::span<const std::array<std::uint32_t, 3>> pieces,
                            const std::set<std::uint64_t>& facet_edges, const std::set<std::uint64_t>& diagonals,
                            const std::set<std::uint32_t>& facet_vertices) const;
  bool crosses(std::uint32_t p, std::uint32_t q, std::uint32_t a, std::uint32_t b, std::uint32_t c) const;

  Tetrahedralization3& mesh_;
  std::vector<Tetrahedralization3::Record>& records_;
  FlipMesh flips_mesh_;
  std::vector<std::uint32_t> vertex_tet_;
  std::vector<std::uint64_t> protected_edges_;
  std::vector<std::array<std::uint32_t, 3>> protected_faces_;
  bool deep_ = false;
  int link_budget_ = 0;
  std::vector<std::uint8_t> lawson_skip_;  // make_constrained_delaunay's skip, by slot
  std::vector<std::uint8_t>* marks_ = nullptr;  // record_changes
  std::unordered_set<std::uint64_t> extra_edges_;
  std::set<std::array<std::uint32_t, 3>> extra_faces_;
  std::vector<std::uint32_t> mark_;
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> ids_, stack_, ball_, walk_;
  std::uint64_t flips_ = 0, removals_ = 0;
  std::array<std::uint32_t, 3> block_{Tetrahedralization3::kNone, Tetrahedralization3::kNone, Tetrahedralization3::kNone};
};

}  // namespace dtlab
