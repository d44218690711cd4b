// The Delaunay kernel of the 3D insertion variants "incremental" and "parallel" (George &
// Borouchaki §2.4-2.6): point P goes in by T_{i+1} = T_i - C_P + B_P. A visibility walk from the
// last insertion finds a base (a tetrahedron in conflict with P), the cavity C_P grows from it by
// adjacency, and the ball B_P joins P to the cavity's boundary facets. Buffers and deleted
// tetrahedra are reused, as in Marot, Pellerin, Remacle, "One machine, one minute, three billion
// tetrahedra" (IJNME 2019). The walk cannot cycle on a (regular) Delaunay tetrahedralization
// (Edelsbrunner 1990); a step bound backs that up.
//
// Ghost conflicts, coplanar case. A ghost (inf, a, b, c) is the limit of the sphere through
// a, b, c and a point q going to infinity beyond the hull facet. For p strictly off the facet's
// plane the limit is the half-space test orient3d(p, a, b, c) > 0. For p on the plane, every
// sphere through a, b, c meets the plane in the circle through a, b, c, so "p inside circle abc"
// equals insphere(a, b, c, d, p) > 0 for any d off the plane; taking for d the finite
// tetrahedron (a, b, c, d) across the hull facet, the exact zero (p on the circle) is broken by
// insphere_perturbed's cofactors: the cofactor of d is orient3d(a, b, c, p) = 0, so only the
// cofactors of a, b, c, p count, each orient3d(three of them, d) = (side of d, fixed) x the
// in-plane orientation of those three, i.e. the lifted-perturbation in-circle test of the plane.
// It is the very call that decides whether p conflicts with that finite tetrahedron, so a ghost
// and its finite neighbour never disagree for a p on their common facet, and the cavity stays
// the conflict region of the unique perturbed Delaunay tetrahedralization.
//
// Ownership (for "parallel"). A kernel may be restricted to the vertices of a slab of space (the
// infinite vertex belongs to every slab). A restricted kernel only modifies tetrahedra whose four
// vertices it owns, and abandons an insertion (returns false, nothing changed) as soon as its
// walk or cavity reaches one it does not own, or when its slots run out. Kernels with disjoint
// slabs can then run at once on one record array without touching a common word: a tetrahedron
// u next to a tetrahedron t owned by kernel A shares a facet of A's vertices with t, and every
// facet of u holds one of them, so no other kernel can rewrite u or any of u's neighbour slots;
// the walk (from an owned tetrahedron) and the cavity search read only owned tetrahedra and such
// neighbours, and write only owned tetrahedra and the neighbour slot of a neighbour facing an
// owned one.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "algorithms/delaunay3d/prepare.hpp"
#include "kernel/predicates/static_filter.hpp"
#include "kernel/vec.hpp"
#include "kernel/worker_team.hpp"
#include "mesh/tetrahedralization3.hpp"
#include "mesh/uninitialized_vector.hpp"

namespace dtlab {

// The vertices a restricted kernel owns: those whose coordinate along one axis lies in
// [lo, hi) (a slab: convex, so that walks between its points rarely leave it), and the infinite
// vertex.
struct SlabOwnership {
  const Vec3* points = nullptr;  // by vertex id
  double Vec3::*axis = &Vec3::x;
  double lo = 0.0, hi = 0.0;

  bool owns(std::uint32_t v) const noexcept {
    if (v == Tetrahedralization3::kInfinite) return true;
    const double c = points[v].*axis;
    return lo <= c && c < hi;
  }
  bool owns_all(const std::array<std::uint32_t, 4>& v) const noexcept {
    return owns(v[0]) && owns(v[1]) && owns(v[2]) && owns(v[3]);
  }
};

class CavityKernel {
 public:
  using Record = Tetrahedralization3::Record;

  // Vertex ids are indices into `points` (the insertion ranks, see InsertionOrder below). The
  // kernel keeps views of `records`; call refresh_views() after anyone else resizes it.
  CavityKernel(const Vec3* points, std::vector<Record>& records);

  // The first tetrahedron (a, b, c, d), positive, and its four ghosts, into empty records.
  void start(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d);

  // For a caller that appends points one at a time (algorithms/constrained3d/recovery/insert_point.hpp):
  // the points' array after it moved.
  void set_points(const Vec3* points) noexcept { p_ = points; }
  // Static filter bounds valid for every point the kernel will see (static_filter.hpp); none by
  // default. Only speed depends on them.
  void set_static_bounds(const StaticBounds3& bounds) noexcept { bounds_ = bounds; }
  // Vertex ids the kernel will see are below `count` (more are taken, only slower).
  void reserve_vertices(std::size_t count) { local_of_.resize(std::max(local_of_.size(), count), 0); }

  // Inserts point p (not a vertex yet). Unrestricted: always true. Restricted: false when the
  // insertion was abandoned, with nothing changed.
  bool insert(std::uint32_t p);

  // The walk's start: the last tetrahedron made, or where locate() ended. Must be alive.
  std::uint32_t last() const noexcept { return last_; }
  void set_last(std::uint32_t t) noexcept { last_ = t; }
  // A tetrahedron in conflict with p, found by walking from last(); restricted, kNone when the
  // walk cannot go on without entering a tetrahedron not owned, with *stopped (if given) the
  // owned one where it stopped.
  std::uint32_t locate(std::uint32_t p, std::uint32_t* stopped = nullptr) const;

  void restrict_to(const SlabOwnership& slab) noexcept { owned_ = slab, restricted_ = true; }
  void lift_restriction() noexcept { restricted_ = false; }

  // Slots. Unrestricted, a kernel takes fresh slots by growing the records itself; restricted,
  // only from its free list and from the chunk given to it.
  void refresh_views() noexcept;
  std::size_t spare_slots() const noexcept { return free_.size() + (chunk_end_ - chunk_next_); }
  // [begin, end): fresh records, for this kernel only; an unused rest of the previous chunk
  // joins the free list.
  void give_slots(std::uint32_t begin, std::uint32_t end);
  // Appends every slot this kernel holds unused (free list, rest of its chunk; all marked dead)
  // to `dead` and forgets them.
  void release_slots(std::vector<std::uint32_t>& dead);

 private:
  struct BoundaryFacet {
    std::array<std::uint32_t, 3> v;  // as the cavity tetrahedron lists it
    std::uint32_t outer;             // its twin outside the cavity
  };
  struct Edge {
    std::uint64_t key;  // vertex ids (from << 32 | to)
    std::uint32_t facet;
  };
  // Records added to the array at a time: an eighth of it, from 64 to 4096, so that a small
  // mesh does not touch (and page in) a large chunk it never uses.
  static constexpr std::size_t kMinChunk = 64, kChunk = 4096;
  // Records whose pages are faulted in at a time ahead of use: 2 MB (populate_ahead).
  static constexpr std::size_t kPopulateAhead = (std::size_t{2} << 20) / sizeof(Record);
  static constexpr std::size_t kTableSide = 64;  // balls with at most 64 boundary vertices

  std::uint32_t& twin(std::uint32_t h) noexcept { return r_[h >> 2].neighbour[h & 3u]; }
  // The vertex of the tetrahedron of h opposite h (marks removed).
  std::uint32_t apex(std::uint32_t h) const noexcept;
  // Restricted is restricted_, as a constant: the sequential kernel carries no ownership test.
  template <bool Restricted>
  bool owns_apex(std::uint32_t h) const noexcept {
    return !Restricted || owned_.owns(apex(h));
  }
  template <bool Restricted>
  bool insert_as(std::uint32_t p);
  template <bool Restricted>
  std::uint32_t walk(std::uint32_t p, std::uint32_t* stopped) const;

  void grow_chunk(std::size_t k);
  std::uint32_t new_slot();
  void populate_ahead() noexcept;
  void set_tetrahedron(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) noexcept {
    r_[t].vertex = {a, b, c, d};
  }
  void link(std::uint32_t g, std::uint32_t h) noexcept { twin(g) = h, twin(h) = g; }
  bool same_vertices(std::uint32_t g, std::uint32_t h) const noexcept;
  bool conflicts(std::uint32_t t, const Vec3& p) const noexcept;
  [[gnu::always_inline]] void enter_cavity(std::uint32_t t) noexcept;
  template <bool Restricted>
  bool grow_cavity(std::uint32_t base, std::uint32_t p);
  void clear_marks() noexcept;
  void fill_ball(std::uint32_t p);
  // Local number of boundary vertex v (kInfinite included), numbered in order of first request.
  std::uint8_t local_number(std::uint32_t v) noexcept {
    std::uint8_t* slot = v < local_of_.size() ? &local_of_[v] : far_local_slot(v);
    if (*slot == 0) {
      numbered_[numbered_count_++] = v;
      *slot = static_cast<std::uint8_t>(numbered_count_);
    }
    return static_cast<std::uint8_t>(*slot - 1);
  }
  std::uint8_t* far_local_slot(std::uint32_t v);
  void link_ball_by_edges();
  void link_large_ball();

  const Vec3* p_;
  StaticBounds3 bounds_;
  std::vector<Record>& records_;
  Record* r_ = nullptr;
  std::size_t slot_count_ = 0;  // records_.size() as of the last refresh
  std::uint32_t last_ = 0;
  bool restricted_ = false;
  SlabOwnership owned_;
  std::size_t chunk_next_ = 0, chunk_end_ = 0;  // fresh slots of this kernel
  std::size_t populated_ = 0;                    // fresh slots below this one are faulted in
  std::vector<std::uint32_t> cavity_, new_tetrahedra_, free_;
  std::vector<BoundaryFacet> boundary_;
  // Local number + 1 of each boundary vertex of the ball being linked, by vertex id (0: none),
  // as in Marot, Pellerin, Remacle 2019: one load instead of a hash probe; the infinite
  // vertex's own in local_of_infinite_. Grown on demand (points may be appended).
  std::vector<std::uint8_t> local_of_;
  std::uint8_t local_of_infinite_ = 0;
  // The vertices numbered for this ball: at most 3 per facet before the Euler check.
  std::array<std::uint32_t, 3 * 2 * kTableSide> numbered_;
  std::size_t numbered_count_ = 0;
  std::array<std::array<std::uint8_t, 3>, 2 * kTableSide> locals_;  // by new tetrahedron
  std::array<std::uint32_t, kTableSide * kTableSide> edge_table_{};
  std::vector<Edge> edges_;
};

// Removes the dead slots (every one has vertex[0] == kNone; `dead` lists each once) by moving
// the last live tetrahedra into them; the result is the same for the same input.
void compact_tetrahedra(std::vector<Tetrahedralization3::Record>& records, std::vector<std::uint32_t>& dead);

// The kernel's numbering: vertex id = insertion rank. Points in BRIO order (Amenta, Choi, Rote
// 2003; each round in Hilbert order), the first simplex moved to ranks 0-3, are reordered in
// place by reorder() (input.points may be that very array, registry.hpp), duplicates after the
// distinct ones; restore() puts the points back and renames the vertices of `records` to input ids.
// Given a WorkerTeam, both share their passes out among its threads (same result).
class InsertionOrder {
 public:
  // With `team`, the BRIO order is dealt on its threads (same result); with find_runs,
  // run_ends() is filled (a pass over 4 bytes a point more).
  explicit InsertionOrder(const PreparedPoints3& input, WorkerTeam* team = nullptr, bool find_runs = false);
  void reorder(std::vector<Vec3>& points, WorkerTeam* team = nullptr);
  std::size_t distinct_count() const noexcept { return distinct_; }
  // After reorder(): whether (0, 1, 2, 3) is positive, else start with (0, 1, 3, 2).
  bool first_simplex_positive() const noexcept { return positive_; }
  // The input id of each insertion rank.
  std::span<const std::uint32_t> input_ids() const noexcept { return order_; }
  // With find_runs: the ends of the runs of ranks [4, distinct_count()) in increasing Hilbert
  // order, ascending, the last one distinct_count(): the BRIO rounds, some split by the first
  // simplex's swaps. Else empty.
  std::span<const std::uint32_t> run_ends() const noexcept { return run_ends_; }
  // Spends the order: std::move(order).restore(...), once, last.
  void restore(std::vector<Vec3>& points, std::vector<Tetrahedralization3::Record>& records,
               WorkerTeam* team = nullptr) &&;

 private:
  UninitializedVector<std::uint32_t> order_;
  std::vector<std::uint32_t> run_ends_;
  std::size_t distinct_ = 0;
  bool positive_ = true;
};

}  // namespace dtlab
