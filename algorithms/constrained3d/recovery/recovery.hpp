// The steps of boundary recovery that every constrained3d method shares (book §3.5.3): which
// constraint pieces the mesh holds, where a missing piece is split, where a missing triangle gets
// a Steiner point, and the insertion of those points with their exact records. The methods
// (conforming.cpp, ...) decide in which order to apply them.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <string>
#include <vector>

#include "algorithms/constrained3d/context.hpp"
#include "algorithms/constrained3d/recovery/insert_point.hpp"
#include "kernel/exact_rational.hpp"

namespace dtlab {

class FlipRecovery;

// The edge pieces that flips cannot make: every missing piece is tried, then the
// ones that failed again, up to `passes` more times while flips for the others make some (each
// recovery changes the pipes of the rest). Each with where its last walk stopped
// (FlipRecovery::blocking_face).
struct MissingPiece {
  std::uint32_t edge = 0, index = 0;  // piece `index` of the edge's chain
  std::array<std::uint32_t, 3> block{};
};
// `present`, where given: per input edge, 1 if it was found an edge of the mesh since it was
// protected (an edge never split, one piece); those are not searched again.
std::vector<MissingPiece> edge_pieces_flips_cannot_make(const Constrained3dContext& c, FlipRecovery& recovery, int passes,
                                                        const std::vector<std::uint8_t>* present = nullptr);

// Edge queries on the mesh (ghost tetrahedra included, kInfinite a vertex like any): one
// tetrahedron per vertex, and each query searches the star of its first vertex. Building it is
// a pass over the records, so that it can be rebuilt after every round of insertions; each
// query costs the size of a star. Not for concurrent use (the search marks are shared).
class MeshIndex {
 public:
  explicit MeshIndex(const Tetrahedralization3& mesh);
  bool has_edge(std::uint32_t u, std::uint32_t v) const;
  bool has_face(std::uint32_t u, std::uint32_t v, std::uint32_t w) const;
  // Every w such that (u, v, w) is a mesh face, each once; empty if (u, v) is no edge.
  void ring(std::uint32_t u, std::uint32_t v, std::vector<std::uint32_t>& out) const;
  static std::uint64_t key(std::uint32_t u, std::uint32_t v) noexcept {
    return u < v ? std::uint64_t{u} << 32 | v : std::uint64_t{v} << 32 | u;
  }

 private:
  // Calls f(t) for every tetrahedron holding u (finite u) until f returns true.
  template <class F>
  void for_each_in_star(std::uint32_t u, F&& f) const;

  const Tetrahedralization3& mesh_;
  std::vector<std::uint32_t> incident_;  // by vertex id; kNone for a vertex in no tetrahedron
  mutable std::vector<std::uint32_t> mark_, stack_;
  mutable std::uint32_t stamp_ = 0;
};

// Method recover (recover.cpp); `delaunay`, where given, is c.mesh as it is now, with no
// Steiner point in c yet: what recover goes back to if its in-place recovery gives up, instead
// of a copy of its own.
void constrained3d_recover(Constrained3dContext& c);
void constrained3d_recover(Constrained3dContext& c, const Tetrahedralization3* delaunay);
// Back to the input's state: `delaunay` (the tetrahedralization of the input's points) as the
// mesh, no Steiner point, every chain its edge's two ends, no triangle pieces.
void reset_to_delaunay(Constrained3dContext& c, Tetrahedralization3 delaunay);

// MeshIndex::key of every edge piece of every chain, sorted: the protected edges of a
// FlipRecovery (flip_recovery.hpp).
std::vector<std::uint64_t> edge_piece_keys(const Constrained3dContext& c);
// Every recovered triangle piece's sorted vertex triple, sorted (the protected faces).
std::vector<std::array<std::uint32_t, 3>> facet_piece_keys(const Constrained3dContext& c);

// A request for a Steiner point: on input edge `edge` at parameter t, or inside input triangle
// `facet` at (s, t).
struct EdgeSplit {
  std::uint32_t edge = 0;
  double t = 0;
};
struct FacetPoint {
  std::uint32_t facet = 0;
  double s = 0, t = 0;
  // Taken instead when (s, t) rounds onto an existing vertex (a circumcentre can be one); when
  // that does too, the missing piece is split if it is a boundary piece.
  double fallback_s = 0, fallback_t = 0;
  std::array<std::uint32_t, 2> piece{};
};

// The split parameter of piece [chain[i], chain[i + 1]] of edge e: on concentric shells
// (distance a power of two from the input vertex) when the piece has exactly one input vertex,
// which keeps two pieces at a shared input vertex from encroaching on each other (Ruppert
// 1995, Shewchuk 2000); else the midpoint of the parameters. Throws InputError naming the
// edge when the piece has no double parameter strictly inside it.
double edge_split_parameter(const Constrained3dContext& c, std::uint32_t e, std::size_t i);

// Each vertex of facet f with its exact (s, t).
using FacetParameters = std::unordered_map<std::uint32_t, std::array<Rational, 2>>;
FacetParameters facet_parameters(const Constrained3dContext& c, std::uint32_t f);

// The boundary pieces of facet f in order (edge 0's chain from A to B, then edge 1, edge 2),
// directed so that the triangle lies to their left in (s, t).
std::vector<std::array<std::uint32_t, 2>> facet_boundary(const Constrained3dContext& c, std::uint32_t f);

// Whether the mesh faces on the vertices of facet f triangulate it: a breadth-first search from
// its boundary pieces that takes, across each open piece, the mesh face on its left whose
// third vertex is a vertex of f (the one whose (s, t) circle holds no other candidate if
// several), then checks exactly that the pieces' (s, t) areas add up to the triangle's.
// Fills c.facets[f].pieces when they do; else lists the directed pieces with no face.
// The number of vertices on facet f (corners, edge Steiner points, interior ones).
std::size_t facet_vertex_count(const Constrained3dContext& c, std::uint32_t f);

// Whether the pieces found for facet f before still triangulate it: no vertex came onto it
// since, and each piece is still a mesh face (then their (s, t) cover is unchanged). Saves
// cover_facet's exact arithmetic on the triangles a round did not touch.
bool facet_still_covered(const Constrained3dContext& c, std::uint32_t f, const MeshIndex& index);

bool cover_facet(Constrained3dContext& c, std::uint32_t f, const MeshIndex& index,
                 std::vector<std::array<std::uint32_t, 2>>& missing);

// The Delaunay triangulation of facet f's vertices in its own plane (metric of the input
// triangle, exact in its (s, t) parameters; cocircular ties broken by a symbolic perturbation
// of the lifting, smallest vertex id first): the pieces, each turned like the triangle, that a
// constrained Delaunay tetrahedralization holds on f once its boundary pieces are Delaunay
// (Shewchuk 2002). Gift-wrapped in (s, t) from the boundary pieces; checked to cover the
// triangle exactly (InternalError otherwise).
std::vector<std::array<std::uint32_t, 3>> facet_delaunay_pieces(const Constrained3dContext& c, std::uint32_t f);
// The same with f's parameters already made (facet_parameters(c, f)).
std::vector<std::array<std::uint32_t, 3>> facet_delaunay_pieces(const Constrained3dContext& c, std::uint32_t f,
                                                                const FacetParameters& st);

// Where facet f gets a point for its missing piece (u, v) (f on its left in (s, t)): the
// circumcentre of (u, v, w), w the Delaunay apex of (u, v) among the vertices of f on its left
// (the one whose circumcentre lies furthest back across (u, v), measured in the triangle's
// plane in doubles: a placement, not a decision), as a point of the triangle; unless it lies
// in the closed diametral ball of boundary pieces of f, which are split instead (Ruppert's
// rule), or outside the triangle (then the centroid of (u, v, w), which is also the fallback).
// Appends to `splits` or `points`.
void request_facet_point(const Constrained3dContext& c, std::uint32_t f, const FacetParameters& st,
                         std::array<std::uint32_t, 2> missing, std::vector<EdgeSplit>& splits,
                         std::vector<FacetPoint>& points);

// For every input triangle whose pieces the mesh (index) does not hold: its Steiner point
// requests, one per missing piece (request_facet_point). Fills the triangles' pieces where held.
void request_missing_facet_points(Constrained3dContext& c, const MeshIndex& index, std::vector<EdgeSplit>& splits,
                                  std::vector<FacetPoint>& points);

// Inserts requested points: each computed exactly, rounded to nearest, recorded in c.steiner,
// added to its edge's chain (kept sorted) or its facet's interior, and inserted into c.mesh.
// An edge split that repeats a parameter already there is dropped; a facet point that rounds
// onto a vertex falls back as FacetPoint says, and is skipped (stuck_facet()) when every
// placement is taken. Throws InputError naming the edge or triangle when an edge split rounds
// onto a vertex or the Steiner limit is reached.
// Returns the number inserted.
class SteinerInserter {
 public:
  explicit SteinerInserter(Constrained3dContext& c);
  // Where the points go instead of Delaunay insertion (a tetrahedralization no longer Delaunay):
  // place(p, a vertex near p) returns p's new vertex id, or kNone where it cannot place p (then
  // insert throws InputError naming the item).
  using Placement = std::function<std::uint32_t(const Vec3&, std::uint32_t)>;
  void set_placement(Placement place) { place_ = std::move(place); }
  std::size_t insert(const std::vector<EdgeSplit>& splits, const std::vector<FacetPoint>& points);
  std::uint32_t rounding_checks_failed() const noexcept { return rounding_failed_; }
  // The last triangle whose request could not be placed at all (kNone if none).
  std::uint32_t stuck_facet() const noexcept { return stuck_facet_; }
  // The InputError for a round that placed nothing: naming stuck_facet().
  [[noreturn]] void throw_stuck() const;

 private:
  std::uint32_t add_vertex(const Vec3& p, const std::string& what, std::uint32_t item, std::uint32_t hint);
  bool is_vertex(const Vec3& p) const;
  bool insert_split(const EdgeSplit& r);
  // by_coordinates_ of the mesh's points, built at the first request (most inserters of a surface
  // that needs no Steiner point are never asked: the map cost a tenth of cdt's time there).
  void index_points() const;
  Constrained3dContext& c_;
  DelaunayInserter inserter_;
  Placement place_;
  mutable std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> by_coordinates_;
  mutable bool indexed_ = false;
  std::uint32_t rounding_failed_ = 0;
  std::uint32_t stuck_facet_ = Tetrahedralization3::kNone;
};
}  // namespace dtlab
