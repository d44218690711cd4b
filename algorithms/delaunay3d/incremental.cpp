// Variant "incremental": the reduced incremental method in 3D, George & Borouchaki §2.4-2.6.
// Each point P goes in by the Delaunay kernel T_{i+1} = T_i - C_P + B_P: a visibility walk from
// the last insertion finds a base (a tetrahedron in conflict with P), the cavity C_P grows from
// it by adjacency, and the ball B_P joins P to the cavity's boundary facets. Insertion order:
// BRIO rounds, each in Hilbert order (Amenta, Choi, Rote 2003); buffers and deleted tetrahedra
// are reused, as in Marot, Pellerin, Remacle, "One machine, one minute, three billion
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
#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/delaunay3d/prepare.hpp"
#include "algorithms/permute_in_place.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "algorithms/spatial_sort.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

namespace {

using T3 = Tetrahedralization3;
constexpr std::uint32_t kInf = T3::kInfinite;
constexpr std::uint32_t kNone = T3::kNone;
constexpr auto kFacet = T3::kFacetVertex;

// Marks live in the two top bits of vertex 3, which is never kInfinite and, below kMaxPoints,
// never uses them: the mark is read with the vertices, in the same cache line. A tetrahedron on
// the free list has vertex 0 = kNone.
constexpr std::uint32_t kInCavity = 0x80000000u;
constexpr std::uint32_t kOutside = 0x40000000u;
constexpr std::uint32_t kMarks = kInCavity | kOutside;
static_assert(T3::kMaxPoints < kOutside);

// The insertion engine, working on raw views of the tetrahedralization's arrays and on the points
// in insertion order: vertex ids are insertion ranks while it runs, which keeps consecutive
// insertions close in memory. Deleted tetrahedra go to a free list and are reused; finish()
// compacts.
class Inserter {
 public:
  Inserter(const Vec3* points, std::size_t point_count, std::vector<T3::Record>& records)
      : p_(points), records_(records) {
    DTLAB_ASSERT(records.empty() && point_count < kOutside);
    local_.fill({kNone, 0});
    refresh_views();
    cavity_.reserve(256);
    boundary_.reserve(512);
    hashed_.reserve(kTableSide);
    locals_.reserve(512);
    free_.reserve(1024);
  }

  // The first tetrahedron (a, b, c, d), positive, and its four ghosts.
  void start(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    grow(5);
    const std::uint32_t v[4] = {a, b, c, d};
    set_tetrahedron(0, a, b, c, d);
    for (std::uint32_t i = 0; i < 4; ++i) {
      // Ghost 1 + i lies across facet i of tetrahedron 0: (inf, f0, f1, f2) with the facet as
      // tetrahedron 0 lists it is positive in the ghost sense (see tetrahedralization3.hpp).
      const auto& f = kFacet[i];
      set_tetrahedron(1 + i, kInf, v[f[0]], v[f[1]], v[f[2]]);
      link(i, 4 * (1 + i));
    }
    // Ghost facets through kInfinite (1, 2, 3): each pair of ghosts shares one.
    for (std::uint32_t g = 1; g <= 4; ++g)
      for (std::uint32_t i = 1; i < 4; ++i)
        for (std::uint32_t h = g + 1; h <= 4; ++h)
          for (std::uint32_t j = 1; j < 4; ++j)
            if (same_vertices(4 * g + i, 4 * h + j)) link(4 * g + i, 4 * h + j);
    last_ = 0;
  }

  void insert(std::uint32_t p) {
    const std::uint32_t base = locate(p);
    grow_cavity(base, p);
    fill_ball(p);
  }

  // Removes the free slots by moving the last live tetrahedra into them.
  void finish() {
    std::sort(free_.begin(), free_.end());
    const std::size_t live = count_ - free_.size();
    std::size_t source = count_;
    for (const std::uint32_t hole : free_) {
      if (hole >= live) break;
      do --source;
      while (r_[source].vertex[0] == kNone);
      move_tetrahedron(static_cast<std::uint32_t>(source), hole);
    }
    count_ = live;
    free_.clear();
    records_.resize(count_);
  }

  std::size_t tetrahedron_count() const noexcept { return count_ - free_.size(); }

 private:
  void refresh_views() noexcept { r_ = records_.data(); }
  std::uint32_t& twin(std::uint32_t h) noexcept { return r_[h >> 2].neighbour[h & 3u]; }

  // k more slots in use at the end. The array's size runs ahead of count_ by chunks, so that
  // most calls only count; its capacity grows by a quarter when exhausted, so that a regrowth
  // costs little peak memory (the caller reserves the expected size up front).
  void grow(std::size_t k) {
    const std::size_t need = count_ + k;
    if (need > records_.size()) {
      if (need > T3::kMaxTetrahedra)  // a size limit of the input, not a bug
        throw InputError("the Delaunay tetrahedralization of these points needs more than " +
                         std::to_string(T3::kMaxTetrahedra) + " tetrahedra (32-bit facet handles)");
      const std::size_t size = std::min<std::size_t>(need + kChunk, T3::kMaxTetrahedra);
      if (size > records_.capacity()) records_.reserve(std::max(size, records_.capacity() + records_.capacity() / 4));
      records_.resize(size);
      refresh_views();
    }
    count_ = need;
  }

  // A slot for a new tetrahedron: a recycled one, else a new one at the end.
  std::uint32_t new_slot() {
    if (!free_.empty()) {
      const std::uint32_t t = free_.back();
      free_.pop_back();
      return t;
    }
    grow(1);
    return static_cast<std::uint32_t>(count_ - 1);
  }

  void set_tetrahedron(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) noexcept {
    r_[t].vertex = {a, b, c, d};
  }
  void link(std::uint32_t g, std::uint32_t h) noexcept { twin(g) = h, twin(h) = g; }

  bool same_vertices(std::uint32_t g, std::uint32_t h) const noexcept {
    std::array<std::uint32_t, 3> a, b;
    for (std::uint32_t k = 0; k < 3; ++k) {
      a[k] = r_[g >> 2].vertex[kFacet[g & 3u][k]];
      b[k] = r_[h >> 2].vertex[kFacet[h & 3u][k]];
    }
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    return a == b;
  }

  void move_tetrahedron(std::uint32_t from, std::uint32_t to) noexcept {
    r_[to] = r_[from];
    for (std::uint32_t i = 0; i < 4; ++i) twin(r_[to].neighbour[i]) = 4 * to + i;
    r_[from].vertex[0] = kNone;
  }

  // See the file comment for the coplanar case.
  bool conflicts(std::uint32_t t, const Vec3& p) const noexcept {
    const std::uint32_t* v = r_[t].vertex.data();
    if (v[0] != kInf) return insphere_perturbed(p_[v[0]], p_[v[1]], p_[v[2]], p_[v[3]], p) == Sign::Positive;
    const Sign side = orient3d(p, p_[v[1]], p_[v[2]], p_[v[3]]);
    if (side != Sign::Zero) return side == Sign::Positive;
    // The finite tetrahedron across the hull facet (it may carry a mark).
    const std::uint32_t* w = r_[r_[t].neighbour[0] >> 2].vertex.data();
    return insphere_perturbed(p_[w[0]], p_[w[1]], p_[w[2]], p_[w[3] & ~kMarks], p) == Sign::Positive;
  }

  // Visibility walk from the last insertion to a tetrahedron in conflict with p: a finite one
  // whose closed region holds p (p is then strictly inside its sphere: p is no vertex), or a
  // ghost whose hull facet p is strictly beyond.
  std::uint32_t locate(std::uint32_t pid) const {
    const Vec3& p = p_[pid];
    std::uint32_t t = last_;
    if (r_[t].vertex[0] == kInf) t = r_[t].neighbour[0] >> 2;
    std::uint32_t entered = 4;  // the facet of t the walk came in through (4: none)
    for (std::size_t steps = 0; steps <= count_; ++steps) {
      const std::uint32_t* v = r_[t].vertex.data();
      if (v[0] == kInf) return t;  // entered across its hull facet: p is strictly beyond it
      std::uint32_t next = kNone;
      for (std::uint32_t k = 1; k <= 4; ++k) {
        const std::uint32_t i = (entered + k) & 3u;
        if (i == entered) continue;
        const auto& f = kFacet[i];
        if (orient3d(p_[v[f[0]]], p_[v[f[1]]], p_[v[f[2]]], p) == Sign::Negative) {
          next = r_[t].neighbour[i];
          break;
        }
      }
      if (next == kNone) return t;
      t = next >> 2, entered = next & 3u;
    }
    throw InternalError("incremental 3D Delaunay: the walk to point (rank " + std::to_string(pid) +
                        ") exceeded its bound of " + std::to_string(count_) + " steps");
  }

  // Neighbours are cache misses more often than not: ask for them when t enters the queue, so
  // that they have arrived when t is processed.
  void enter_cavity(std::uint32_t t) noexcept {
    r_[t].vertex[3] |= kInCavity;
    cavity_.push_back(t);
    for (std::uint32_t i = 0; i < 4; ++i) __builtin_prefetch(r_ + (r_[t].neighbour[i] >> 2));
  }

  // C_P by breadth-first search from the base over adjacency (the cavity is connected). Every
  // facet of a cavity tetrahedron is looked at once, so the boundary facets come out on the way,
  // each as the cavity tetrahedron lists it (counter-clockwise seen from P).
  void grow_cavity(std::uint32_t base, std::uint32_t pid) {
    const Vec3& p = p_[pid];
    cavity_.clear();
    boundary_.clear();
    enter_cavity(base);
    for (std::size_t k = 0; k < cavity_.size(); ++k) {
      const std::uint32_t t = cavity_[k];
      for (std::uint32_t i = 0; i < 4; ++i) {
        const std::uint32_t outer = r_[t].neighbour[i];
        const std::uint32_t u = outer >> 2;
        const std::uint32_t mark = r_[u].vertex[3] & kMarks;
        if (mark == 0) {
          if (conflicts(u, p)) {
            enter_cavity(u);
            continue;
          }
          r_[u].vertex[3] |= kOutside;  // cleared when B_P links to it
        } else if (mark == kInCavity) {
          continue;
        }
        const std::uint32_t* w = r_[t].vertex.data();
        const std::uint32_t v[4] = {w[0], w[1], w[2], w[3] & ~kMarks};
        const auto& f = kFacet[i];
        boundary_.push_back({{v[f[0]], v[f[1]], v[f[2]]}, outer});
      }
    }
  }

  // B_P: one tetrahedron (f0, f1, f2, P) per boundary facet, in the cavity's slots first. A
  // facet through kInfinite lists it first (ghosts keep it at index 0 and every facet of a
  // ghost that holds it starts with it), so the new tetrahedron is a ghost in normal form.
  void fill_ball(std::uint32_t p) {
    const std::size_t faces = boundary_.size();
    const std::size_t cavity_size = cavity_.size();
    new_tetrahedra_.clear();
    for (std::size_t j = 0; j < faces; ++j) {
      const std::uint32_t t = j < cavity_size ? cavity_[j] : new_slot();
      const BoundaryFacet& b = boundary_[j];
      set_tetrahedron(t, b.v[0], b.v[1], b.v[2], p);
      link(4 * t + 3, b.outer);
      r_[b.outer >> 2].vertex[3] &= ~kMarks;  // every tetrahedron marked outside is behind some facet
      new_tetrahedra_.push_back(t);
    }
    for (std::size_t j = faces; j < cavity_size; ++j) {
      r_[cavity_[j]].vertex[0] = kNone;
      free_.push_back(cavity_[j]);
    }
    link_ball_by_edges();
    last_ = new_tetrahedra_[0];
    for (const std::uint32_t t : new_tetrahedra_)
      if (r_[t].vertex[0] != kInf) {
        last_ = t;
        break;
      }
  }

  // Local number of boundary vertex v, from a small open-addressing hash table (kInfinite is
  // a key like any other).
  std::uint8_t local_number(std::uint32_t v) {
    std::uint32_t h = (v * 0x9E3779B1u) >> (32 - kHashBits);
    while (local_[h].key != v) {
      if (local_[h].key == kNone) {
        local_[h] = {v, static_cast<std::uint32_t>(hashed_.size())};
        hashed_.push_back(h);
        break;
      }
      h = (h + 1) & (kHashSize - 1);
    }
    return static_cast<std::uint8_t>(local_[h].local);
  }

  // Links facets 0, 1, 2 of the new tetrahedra (x0, x1, x2, P) among themselves. Facet k holds
  // P and the boundary edge x(k+1) -> x(k+2); the neighbour across it is the new tetrahedron
  // whose boundary facet holds the same edge reversed. Boundary vertices get small local
  // numbers, and a table indexed by (from, to) finds the reversed edge.
  void link_ball_by_edges() {
    // The boundary is a triangulated sphere: F = 2V - 4 (Euler).
    const std::size_t faces = new_tetrahedra_.size();
    if (faces / 2 + 2 > kTableSide) {
      link_large_ball();
      return;
    }
    locals_.clear();
    for (const std::uint32_t t : new_tetrahedra_) {
      const std::uint32_t* v = r_[t].vertex.data();
      const std::array<std::uint8_t, 3> l = {local_number(v[0]), local_number(v[1]), local_number(v[2])};
      locals_.push_back(l);
      edge_table_[l[1] * kTableSide + l[2]] = 4 * t + 0;
      edge_table_[l[2] * kTableSide + l[0]] = 4 * t + 1;
      edge_table_[l[0] * kTableSide + l[1]] = 4 * t + 2;
    }
    DTLAB_ASSERT(faces == 2 * hashed_.size() - 4);
    for (std::size_t j = 0; j < faces; ++j) {
      const std::uint32_t t = new_tetrahedra_[j];
      const auto& l = locals_[j];
      r_[t].neighbour[0] = edge_table_[l[2] * kTableSide + l[1]];
      r_[t].neighbour[1] = edge_table_[l[0] * kTableSide + l[2]];
      r_[t].neighbour[2] = edge_table_[l[1] * kTableSide + l[0]];
    }
    for (const std::uint32_t h : hashed_) local_[h].key = kNone;
    hashed_.clear();
  }

  // The same matching by sorting the directed edges by vertex ids, for large balls.
  void link_large_ball() {
    edges_.clear();
    for (const std::uint32_t t : new_tetrahedra_) {
      const std::uint32_t* v = r_[t].vertex.data();
      for (std::uint32_t k = 0; k < 3; ++k)
        edges_.push_back({std::uint64_t{v[(k + 1) % 3]} << 32 | v[(k + 2) % 3], 4 * t + k});
    }
    std::sort(edges_.begin(), edges_.end(), [](const Edge& a, const Edge& b) { return a.key < b.key; });
    std::size_t vertices = 0;
    for (std::size_t j = 0; j < edges_.size(); ++j) {
      const Edge& e = edges_[j];
      vertices += j == 0 || (e.key >> 32) != (edges_[j - 1].key >> 32);
      const std::uint64_t reversed = e.key << 32 | e.key >> 32;
      const auto it = std::lower_bound(edges_.begin(), edges_.end(), reversed,
                                       [](const Edge& x, std::uint64_t key) { return x.key < key; });
      DTLAB_ASSERT(it != edges_.end() && it->key == reversed);
      twin(e.facet) = it->facet;
    }
    DTLAB_ASSERT(new_tetrahedra_.size() == 2 * vertices - 4);
  }

  struct BoundaryFacet {
    std::array<std::uint32_t, 3> v;  // as the cavity tetrahedron lists it
    std::uint32_t outer;             // its twin outside the cavity
  };
  struct Edge {
    std::uint64_t key;  // vertex ids (from << 32 | to)
    std::uint32_t facet;
  };
  struct HashSlot {
    std::uint32_t key;  // a vertex id, or kNone
    std::uint32_t local;
  };
  static constexpr std::size_t kChunk = 4096;     // records added to the array at a time
  static constexpr std::size_t kTableSide = 64;  // balls with at most 64 boundary vertices
  static constexpr int kHashBits = 8;            // load at most 1/4
  static constexpr std::size_t kHashSize = std::size_t{1} << kHashBits;

  const Vec3* p_;
  std::vector<T3::Record>& records_;
  T3::Record* r_ = nullptr;
  std::size_t count_ = 0;  // slots in use, free ones included
  std::uint32_t last_ = 0;
  std::vector<std::uint32_t> cavity_, new_tetrahedra_, free_;
  std::vector<BoundaryFacet> boundary_;
  std::array<HashSlot, kHashSize> local_;
  std::vector<std::uint32_t> hashed_;  // the used slots of local_
  std::vector<std::array<std::uint8_t, 3>> locals_;
  std::array<std::uint32_t, kTableSide * kTableSide> edge_table_{};
  std::vector<Edge> edges_;
};

}  // namespace

void delaunay3d_incremental(const PreparedPoints3& input, const Delaunay3dOptions& /*options*/,
                            Tetrahedralization3& tetrahedralization) {
  std::vector<Vec3>& points = tetrahedralization.mutable_points();
  DTLAB_ASSERT(points.size() == input.points.size());
  std::vector<std::uint32_t> order = brio_order_of_sorted(input.distinct, input.seed);
  const std::size_t m = order.size();

  // The first tetrahedron: the first two points, the first one off their line, the first one
  // off their plane, moved to the front of the order.
  const auto simplex = first_simplex(input.points, order);
  DTLAB_ASSERT(m >= 4 && simplex[3] < m);
  std::swap(order[2], order[simplex[2]]);
  std::swap(order[3], order[simplex[3]]);
  // The coordinates in insertion order, in place (input.points may be this very array, see
  // registry.hpp); the duplicates, never inserted, go after the distinct points.
  if (input.duplicates.size() + m != points.size())
    throw InternalError("incremental 3D Delaunay: distinct and duplicate points do not partition the input");
  order.insert(order.end(), input.duplicates.begin(), input.duplicates.end());
  permute_in_place(std::span<Vec3>(points), order);
  const Sign orientation = orient3d(points[0], points[1], points[2], points[3]);
  DTLAB_ASSERT(orientation != Sign::Zero);

  std::vector<T3::Record>& records = tetrahedralization.mutable_records();
  tetrahedralization.clear_tetrahedra();
  // About 6.7 tetrahedra per point for uniform points; memory reserved but never written costs
  // nothing, so reserve above that.
  tetrahedralization.reserve_tetrahedra(std::min<std::size_t>(7 * m + m / 2 + 64, T3::kMaxTetrahedra));

  Inserter inserter(points.data(), m, records);
  if (orientation == Sign::Positive) {
    inserter.start(0, 1, 2, 3);
  } else {
    inserter.start(0, 1, 3, 2);
  }
  for (std::size_t r = 4; r < m; ++r) inserter.insert(static_cast<std::uint32_t>(r));
  inserter.finish();

  // Back to input ids and input order.
  for (T3::Record& r : records)
    for (std::uint32_t& v : r.vertex)
      if (v != kInf) v = order[v];
  unpermute_in_place(std::span<Vec3>(points), order);
}

}  // namespace dtlab
