// The mutable 3D simplicial mesh that generation, optimization and adaptation share (book §10;
// MMG keeps one such structure for all its operators), the 3D counterpart of mesh/mesh2.hpp:
// flat arrays with free lists, a metric per vertex, a reference (region) per tetrahedron, and
// constrained facets carrying the reference of the boundary (or internal) face they belong to.
//
// Numbering is the one drawn in mesh/tetrahedralization3.hpp: tetrahedron t has vertices
// vertices[4t + 0..3], positive (orient3d(v0, v1, v2, v3) > 0); facet handle h = 4t + i lies
// opposite vertex i, its vertices in Tetrahedralization3::kFacetVertex[i] order; twin(h) is the
// same facet in the adjacent tetrahedron. The convex hull is closed by ghost tetrahedra with
// kInfinite as vertex 0, so every facet of a live tetrahedron has a twin.
//
// Tetrahedra outside the domain (between the surface and the hull, in holes and cavities) stay
// with the reference kExterior until the end, as the book keeps the exterior of the empty mesh
// (§7.2). The domain's boundary is made of constrained facets, so an operator that never crosses
// a constrained facet never touches the exterior. Constrained edges (the input surface's edges,
// specified internal edges) are marked per vertex pair, so that a shell transformation or a
// collapse can ask whether it may remove an edge.
//
// Free lists: a removed tetrahedron or vertex keeps its slot, marked dead, and the next new one
// reuses it. Operators keep the invariant that every live tetrahedron is linked on all four
// facets; check() verifies it (and orientation, exactly) for tests.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <unordered_map>
#include <vector>

#include "kernel/metric.hpp"
#include "kernel/vec.hpp"
#include "mesh/io/mesh_data3.hpp"
#include "mesh/mesh_vertices.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

// A constrained triangle of the input to Mesh3: vertex ids and the reference of its face.
struct MeshTriangle3 {
  std::uint32_t a = 0, b = 0, c = 0;
  int ref = 0;
};

class Mesh3 : public MeshVertices<Vec3, Metric3> {
 public:
  static constexpr std::uint32_t kNone = Tetrahedralization3::kNone;
  static constexpr std::uint32_t kInfinite = Tetrahedralization3::kInfinite;
  static constexpr auto kFacetVertex = Tetrahedralization3::kFacetVertex;
  // The reference of a tetrahedron outside the domain (exterior, holes, ghosts).
  static constexpr int kExterior = std::numeric_limits<int>::min();

  // Vertex flags kFixed, kOnBoundary, kDead: mesh/mesh_vertices.hpp.

  Mesh3() = default;
  // From a closed tetrahedralization (ghosts included): `tetrahedron_refs` one per stored
  // tetrahedron of `tet` (kExterior for ghosts and for tetrahedra outside the domain);
  // `constrained` the triangles that carry a constraint (each must be a facet of `tet`, else
  // InputError naming it); their edges become constrained edges. Every vertex gets `metric` and
  // the flag kFixed, vertices on a constrained triangle also kOnBoundary.
  Mesh3(const Tetrahedralization3& tet, std::span<const int> tetrahedron_refs, std::span<const MeshTriangle3> constrained,
        const Metric3& metric = {});

  // --- Navigation (as Tetrahedralization3) -----------------------------------------------------
  static constexpr std::uint32_t tetrahedron_of(std::uint32_t h) noexcept { return h >> 2; }
  static constexpr std::uint32_t index_in_tetrahedron(std::uint32_t h) noexcept { return h & 3u; }
  static constexpr std::uint32_t facet(std::uint32_t t, std::uint32_t i) noexcept { return 4 * t + i; }

  // --- Vertices (slots, points, metrics, flags, remove_vertex: mesh/mesh_vertices.hpp) ----------
  // Moving a vertex is the caller's responsibility for validity (check orientation first).
  void set_point(std::uint32_t v, const Vec3& p) noexcept {
    points_[v] = p;
    touch(v);
  }
  void set_metric(std::uint32_t v, const Metric3& m) noexcept {
    replace_metric(v, m);
    touch(v);
  }
  // Whether every vertex slot's metric is scalar (lambda I): Q_K is then the Euclidean one, and
  // the optimizer's quality tests need not read the metrics.
  bool metrics_all_scalar() const noexcept { return anisotropic_slots_ == 0; }
  // One live tetrahedron incident to v (kNone for a dead vertex). Operators keep it current.
  std::uint32_t vertex_tetrahedron(std::uint32_t v) const noexcept { return vertex_element_[v]; }
  void set_vertex_tetrahedron(std::uint32_t v, std::uint32_t t) noexcept { vertex_element_[v] = t; }
  // A new vertex (reusing a dead slot if any); no tetrahedron yet.
  std::uint32_t add_vertex(const Vec3& p, const Metric3& m, std::uint8_t flags = 0);

  // --- Tetrahedra --------------------------------------------------------------------------------
  std::uint32_t tetrahedron_capacity() const noexcept { return static_cast<std::uint32_t>(vertices_.size() / 4); }
  std::uint32_t live_tetrahedron_count() const noexcept {
    return tetrahedron_capacity() - static_cast<std::uint32_t>(free_tetrahedra_.size());
  }
  bool is_alive(std::uint32_t t) const noexcept { return vertices_[4 * t] != kNone; }
  bool is_ghost(std::uint32_t t) const noexcept { return vertices_[4 * t] == kInfinite; }
  // Alive, finite and inside the domain.
  bool in_domain(std::uint32_t t) const noexcept { return is_alive(t) && !is_ghost(t) && refs_[t] != kExterior; }
  std::uint32_t vertex(std::uint32_t t, std::uint32_t i) const noexcept { return vertices_[4 * t + i]; }
  std::array<std::uint32_t, 4> tetrahedron(std::uint32_t t) const noexcept {
    return {vertices_[4 * t], vertices_[4 * t + 1], vertices_[4 * t + 2], vertices_[4 * t + 3]};
  }
  std::uint32_t apex(std::uint32_t h) const noexcept { return vertices_[h]; }  // the vertex opposite h
  // The three vertices of facet h, in kFacetVertex order.
  std::array<std::uint32_t, 3> facet_vertices(std::uint32_t h) const noexcept {
    const std::uint32_t t = tetrahedron_of(h);
    const auto& f = kFacetVertex[index_in_tetrahedron(h)];
    return {vertices_[4 * t + f[0]], vertices_[4 * t + f[1]], vertices_[4 * t + f[2]]};
  }
  std::uint32_t twin(std::uint32_t h) const noexcept { return neighbours_[h]; }
  std::uint32_t adjacent(std::uint32_t t, std::uint32_t i) const noexcept { return tetrahedron_of(neighbours_[4 * t + i]); }
  int ref(std::uint32_t t) const noexcept { return refs_[t]; }
  void set_ref(std::uint32_t t, int r) noexcept { refs_[t] = r; }

  // A new tetrahedron (a, b, c, d), positive, with reference r (reusing a dead slot if any), no
  // neighbours (kNone) and no constrained facets yet; kInfinite may only be `a`. Updates
  // vertex_tetrahedron of its finite vertices.
  std::uint32_t add_tetrahedron(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, int r);
  // Marks t dead and frees its slot (its neighbours' links to it are the caller's to redo).
  void remove_tetrahedron(std::uint32_t t);
  // The two halves of add_tetrahedron and remove_tetrahedron, for an inserter that takes and gives
  // back slots on one thread and fills and kills them on several, each in its own part of the mesh
  // (algorithms/mesh3d/field_point_regions.hpp). A slot taken (the free list's last, else a new
  // one: the arrays may grow) is the caller's until filled; a slot given back must be dead, or
  // killed before the free list is next used.
  std::uint32_t take_tetrahedron_slot();
  // k slots at once (the free list's last first, then new ones, the arrays grown once), appended to out.
  void take_tetrahedron_slots(std::size_t k, std::vector<std::uint32_t>& out);
  // The same for vertex slots: a dead slot (the free list's last, else a new one) whose metric is
  // reset to the identity; fill_vertex makes it a vertex without the bookkeeping that another
  // thread could race on, settle_vertex (on one thread) does that bookkeeping afterwards; a slot
  // not filled is given back dead.
  std::uint32_t take_vertex_slot();
  void fill_vertex(std::uint32_t v, const Vec3& p, const Metric3& m, std::uint8_t flags = 0) noexcept {
    points_[v] = p;
    metrics_[v] = m;
    vertex_flags_[v] = flags;
    vertex_element_[v] = kNone;
    changed_at_[v] = epoch_;
  }
  void settle_vertex(std::uint32_t v) noexcept { anisotropic_slots_ += static_cast<std::uint64_t>(!metrics_[v].is_scalar()); }
  void give_back_vertex_slot(std::uint32_t v) { free_vertices_.push_back(v); }
  void give_back_tetrahedron_slot(std::uint32_t t) { free_tetrahedra_.push_back(t); }
  // add_tetrahedron into slot t (taken, or dead and about to be reused by the same caller).
  void fill_tetrahedron(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, int r);
  // remove_tetrahedron without giving the slot back.
  void kill_tetrahedron(std::uint32_t t);
  // Makes facets g and h twins.
  void link(std::uint32_t g, std::uint32_t h) noexcept {
    neighbours_[g] = h;
    neighbours_[h] = g;
  }

  // --- Constraints -------------------------------------------------------------------------------
  // Constrained facets: set on each side (operators that rebuild tetrahedra call set_facet on
  // each new facet; set_facet_both on h and its twin).
  bool is_constrained(std::uint32_t h) const noexcept { return facet_refs_[h] != kUnconstrained; }
  int facet_ref(std::uint32_t h) const noexcept { return facet_refs_[h]; }
  void set_facet(std::uint32_t h, bool constrained, int r = 0) noexcept { facet_refs_[h] = constrained ? r : kUnconstrained; }
  void set_facet_both(std::uint32_t h, bool constrained, int r = 0) noexcept {
    set_facet(h, constrained, r);
    set_facet(neighbours_[h], constrained, r);
  }
  // Constrained edges, by unordered vertex pair (a surface edge, a specified internal edge):
  // an operator may not remove one; splitting one replaces it by its two halves.
  bool is_constrained_edge(std::uint32_t a, std::uint32_t b) const;
  void set_constrained_edge(std::uint32_t a, std::uint32_t b, bool constrained);
  std::size_t constrained_edge_count() const noexcept { return constrained_edges_.size(); }
  // Forgets every constrained facet and edge (for a copy that only locates points: the control
  // space's background, algorithms/mesh3d/control_space.hpp).
  void clear_constraints();
  // Constrains facet h on both sides with c.ref, and c's edges (ab, bc, ca) and vertices; c names
  // h's three vertices.
  void constrain_triangle(std::uint32_t h, const MeshTriangle3& c);

  // --- Queries -----------------------------------------------------------------------------------
  // The live tetrahedra around v (ghosts included), by a search across facets from
  // vertex_tetrahedron(v), in a deterministic order. Throws InternalError past a bound.
  void ball(std::uint32_t v, std::vector<std::uint32_t>& out) const;
  // The tetrahedra around edge (a, b) in cyclic order (its shell, §8.3.2), ghosts included;
  // returns false when a and b share no edge. `ring` (optional) receives the vertices of the
  // shell's ring in the same order: ring[k] and ring[k+1] with a, b span shell[k], cyclically
  // (ring has out.size() entries; ring[n-1] and ring[0] span shell[n-1]), and (a, b, ring[k],
  // ring[k+1]) is positive: the ring turns counter-clockwise seen from b towards a.
  bool shell(std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t>& out, std::vector<std::uint32_t>* ring = nullptr) const;
  // The same, starting from t, a live tetrahedron that has edge (a, b) (no search for one):
  // shell[0] is t.
  void shell_at(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t>& out,
                std::vector<std::uint32_t>* ring = nullptr) const;
  // A live tetrahedron having edge (a, b), or kNone.
  std::uint32_t find_edge(std::uint32_t a, std::uint32_t b) const;
  // The facet handle of triangle (a, b, c) (any order) in a live tetrahedron, or kNone.
  std::uint32_t find_facet(std::uint32_t a, std::uint32_t b, std::uint32_t c) const;

  // Where p lies, found by a visibility walk from `start` (a live tetrahedron) that does not
  // cross constrained facets when `stop_at_constraints` (it then ends in the last tetrahedron
  // reached, `blocked` set). Exact orient3d throughout; the walk is bounded (InternalError).
  enum class Where : std::uint8_t { Inside, Facet, Edge, Vertex, Outside };
  struct Location {
    Where where = Where::Inside;
    std::uint32_t tetrahedron = kNone;  // the tetrahedron holding p
    std::uint32_t handle = kNone;       // Facet: the facet handle; Vertex: the vertex
    bool blocked = false;
    std::uint32_t edge_a = kNone, edge_b = kNone;  // Edge: the edge's two vertices
  };
  // A part of the mesh that a walk must not leave: the tetrahedra whose four vertices all have
  // region `id` in `vertex_region` (an entry per vertex slot). With one, locate ends `blocked` in
  // the last tetrahedron of the part it reached when the next is outside it (or at once when
  // `start` is).
  struct Region {
    const std::uint16_t* vertex_region = nullptr;
    std::uint16_t id = 0;
  };
  bool in_region(std::uint32_t t, const Region& r) const noexcept {
    const std::uint32_t* v = &vertices_[4 * t];
    return v[0] != kInfinite && v[0] != kNone && r.vertex_region[v[0]] == r.id && r.vertex_region[v[1]] == r.id &&
           r.vertex_region[v[2]] == r.id && r.vertex_region[v[3]] == r.id;
  }
  Location locate(const Vec3& p, std::uint32_t start, bool stop_at_constraints = false,
                  const Region* region = nullptr) const;

  // --- Change epochs --------------------------------------------------------------------------
  // For memos of failed attempts (an operator that failed on a piece of mesh fails again while
  // the piece is unchanged; algorithms/optimize3d): every vertex carries the epoch of the last
  // change around it: a tetrahedron holding it added or removed, its position or metric set
  // (set_point, set_metric). A caller moving v also touches the vertices of v's ball, whose
  // tetrahedra changed shape. new_epoch() opens an epoch e; v has not changed since e was opened
  // while changed_at(v) < e.
  std::uint64_t new_epoch() noexcept { return ++epoch_; }
  std::uint64_t epoch() const noexcept { return epoch_; }
  std::uint64_t changed_at(std::uint32_t v) const noexcept { return changed_at_[v]; }
  void touch(std::uint32_t v) noexcept { changed_at_[v] = epoch_; }

  // --- Renumbering -----------------------------------------------------------------------------
  // Renumbers the vertices and the tetrahedra, dropping the free slots: `vertex_order` lists every
  // live vertex once (the new id of vertex_order[k] is k), `tetrahedron_order` every live
  // tetrahedron once, ghosts included (the new slot of tetrahedron_order[k] is k). Everything
  // moves with them: coordinates, metrics, flags, references, constrained facets and edges,
  // links, change epochs. For locality (the operators that follow touch neighbours: neighbours
  // in memory then): InputError when a list is not such a permutation.
  void renumber(std::span<const std::uint32_t> vertex_order, std::span<const std::uint32_t> tetrahedron_order);

  // --- Whole-mesh --------------------------------------------------------------------------------
  // Throws InternalError naming the first problem: links symmetric over the same three vertices
  // in opposite cyclic order, no live tetrahedron on a dead vertex, vertex_tetrahedron current,
  // facet constraints equal on both sides, every finite live tetrahedron positive (exact
  // orient3d), the free lists consistent.
  void check() const;
  // The domain as a neutral mesh: the live vertices used by domain tetrahedra, renumbered in
  // slot order; domain tetrahedra with their references; every constrained facet with at least
  // one domain tetrahedron beside it, with its reference, each once (turned as seen from the
  // domain side with the smaller slot). `vertex_ids` (optional) receives the slot of each output
  // vertex.
  MeshData3 domain(std::vector<std::uint32_t>* vertex_ids = nullptr) const;

 private:
  static constexpr int kUnconstrained = std::numeric_limits<int>::max();

  std::uint64_t anisotropic_slots_ = 0;  // vertex slots (dead ones too) whose metric is not scalar
  std::vector<std::uint64_t> changed_at_;  // per vertex: the epoch of its last change
  std::uint64_t epoch_ = 0;
  // k new dead slots at the end of the tetrahedron arrays; the first one's id.
  std::uint32_t grow_tetrahedra(std::size_t k);
  void replace_metric(std::uint32_t v, const Metric3& m) noexcept {
    anisotropic_slots_ += static_cast<std::uint64_t>(!m.is_scalar()) - static_cast<std::uint64_t>(!metrics_[v].is_scalar());
    metrics_[v] = m;
  }

  std::vector<std::uint32_t> vertices_;    // 4 per tetrahedron; vertices_[4t] == kNone: dead
  std::vector<std::uint32_t> neighbours_;  // 4 per tetrahedron: twin facet handles
  std::vector<int> refs_;                  // 1 per tetrahedron
  std::vector<int> facet_refs_;            // 1 per facet handle; kUnconstrained when free
  std::vector<std::uint32_t> free_tetrahedra_;
  // Key: (min << 32) | max of the two vertex ids.
  std::unordered_map<std::uint64_t, std::uint8_t> constrained_edges_;
};

}  // namespace dtlab
