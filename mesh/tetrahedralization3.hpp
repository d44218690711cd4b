// The 3D tetrahedralization structure every 3D algorithm of dtlab builds and every caller reads
// (book §1.3, §1.7): one flat array of 32-byte records, each the 4 vertex ids and 4 neighbour
// facet handles (32-bit) of a tetrahedron, the convex hull closed by an infinite vertex with ghost
// tetrahedra. Vertices and neighbours share a record, and so a cache line, because every step of
// point location and cavity search reads both for a tetrahedron it has not seen yet.
//
// Numbering, drawn once (every 3D file follows it):
//
//   +-------------------------------------------------------------+
//   |                          v3                                 |
//   |                         /|\         positive: orient3d(v0,  |
//   |                        / | \        v1, v2, v3) > 0, i.e.   |
//   |                       /  |  \       det(v1-v0, v2-v0,       |
//   |                      /   |   \      v3-v0) > 0 (Medit):     |
//   |                     /    |    \     v0 -> v1 -> v2 turns    |
//   |                    /     |     \    counter-clockwise seen  |
//   |                  v0 . . .|. . . v2  from v3 (v1 in front).  |
//   |                    \     |     /                            |
//   |                      \   |   /      facet i lies opposite   |
//   |                        \ | /        vertex i:               |
//   |                         v1          kFacetVertex[i] below   |
//   +-------------------------------------------------------------+
//
//   facet i | vertices (local indices), counter-clockwise seen from vertex i (from inside)
//   --------+--------------------------------------------------------------------------------
//      0    | v1 v3 v2
//      1    | v0 v2 v3
//      2    | v0 v3 v1
//      3    | v0 v1 v2
//
//  - Tetrahedron t has vertices v0..v3 = records()[t].vertex[0..3], positively oriented.
//  - Facet handle h = 4t + i is facet i of t, opposite vertex i. Listed in kFacetVertex[i] order,
//    the facet followed by vertex i is again a positive tetrahedron: orient3d(f0, f1, f2, vi) > 0
//    (seen from outside t, the same facet turns clockwise). Any cyclic rotation of a facet's
//    three vertices keeps this, and so does any even permutation of a tetrahedron's four.
//  - records()[t].neighbour[i] is the twin of h = 4t + i: the same facet seen from the adjacent tetrahedron, which
//    lists its three vertices in the opposite cyclic order.
//
// Convex hull: the infinite vertex kInfinite closes space into a 3-sphere. Across each hull facet
// lies a ghost tetrahedron (kInfinite, a, b, c); the infinite vertex is always vertex 0 of a ghost,
// so facet 0 of a ghost, (a, c, b) in table order, is its hull facet. A ghost is positive in the
// sense that it becomes a positive tetrahedron when kInfinite is replaced by any point strictly
// beyond the hull facet: orient3d(q, a, b, c) > 0 for q outside. Ghosts are linked to each other
// like any tetrahedra: every facet has a twin. A ghost (kInfinite, a, b, c) stands for the limit
// of the sphere through a, b, c and a point going to infinity beyond the hull facet: p is in
// conflict with it iff p is strictly beyond the facet's plane, or on that plane and strictly
// inside the circle through a, b, c (algorithms/delaunay3d/incremental.cpp decides the circle
// case with the symbolic perturbation, so that ties resolve as for finite tetrahedra).
//
// Contract between algorithms and callers. Algorithms build the structure through the mutable
// accessors; when an algorithm returns, the structure is
//   - compact: every stored tetrahedron is alive (no holes, no kNone anywhere);
//   - closed: twin(twin(h)) == h, twins hold the same three vertices in opposite
//     cyclic order, ghosts carry kInfinite at index 0 and nowhere else;
//   - in input numbering: vertex ids are 0-based indices into points() (the input, in input
//     order); a point that is a duplicate of an earlier one is referenced by no tetrahedron.
// With m distinct used vertices and e edges (those to kInfinite included) it holds e - m - 1
// tetrahedra, ghosts included (Euler's relation on the 3-sphere); unlike 2D, m does not fix the
// count. Callers read it; check_topology() verifies the combinatorial part cheaply (tests check
// the geometry).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

class Tetrahedralization3 {
 public:
  // The infinite vertex, apex of every ghost tetrahedron.
  static constexpr std::uint32_t kInfinite = 0xFFFFFFFEu;
  // No vertex / no tetrahedron / no facet handle.
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  // Facet handles 4t + 3 must stay below kInfinite.
  static constexpr std::uint64_t kMaxTetrahedra = kInfinite / 4;
  // Vertex ids must stay below kInfinite; a uniform point set makes about 6.7 tetrahedra per
  // point, so about 160 million points fill kMaxTetrahedra.
  static constexpr std::uint64_t kMaxPoints = 150'000'000;

  // Local indices of facet i, counter-clockwise seen from vertex i (see the drawing).
  static constexpr std::array<std::array<std::uint32_t, 3>, 4> kFacetVertex = {{
      {1, 3, 2},
      {0, 2, 3},
      {0, 3, 1},
      {0, 1, 2},
  }};

  // One tetrahedron: vertex[i] is vertex i, neighbour[i] the twin of its facet i.
  struct Record {
    // Left unwritten when an array of records grows: the insertion kernels write every slot they
    // take before reading it, so zeros written first are a pass for nothing. In the parallel
    // kernel that pass was one thread's over every thread's fresh slots (13 % of its samples at
    // 10^7 points, issue 23); sequentially, the first touch's cost only moves to the slot's first
    // write. Its arrays are indeterminate until written.
    Record() noexcept {}  // NOLINT(modernize-use-equals-default): = default makes resize() zero them
    Record(const std::array<std::uint32_t, 4>& v, const std::array<std::uint32_t, 4>& n) noexcept
        : vertex(v), neighbour(n) {}
    std::array<std::uint32_t, 4> vertex;
    std::array<std::uint32_t, 4> neighbour;
  };
  static_assert(sizeof(Record) == 32);

  Tetrahedralization3() = default;
  // The input points, in input order (vertex id = index). No tetrahedra yet.
  explicit Tetrahedralization3(std::vector<Vec3> points) : points_(std::move(points)) {}

  std::span<const Vec3> points() const noexcept { return points_; }
  std::size_t point_count() const noexcept { return points_.size(); }

  // --- Navigation (pure arithmetic on handles) ------------------------------------------------
  static constexpr std::uint32_t tetrahedron_of(std::uint32_t h) noexcept { return h >> 2; }
  static constexpr std::uint32_t index_in_tetrahedron(std::uint32_t h) noexcept { return h & 3u; }
  static constexpr std::uint32_t facet(std::uint32_t t, std::uint32_t i) noexcept { return 4 * t + i; }

  // --- Reading ------------------------------------------------------------------------------
  // Every stored tetrahedron, ghosts included.
  std::size_t tetrahedron_count() const noexcept { return records_.size(); }
  const std::vector<Record>& records() const noexcept { return records_; }

  std::uint32_t vertex(std::uint32_t t, std::uint32_t i) const noexcept { return records_[t].vertex[i]; }
  std::uint32_t twin(std::uint32_t h) const noexcept { return records_[h >> 2].neighbour[h & 3u]; }
  // The tetrahedron across facet i of t.
  std::uint32_t adjacent(std::uint32_t t, std::uint32_t i) const noexcept {
    return tetrahedron_of(records_[t].neighbour[i]);
  }
  bool is_ghost(std::uint32_t t) const noexcept { return records_[t].vertex[0] == kInfinite; }
  // The vertex opposite facet handle h (the one h's tetrahedron adds to the facet).
  std::uint32_t apex(std::uint32_t h) const noexcept { return records_[h >> 2].vertex[h & 3u]; }
  // The three vertices of facet handle h, in kFacetVertex order.
  std::array<std::uint32_t, 3> facet_vertices(std::uint32_t h) const noexcept {
    const auto& v = records_[tetrahedron_of(h)].vertex;
    const auto& f = kFacetVertex[index_in_tetrahedron(h)];
    return {v[f[0]], v[f[1]], v[f[2]]};
  }

  // Finite tetrahedra (ghosts left out), positively oriented, input ids, in storage order.
  std::vector<std::array<std::uint32_t, 4>> finite_tetrahedra() const;
  std::size_t finite_tetrahedron_count() const noexcept;

  // Throws InternalError naming the first broken facet: sizes, vertex ids in range, kInfinite
  // only at index 0, no repeated vertex in a tetrahedron, twins present, in another
  // tetrahedron, symmetric, over the same three vertices in opposite cyclic order.
  // O(size), combinatorial only.
  void check_topology() const;

  // --- Building (for algorithms; see the contract above) -------------------------------------
  std::vector<Vec3>& mutable_points() noexcept { return points_; }
  std::vector<Record>& mutable_records() noexcept { return records_; }
  // Appends tetrahedron (a, b, c, d), which must be positive, permuted evenly so that kInfinite
  // (if present) is vertex 0, with no neighbours yet (kNone). Returns its index.
  std::uint32_t add_tetrahedron(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d);
  // Makes facets g and h twins of each other.
  void link(std::uint32_t g, std::uint32_t h) noexcept {
    records_[g >> 2].neighbour[g & 3u] = h;
    records_[h >> 2].neighbour[h & 3u] = g;
  }
  // Reserves room for `tetrahedra` tetrahedra (reserved memory that is never written costs no
  // physical memory on systems with lazy allocation).
  void reserve_tetrahedra(std::size_t tetrahedra);
  void clear_tetrahedra() noexcept { records_.clear(); }

 private:
  std::vector<Vec3> points_;
  std::vector<Record> records_;
};

}  // namespace dtlab
