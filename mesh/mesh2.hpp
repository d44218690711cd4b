// The mutable 2D simplicial mesh that generation, optimization and adaptation share (book §10;
// MMG keeps one such structure for all its operators): flat arrays with free lists, a metric
// per vertex, a reference (region) per triangle, and constrained half-edges carrying the
// reference of the boundary piece they belong to.
//
// Numbering is the one drawn in mesh/triangulation2.hpp: triangle t has vertices
// vertices[3t + 0..2] counter-clockwise; half-edge h = 3t + i lies opposite vertex i and runs
// from v(i+1) to v(i+2); twin(h) is the same edge in the adjacent triangle. The convex hull is
// closed by ghost triangles with kInfinite as vertex 0, as in Triangulation2, so every half-edge
// of a live triangle has a twin.
//
// Triangles outside the domain (between the boundary and the hull, and in holes) stay in the
// structure with the reference kExterior, as the book keeps the exterior of the empty mesh until
// the end (§5.2). The domain's boundary is made of constrained half-edges, so an operator that
// never crosses a constrained edge never touches the exterior.
//
// Free lists: a removed triangle or vertex keeps its slot, marked dead, and the next new one
// reuses it. Operators keep the invariant that every live triangle is linked on all three edges;
// check() verifies it (and orientation, exactly) for tests.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "kernel/metric.hpp"
#include "kernel/vec.hpp"
#include "mesh/io/mesh_data.hpp"
#include "mesh/mesh_vertices.hpp"
#include "mesh/navigation2.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

// A constrained edge of the input to Mesh2: vertex ids and the reference of its boundary piece.
struct MeshEdge2 {
  std::uint32_t a = 0, b = 0;
  int ref = 0;
};

class Mesh2 : public MeshVertices<Vec2, Metric2> {
 public:
  static constexpr std::uint32_t kNone = Triangulation2::kNone;
  static constexpr std::uint32_t kInfinite = Triangulation2::kInfinite;
  // The reference of a triangle outside the domain (exterior of the boundary, holes, ghosts).
  static constexpr int kExterior = std::numeric_limits<int>::min();

  // Vertex flags kFixed, kOnBoundary, kDead: mesh/mesh_vertices.hpp.

  Mesh2() = default;
  // From a closed triangulation (ghosts included): `triangle_refs` one per stored triangle of
  // `tri` (kExterior for ghosts and for triangles outside the domain); `constrained` the edges
  // that carry a constraint (each must be an edge of `tri`, else InputError naming it); every
  // vertex gets `metric` and the flag kFixed, vertices on a constrained edge also kOnBoundary.
  Mesh2(const Triangulation2& tri, std::span<const int> triangle_refs, std::span<const MeshEdge2> constrained,
        const Metric2& metric = {});

  // --- Navigation (as Triangulation2) --------------------------------------------------------
  static constexpr std::uint32_t triangle_of(std::uint32_t h) noexcept { return h / 3; }
  static constexpr std::uint32_t index_in_triangle(std::uint32_t h) noexcept { return h % 3; }
  static constexpr std::uint32_t half_edge(std::uint32_t t, std::uint32_t i) noexcept { return 3 * t + i; }
  static constexpr std::uint32_t next(std::uint32_t h) noexcept { return h % 3 == 2 ? h - 2 : h + 1; }
  static constexpr std::uint32_t prev(std::uint32_t h) noexcept { return h % 3 == 0 ? h + 2 : h - 1; }

  // --- Vertices (slots, points, metrics, flags, remove_vertex: mesh/mesh_vertices.hpp) --------
  // Moving a vertex is the caller's responsibility for validity (check orientation first).
  void set_point(std::uint32_t v, const Vec2& p) noexcept { points_[v] = p; }
  void set_metric(std::uint32_t v, const Metric2& m) noexcept { metrics_[v] = m; }
  // One live triangle incident to v (kNone for a dead vertex). Operators keep it current.
  std::uint32_t vertex_triangle(std::uint32_t v) const noexcept { return vertex_element_[v]; }
  void set_vertex_triangle(std::uint32_t v, std::uint32_t t) noexcept { vertex_element_[v] = t; }
  // A new vertex (reusing a dead slot if any); no triangle yet.
  std::uint32_t add_vertex(const Vec2& p, const Metric2& m, std::uint8_t flags = 0);

  // --- Triangles -----------------------------------------------------------------------------
  std::uint32_t triangle_capacity() const noexcept { return static_cast<std::uint32_t>(vertices_.size() / 3); }
  std::uint32_t live_triangle_count() const noexcept { return triangle_capacity() - static_cast<std::uint32_t>(free_triangles_.size()); }
  bool is_alive(std::uint32_t t) const noexcept { return vertices_[3 * t] != kNone; }
  bool is_ghost(std::uint32_t t) const noexcept { return vertices_[3 * t] == kInfinite; }
  // Alive, finite and inside the domain.
  bool in_domain(std::uint32_t t) const noexcept { return is_alive(t) && !is_ghost(t) && refs_[t] != kExterior; }
  std::uint32_t vertex(std::uint32_t t, std::uint32_t i) const noexcept { return vertices_[3 * t + i]; }
  std::uint32_t vertex_at(std::uint32_t h) const noexcept { return vertices_[h]; }  // opposite h
  std::uint32_t origin(std::uint32_t h) const noexcept { return vertices_[next(h)]; }
  std::uint32_t destination(std::uint32_t h) const noexcept { return vertices_[prev(h)]; }
  std::uint32_t twin(std::uint32_t h) const noexcept { return neighbours_[h]; }
  int ref(std::uint32_t t) const noexcept { return refs_[t]; }
  void set_ref(std::uint32_t t, int r) noexcept { refs_[t] = r; }

  // A new triangle (a, b, c) with reference r (reusing a dead slot if any), no neighbours
  // (kNone) and no constraints yet; kInfinite may only be `a`. Updates vertex_triangle of its
  // finite vertices.
  std::uint32_t add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, int r);
  // Marks t dead and frees its slot (its neighbours' links to it are the caller's to redo).
  void remove_triangle(std::uint32_t t);
  // Makes g and h twins.
  void link(std::uint32_t g, std::uint32_t h) noexcept {
    neighbours_[g] = h;
    neighbours_[h] = g;
  }

  // --- Constraints ---------------------------------------------------------------------------
  bool is_constrained(std::uint32_t h) const noexcept { return constrained_[h] != 0; }
  int edge_ref(std::uint32_t h) const noexcept { return edge_refs_[h]; }
  // Sets the constraint (with its reference) on h only: operators that rebuild triangles call
  // it on each side; set_constraint_both on h and its twin.
  void set_constraint(std::uint32_t h, bool constrained, int r) noexcept {
    constrained_[h] = constrained ? 1 : 0;
    edge_refs_[h] = r;
  }
  void set_constraint_both(std::uint32_t h, bool constrained, int r) noexcept {
    set_constraint(h, constrained, r);
    set_constraint(neighbours_[h], constrained, r);
  }

  // --- Queries -------------------------------------------------------------------------------
  // The half-edges opposite v in the triangles around v (the edges of v's link), counter-clockwise,
  // starting from vertex_triangle(v). Ghosts included. Throws InternalError past a bound.
  void ball(std::uint32_t v, std::vector<std::uint32_t>& out) const;
  // The half-edge u -> v, or kNone.
  std::uint32_t find_half_edge(std::uint32_t u, std::uint32_t v) const;

  // Where p lies (nav2::locate), found by a visibility walk from `start` (a live triangle) that
  // does not cross constrained edges when `stop_at_constraints` (it then ends in the last
  // triangle reached, `blocked` set). The walk's random choices are seeded from `start`.
  using Where = nav2::Where;
  using Location = nav2::Location;
  Location locate(const Vec2& p, std::uint32_t start, bool stop_at_constraints = false) const;

  // Replaces the diagonal h of its quadrilateral by the other one; both triangles must be live and
  // finite, h unconstrained, and the quadrilateral strictly convex (the caller checks). The two
  // triangles keep their slots and references; constraints on the four outer edges move with
  // them. Returns a half-edge of the new diagonal.
  std::uint32_t flip(std::uint32_t h);

  // --- Whole-mesh ----------------------------------------------------------------------------
  // Throws InternalError naming the first problem: links symmetric and reversed, no live
  // triangle on a dead vertex, vertex_triangle current, constraints equal on both sides, every
  // finite live triangle positively oriented (exact orient2d), the free lists consistent.
  void check() const;
  // The domain as a neutral mesh: the live vertices used by domain triangles, renumbered in
  // slot order; domain triangles with their references; every constrained edge with at least
  // one domain triangle beside it, with its reference, each once. `vertex_ids` (optional)
  // receives the slot of each output vertex.
  MeshData2 domain(std::vector<std::uint32_t>* vertex_ids = nullptr) const;

 private:
  std::vector<std::uint32_t> vertices_;    // 3 per triangle; vertices_[3t] == kNone: dead
  std::vector<std::uint32_t> neighbours_;  // 3 per triangle: twin half-edges
  std::vector<int> refs_;                  // 1 per triangle
  std::vector<std::uint8_t> constrained_;  // 1 per half-edge
  std::vector<int> edge_refs_;             // 1 per half-edge
  std::vector<std::uint32_t> free_triangles_;
};

}  // namespace dtlab
