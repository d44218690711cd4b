#include "algorithms/delaunay3d/cavity_kernel.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "algorithms/permute_in_place.hpp"
#include "algorithms/spatial_sort.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "kernel/predicates/facet_batch.hpp"
#include "mesh/memory_hints.hpp"

namespace dtlab {

namespace {

using T3 = Tetrahedralization3;
constexpr std::uint32_t kInf = T3::kInfinite;
constexpr std::uint32_t kNone = T3::kNone;
constexpr auto kFacet = T3::kFacetVertex;

// Marks live in the two top bits of vertex 3, which is never kInfinite and, below kMaxPoints,
// never uses them: the mark is read with the vertices, in the same cache line. A tetrahedron on
// a free list has vertex 0 = kNone. A restricted kernel marks only tetrahedra it owns.
constexpr std::uint32_t kInCavity = 0x80000000u;
constexpr std::uint32_t kOutside = 0x40000000u;
constexpr std::uint32_t kMarks = kInCavity | kOutside;
static_assert(T3::kMaxPoints < kOutside);

// The facet batches (facet_batch.hpp) list the facets as the tetrahedralization does.
constexpr bool same_facet_rows() {
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      if (kFacet[i][j] != kFacetRows[i][j]) return false;
  return true;
}
static_assert(same_facet_rows());

}  // namespace

CavityKernel::CavityKernel(const Vec3* points, std::vector<Record>& records) : p_(points), records_(records) {
  refresh_views();
  cavity_.reserve(256);
  boundary_.reserve(512);
  free_.reserve(1024);
}

void CavityKernel::start(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  DTLAB_ASSERT(records_.empty() && !restricted_);
  const std::uint32_t v[4] = {a, b, c, d};
  for (std::uint32_t t = 0; t < 5; ++t) DTLAB_ASSERT(new_slot() == t);
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

bool CavityKernel::insert(std::uint32_t p) { return restricted_ ? insert_as<true>(p) : insert_as<false>(p); }

template <bool Restricted>
bool CavityKernel::insert_as(std::uint32_t p) {
  // Abandoned, the next walk starts from as close to p as this one got: along the Hilbert
  // curve, the next point is near, and the way round an unowned region follows the curve.
  std::uint32_t stopped = kNone;
  const std::uint32_t base = walk<Restricted>(p, &stopped);
  if (base == kNone) {
    last_ = stopped;
    return false;
  }
  if (!grow_cavity<Restricted>(base, p)) {
    clear_marks();
    last_ = base;
    return false;
  }
  // A restricted kernel cannot grow the shared records: it checks its slots before writing.
  if (Restricted && boundary_.size() > cavity_.size() + spare_slots()) {
    clear_marks();
    return false;
  }
  fill_ball(p);
  return true;
}

void CavityKernel::give_slots(std::uint32_t begin, std::uint32_t end) {
  DTLAB_ASSERT(begin <= end && end <= records_.size());
  // The rest of the old chunk becomes free slots, each written once: its pages not yet faulted in
  // are, in one call (after a parallel round, a kernel that deferred many points hands back
  // hundreds of thousands of slots never touched).
  const std::size_t unpopulated = std::max(chunk_next_, populated_);
  if (unpopulated < chunk_end_) populate_for_writing(records_.data() + unpopulated, records_.data() + chunk_end_);
  for (std::size_t s = chunk_next_; s < chunk_end_; ++s) {
    records_[s].vertex[0] = kNone;
    free_.push_back(static_cast<std::uint32_t>(s));
  }
  chunk_next_ = begin, chunk_end_ = end;
}

void CavityKernel::release_slots(std::vector<std::uint32_t>& dead) {
  give_slots(0, 0);
  dead.insert(dead.end(), free_.begin(), free_.end());
  free_.clear();
}

// k more fresh slots at the end of the records. The array's size runs ahead by chunks, so that
// most new slots only count; its capacity grows by a quarter when exhausted, so that a regrowth
// costs little peak memory (the caller reserves the expected size up front).
void CavityKernel::grow_chunk(std::size_t k) {
  DTLAB_ASSERT(!restricted_);
  const std::size_t begin = records_.size();
  if (begin + k > T3::kMaxTetrahedra)  // a size limit of the input, not a bug
    throw InputError("the Delaunay tetrahedralization of these points needs more than " +
                     std::to_string(T3::kMaxTetrahedra) + " tetrahedra (32-bit facet handles)");
  const std::size_t chunk = std::clamp(begin / 8, kMinChunk, kChunk);
  const std::size_t size = std::min<std::size_t>(begin + std::max(k, chunk), T3::kMaxTetrahedra);
  if (size > records_.capacity()) records_.reserve(std::max(size, records_.capacity() + records_.capacity() / 4));
  records_.resize(size);  // writes nothing (Tetrahedralization3::Record)
  refresh_views();
  give_slots(static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(size));
}

void CavityKernel::refresh_views() noexcept {
  if (records_.data() != r_) populated_ = 0;  // a new array: its fresh end is not faulted in
  r_ = records_.data(), slot_count_ = records_.size();
}

// A slot for a new tetrahedron: a recycled one, else a fresh one.
std::uint32_t CavityKernel::new_slot() {
  if (!free_.empty()) {
    const std::uint32_t t = free_.back();
    free_.pop_back();
    return t;
  }
  if (chunk_next_ == chunk_end_) grow_chunk(1);
  if (chunk_next_ >= populated_) populate_ahead();
  return static_cast<std::uint32_t>(chunk_next_++);
}

// Fresh slots are about to be written: fault their pages in, kPopulateAhead records at a time, in
// one call each instead of one page fault a page (memory_hints.hpp). Unrestricted, up to the
// array's capacity, which it grows into; restricted, within its own chunk, on its own thread: the
// first touch of a parallel round's fresh memory is shared out as the insertions are. Only speed
// depends on it.
void CavityKernel::populate_ahead() noexcept {
  const std::size_t limit = restricted_ ? chunk_end_ : records_.capacity();
  const std::size_t until = std::min(limit, chunk_next_ + kPopulateAhead);
  populate_for_writing(r_ + chunk_next_, r_ + until);
  populated_ = until;
}

std::uint32_t CavityKernel::apex(std::uint32_t h) const noexcept {
  const std::uint32_t i = h & 3u;
  const std::uint32_t v = r_[h >> 2].vertex[i];
  return i == 3 ? v & ~kMarks : v;
}

bool CavityKernel::same_vertices(std::uint32_t g, std::uint32_t h) const noexcept {
  std::array<std::uint32_t, 3> a, b;
  for (std::uint32_t k = 0; k < 3; ++k) {
    a[k] = r_[g >> 2].vertex[kFacet[g & 3u][k]];
    b[k] = r_[h >> 2].vertex[kFacet[h & 3u][k]];
  }
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

// See the file comment of the header for the coplanar case.
bool CavityKernel::conflicts(std::uint32_t t, const Vec3& p) const noexcept {
  const std::uint32_t* v = r_[t].vertex.data();
  if (v[0] != kInf)
    return insphere_perturbed_bounded(p_[v[0]], p_[v[1]], p_[v[2]], p_[v[3]], p, bounds_.insphere) == Sign::Positive;
  const Sign side = orient3d_bounded(p, p_[v[1]], p_[v[2]], p_[v[3]], bounds_.orient3d);
  if (side != Sign::Zero) return side == Sign::Positive;
  // The finite tetrahedron across the hull facet (it may carry a mark).
  const std::uint32_t* w = r_[r_[t].neighbour[0] >> 2].vertex.data();
  return insphere_perturbed_bounded(p_[w[0]], p_[w[1]], p_[w[2]], p_[w[3] & ~kMarks], p, bounds_.insphere) ==
         Sign::Positive;
}

// Visibility walk from last_ to a tetrahedron in conflict with p: a finite one whose closed
// region holds p (p is then strictly inside its sphere: p is no vertex), or a ghost whose hull
// facet p is strictly beyond. Any facet with p strictly behind it may be crossed: the walk
// cannot cycle whichever it takes, since no "in front of" cycle exists with respect to p
// (Edelsbrunner 1990). Restricted, last_ is owned, the walk crosses only into tetrahedra it owns
// (checking the one vertex a neighbour adds to the facet crossed), and where it can go no
// further it gives kNone and, in *stopped, the owned tetrahedron it reached.
std::uint32_t CavityKernel::locate(std::uint32_t p, std::uint32_t* stopped) const {
  return restricted_ ? walk<true>(p, stopped) : walk<false>(p, stopped);
}

template <bool Restricted>
std::uint32_t CavityKernel::walk(std::uint32_t pid, std::uint32_t* stopped) const {
  const Vec3& p = p_[pid];
  std::uint32_t t = last_;
  if (r_[t].vertex[0] == kInf) {
    const std::uint32_t h = r_[t].neighbour[0];
    if (!owns_apex<Restricted>(h)) {
      if (stopped != nullptr) *stopped = t;
      return kNone;
    }
    t = h >> 2;
  }
  std::uint32_t entered = 4;  // the facet of t the walk came in through (4: none)
  for (std::size_t steps = 0; steps <= slot_count_; ++steps) {
    const std::array<std::uint32_t, 4> v = r_[t].vertex;
    if (v[0] == kInf) return t;  // entered across its hull facet: p is strictly beyond it
    // The facets not entered through, tested together (facet_batch.hpp); the first one p is
    // beyond, in the order below, is crossed.
    const OrientBatch batch = orient3d_static_facets(p_, v, 0xFu & ~(1u << entered), p, bounds_.orient3d);
    std::uint32_t next = kNone;
    bool blocked = false;
    for (std::uint32_t k = 1; k <= 4; ++k) {
      const std::uint32_t i = (entered + k) & 3u;
      if (i == entered) continue;
      const auto& f = kFacet[i];
      const unsigned bit = 1u << i;
      if ((batch.undecided & bit) ? orient3d_bounded(p_[v[f[0]]], p_[v[f[1]]], p_[v[f[2]]], p, bounds_.orient3d) ==
                                        Sign::Negative
                                  : (batch.negative & bit) != 0) {
        if (!owns_apex<Restricted>(r_[t].neighbour[i])) {
          blocked = true;
          continue;
        }
        next = r_[t].neighbour[i];
        break;
      }
    }
    if (next == kNone) {
      if (!blocked) return t;
      if (stopped != nullptr) *stopped = t;
      return kNone;
    }
    t = next >> 2, entered = next & 3u;
  }
  throw InternalError("3D Delaunay kernel: the walk to point (rank " + std::to_string(pid) +
                      ") exceeded its bound of " + std::to_string(slot_count_) + " steps");
}

// Neighbours are cache misses more often than not: ask for them when t enters the queue, so
// that they have arrived when t is processed.
inline void CavityKernel::enter_cavity(std::uint32_t t) noexcept {
  r_[t].vertex[3] |= kInCavity;
  cavity_.push_back(t);
  for (std::uint32_t i = 0; i < 4; ++i) __builtin_prefetch(r_ + (r_[t].neighbour[i] >> 2));
}

// C_P by breadth-first search from the base over adjacency (the cavity is connected). Every
// facet of a cavity tetrahedron is looked at once, so the boundary facets come out on the way,
// each as the cavity tetrahedron lists it (counter-clockwise seen from P). Restricted: false as
// soon as a tetrahedron in conflict is not owned; a neighbour not owned is not marked (it may
// be tested again through another facet, with the same answer).
template <bool Restricted>
bool CavityKernel::grow_cavity(std::uint32_t base, std::uint32_t pid) {
  const Vec3& p = p_[pid];
  Record* const r = r_;
  cavity_.clear();
  boundary_.clear();
  enter_cavity(base);
  for (std::size_t k = 0; k < cavity_.size(); ++k) {
    const std::uint32_t t = cavity_[k];
    const std::array<std::uint32_t, 4> outer = r[t].neighbour;
    const std::array<std::uint32_t, 4> v = {r[t].vertex[0], r[t].vertex[1], r[t].vertex[2],
                                            r[t].vertex[3] & ~kMarks};
    // The unmarked finite neighbours of a finite t are tested together (facet_batch.hpp): no
    // two facets of t share a neighbour, so marking one cannot change another's answer.
    std::array<std::uint32_t, 4> mark, apex;
    unsigned batched = 0;  // bit i: neighbour i is tested in the batch
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t* w = r[outer[i] >> 2].vertex.data();
      mark[i] = w[3] & kMarks;
      apex[i] = w[outer[i] & 3u];  // unmarked, so vertex 3 carries no mark
      if (mark[i] == 0 && w[0] != kInf) batched |= 1u << i;
    }
    if (v[0] == kInf) batched = 0;
    const InsphereBatch batch = batched == 0 ? InsphereBatch{}
                                             : insphere_static_across_facets(p_, v, apex, batched, p, bounds_.insphere);
#pragma GCC unroll 4
    for (std::uint32_t i = 0; i < 4; ++i) {
      if (mark[i] == kInCavity) continue;
      const std::uint32_t u = outer[i] >> 2;
      if (mark[i] == 0) {
        const unsigned bit = 1u << i;
        const bool conflict =
            (batched & bit) && !(batch.undecided & bit) ? (batch.positive & bit) != 0 : conflicts(u, p);
        if (conflict) {
          if (!owns_apex<Restricted>(outer[i])) return false;
          enter_cavity(u);
          continue;
        }
        if (owns_apex<Restricted>(outer[i])) r[u].vertex[3] |= kOutside;  // cleared when B_P links to it
      }
      const auto& f = kFacet[i];
      boundary_.push_back({{v[f[0]], v[f[1]], v[f[2]]}, outer[i]});
    }
  }
  return true;
}

// Undoes grow_cavity's marks: every tetrahedron marked outside is behind a boundary facet.
void CavityKernel::clear_marks() noexcept {
  for (const std::uint32_t t : cavity_) r_[t].vertex[3] &= ~kMarks;
  for (const BoundaryFacet& b : boundary_) {
    std::uint32_t& outer_mark = r_[b.outer >> 2].vertex[3];
    if (outer_mark & kMarks) outer_mark &= ~kMarks;
  }
}

// B_P: one tetrahedron (f0, f1, f2, P) per boundary facet, in the cavity's slots first. A
// facet through kInfinite lists it first (ghosts keep it at index 0 and every facet of a
// ghost that holds it starts with it), so the new tetrahedron is a ghost in normal form.
//
// Facets 0, 1, 2 of the new tetrahedra link among themselves: facet k holds P and the boundary
// edge x(k+1) -> x(k+2); the neighbour across it is the new tetrahedron whose boundary facet
// holds the same edge reversed. The boundary vertices get small local numbers, and a table
// indexed by (from, to) finds the reversed edge; the numbering and the table are filled in the
// same pass that writes the tetrahedra.
void CavityKernel::fill_ball(std::uint32_t p) {
  const std::size_t faces = boundary_.size();
  const std::size_t cavity_size = cavity_.size();
  // The boundary is a triangulated sphere: F = 2V - 4 (Euler), so a small F fits the table.
  const bool small = faces / 2 + 2 <= kTableSide;
  new_tetrahedra_.resize(faces);
  for (std::size_t j = 0; j < faces; ++j) {
    const std::uint32_t t = j < cavity_size ? cavity_[j] : new_slot();
    const BoundaryFacet& b = boundary_[j];
    Record& rt = r_[t];
    rt.vertex = {b.v[0], b.v[1], b.v[2], p};
    rt.neighbour[3] = b.outer;
    // Only marked tetrahedra are written: one not owned is left untouched.
    Record& outer = r_[b.outer >> 2];
    outer.neighbour[b.outer & 3u] = 4 * t + 3;
    if (outer.vertex[3] & kMarks) outer.vertex[3] &= ~kMarks;
    new_tetrahedra_[j] = t;
    if (small) {
      const std::array<std::uint8_t, 3> l = {local_number(b.v[0]), local_number(b.v[1]), local_number(b.v[2])};
      locals_[j] = l;
      edge_table_[l[1] * kTableSide + l[2]] = 4 * t + 0;
      edge_table_[l[2] * kTableSide + l[0]] = 4 * t + 1;
      edge_table_[l[0] * kTableSide + l[1]] = 4 * t + 2;
    }
  }
  for (std::size_t j = faces; j < cavity_size; ++j) {
    r_[cavity_[j]].vertex[0] = kNone;
    free_.push_back(cavity_[j]);
  }
  if (small) {
    link_ball_by_edges();
  } else {
    link_large_ball();
  }
  last_ = new_tetrahedra_[0];
  for (const std::uint32_t t : new_tetrahedra_)
    if (r_[t].vertex[0] != kInf) {
      last_ = t;
      break;
    }
}

// local_number's slot for the infinite vertex or a vertex beyond local_of_ (which grows).
std::uint8_t* CavityKernel::far_local_slot(std::uint32_t v) {
  if (v == kInf) return &local_of_infinite_;
  local_of_.resize(std::max<std::size_t>(v + 1, 2 * local_of_.size()), 0);
  return &local_of_[v];
}

// The second half of fill_ball's linking: each new tetrahedron's facets 0, 1, 2 from the table.
void CavityKernel::link_ball_by_edges() {
  const std::size_t faces = new_tetrahedra_.size();
  DTLAB_ASSERT(faces == 2 * numbered_count_ - 4);  // so every local number is below kTableSide
  for (std::size_t j = 0; j < faces; ++j) {
    const std::uint32_t t = new_tetrahedra_[j];
    const auto& l = locals_[j];
    r_[t].neighbour[0] = edge_table_[l[2] * kTableSide + l[1]];
    r_[t].neighbour[1] = edge_table_[l[0] * kTableSide + l[2]];
    r_[t].neighbour[2] = edge_table_[l[1] * kTableSide + l[0]];
  }
  for (std::size_t k = 0; k < numbered_count_; ++k) {
    const std::uint32_t v = numbered_[k];
    (v == kInf ? local_of_infinite_ : local_of_[v]) = 0;
  }
  numbered_count_ = 0;
}

// The same matching by sorting the directed edges by vertex ids, for large balls.
void CavityKernel::link_large_ball() {
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

void compact_tetrahedra(std::vector<T3::Record>& records, std::vector<std::uint32_t>& dead) {
  std::sort(dead.begin(), dead.end());
  DTLAB_ASSERT(dead.size() <= records.size());
  const std::size_t live = records.size() - dead.size();
  std::size_t source = records.size();
  for (const std::uint32_t hole : dead) {
    if (hole >= live) break;
    do --source;
    while (records[source].vertex[0] == kNone);
    T3::Record& to = records[hole];
    to = records[source];
    for (std::uint32_t i = 0; i < 4; ++i) records[to.neighbour[i] >> 2].neighbour[to.neighbour[i] & 3u] = 4 * hole + i;
    records[source].vertex[0] = kNone;
  }
  dead.clear();
  records.resize(live);
}

InsertionOrder::InsertionOrder(const PreparedPoints3& input, WorkerTeam* team, bool find_runs) {
  BrioOrder brio = brio_order_of_sorted(input.distinct, input.seed, team, find_runs);
  order_ = std::move(brio.ids);
  distinct_ = order_.size();
  // The first tetrahedron: the first two points, the first one off their line, the first one
  // off their plane, moved to the front of the order.
  const auto simplex = first_simplex(input.points, order_);
  DTLAB_ASSERT(distinct_ >= 4 && simplex[3] < distinct_);
  for (const std::size_t k : {std::size_t{2}, std::size_t{3}}) {
    std::swap(order_[k], order_[simplex[k]]);
    if (find_runs) std::swap(brio.ranks[k], brio.ranks[simplex[k]]);
  }
  if (find_runs) {
    // The runs of increasing Hilbert rank after the first simplex: the BRIO rounds, some split
    // by the swaps above.
    for (std::size_t r = 5; r < distinct_; ++r)
      if (brio.ranks[r] < brio.ranks[r - 1]) run_ends_.push_back(static_cast<std::uint32_t>(r));
    run_ends_.push_back(static_cast<std::uint32_t>(distinct_));
  }
  if (input.duplicates.size() + distinct_ != input.points.size())
    throw InternalError("3D Delaunay kernel: distinct and duplicate points do not partition the input");
  order_.insert(order_.end(), input.duplicates.begin(), input.duplicates.end());
}

void InsertionOrder::reorder(std::vector<Vec3>& points, WorkerTeam* team) {
  DTLAB_ASSERT(points.size() == order_.size());
  permute_in_place(std::span<Vec3>(points), order_, team);
  const Sign orientation = orient3d(points[0], points[1], points[2], points[3]);
  DTLAB_ASSERT(orientation != Sign::Zero);
  positive_ = orientation == Sign::Positive;
}

void InsertionOrder::restore(std::vector<Vec3>& points, std::vector<T3::Record>& records, WorkerTeam* team) && {
  for_each_share(team, records.size(), [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
      for (std::uint32_t& v : records[t].vertex)
        if (v != kInf) v = order_[v];
  });
  // The point of rank r goes back to position order_[r]; order_ is spent doing it (no scratch
  // while the mesh is at its largest).
  move_to_destinations(std::span<Vec3>(points), std::span<std::uint32_t>(order_), team);
  order_.clear();
}

}  // namespace dtlab
