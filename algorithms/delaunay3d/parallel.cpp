// Variant "parallel": the Delaunay kernel (cavity_kernel.hpp) run by several threads at once, as
// in Marot, Pellerin, Remacle, "One machine, one minute, three billion tetrahedra" (IJNME 2019).
// Points go in by BRIO rounds, each in Hilbert order. Each round is cut into one slab of space per
// thread (equal counts of the round's points); a thread inserts its slab's points and touches only
// tetrahedra whose vertices all lie in its slab, and defers an insertion that would leave it. The
// deferred points, which lie near the cuts, are tried again with slabs across the next axis (x,
// then y, then z), so new cuts cross old ones instead of running along them; what still fails
// goes in sequentially. The result is the unique perturbed Delaunay tetrahedralization, the same
// as "incremental"'s; for a given thread count the run, and so the storage order, is
// deterministic (during a sub-round no thread reads a word that another writes).
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/delaunay3d/cavity_kernel.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "kernel/error.hpp"
#include "kernel/stats.hpp"
#include "kernel/worker_team.hpp"
#include "mesh/memory_hints.hpp"
#include "mesh/tetrahedralization3.hpp"
#include "mesh/uninitialized_vector.hpp"

namespace dtlab {

void delaunay3d_incremental(PreparedPoints3& input, const Delaunay3dOptions& options,
                            Tetrahedralization3& tetrahedralization);

namespace {

using T3 = Tetrahedralization3;
constexpr std::uint32_t kNone = T3::kNone;
constexpr std::uint32_t kDone = kNone;  // a pending point that went in

// The axes of the successive sub-rounds of a round.
constexpr std::array<double Vec3::*, 3> kAxes = {&Vec3::x, &Vec3::y, &Vec3::z};
// Fewer pending points per thread than this, or a sub-round that inserts less than a quarter of
// its points: the rest goes in sequentially.
constexpr std::size_t kMinPointsPerThread = 8;
// Points sampled for the slab cuts.
constexpr std::size_t kQuantileSample = 16384;

class ParallelInsertion {
 public:
  // Vertex ids below `vertices`, all among points [0, vertices).
  // One slab, kernel and seed per thread (`threads`), run on `team` (which may have fewer).
  ParallelInsertion(const Vec3* points, std::size_t vertices, std::vector<T3::Record>& records, unsigned threads,
                    WorkerTeam& team)
      : p_(points), records_(records), threads_(threads), team_(team), shares_(threads), seeds_(threads) {
    kernels_.reserve(threads);
    const StaticBounds3 bounds = static_bounds3(std::span<const Vec3>(points, vertices));
    for (unsigned k = 0; k < threads; ++k) {
      kernels_.emplace_back(points, records);
      kernels_.back().set_static_bounds(bounds);
      kernels_.back().reserve_vertices(vertices);
    }
  }

  void start(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    kernels_[0].start(a, b, c, d);
    inserted_ = 4;
  }

  // Room for runs of up to `points` points, its pages faulted in at once: grown run by run, the
  // lists' fresh pages were faulted in one at a time, dear on a virtual machine (0.08 s of the
  // one-thread work between sub-rounds at 10^7 points).
  void reserve_for_runs(std::size_t points) {
    pending_.reserve(points);
    populate_for_writing(pending_.data(), pending_.data() + points);
    const std::size_t share = points / threads_ + points / 64 + 64;  // the cuts balance a sample
    for (auto& list : shares_) {
      list.reserve(share);
      populate_for_writing(list.data(), list.data() + share);
    }
  }

  // Inserts the points of ranks [first, end), which are in Hilbert order.
  void insert_run(std::uint32_t first, std::uint32_t end) {
    pending_.resize(end - first);
    for (std::uint32_t r = first; r < end; ++r) pending_[r - first] = r;
    for (double Vec3::*axis : kAxes) {
      const std::size_t before = pending_.size();
      if (before < kMinPointsPerThread * threads_) break;
      sub_round(axis);
      std::erase(pending_, kDone);
      inserted_ += before - pending_.size();
      if (4 * (before - pending_.size()) < before) break;
    }
    CavityKernel& kernel = kernels_[0];
    kernel.refresh_views();
    kernel.lift_restriction();
    for (const std::uint32_t p : pending_)
      if (!kernel.insert(p)) throw InternalError("parallel 3D Delaunay: an unrestricted insertion was abandoned");
    inserted_ += pending_.size();
    pending_.clear();
  }

  void finish() {
    std::vector<std::uint32_t> dead;
    for (CavityKernel& kernel : kernels_) kernel.release_slots(dead);
    compact_tetrahedra(records_, dead);
  }

 private:
  void sub_round(double Vec3::*axis) {
    restart_dead_walks();
    const std::vector<SlabOwnership> slabs = cut_into_slabs(axis);
    deal_into_slabs(slabs);
    hand_out_slots();
    for (unsigned k = 0; k < threads_; ++k) {
      kernels_[k].refresh_views();
      kernels_[k].lift_restriction();
      find_seed(k, slabs[k]);
      kernels_[k].restrict_to(slabs[k]);
    }

    // Slab k's insertions on whichever thread of the team runs index k: the outcome depends only
    // on k (its kernel, slots and seed), never on the thread.
    std::vector<PredicateStats> stats(threads_);
    team_.run(threads_, [&](std::size_t k, unsigned worker) {
      if (seeds_[k] == kNone) return;
      const PredicateStats before = predicate_stats();
      CavityKernel& kernel = kernels_[k];
      kernel.set_last(seeds_[k]);
      // Each slab writes only its own entries of pending_.
      for (const std::uint32_t i : shares_[k])
        if (kernel.insert(pending_[i])) pending_[i] = kDone;
      if (worker != 0) stats[k] = predicate_stats() - before;  // the caller's thread counts its own
    });
    for (const PredicateStats& s : stats) add_predicate_stats(s);
    restart_dead_walks();
  }

  // shares_[k]: the positions in pending_ of slab k's points, in order. Counted and dealt in
  // shares of pending_ on the team (each share's points of slab k after the earlier shares'), so
  // the lists are the same for every team size.
  void deal_into_slabs(const std::vector<SlabOwnership>& slabs) {
    const auto slab_of = [&](std::uint32_t p) {
      unsigned k = 0;
      while (k + 1 < threads_ && !slabs[k].owns(p)) ++k;
      return k;
    };
    const std::size_t parts = shares(&team_);
    std::vector<std::size_t> next(parts * threads_, 0);  // [part * threads_ + slab]
    for_each_share(&team_, pending_.size(), [&](std::size_t part, std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) ++next[part * threads_ + slab_of(pending_[i])];
    });
    for (unsigned k = 0; k < threads_; ++k) {
      std::size_t at = 0;
      for (std::size_t part = 0; part < parts; ++part) at += std::exchange(next[part * threads_ + k], at);
      shares_[k].resize(at);
    }
    for_each_share(&team_, pending_.size(), [&](std::size_t part, std::size_t begin, std::size_t end) {
      std::size_t* at = &next[part * threads_];
      for (std::size_t i = begin; i < end; ++i) {
        const unsigned k = slab_of(pending_[i]);
        shares_[k][at[k]++] = static_cast<std::uint32_t>(i);
      }
    });
  }

  // One slab per thread across `axis`, cut at quantiles of the pending points' coordinates (of
  // an evenly spread sample of them: any cuts are correct, these only balance the work), the
  // outer two open to infinity: every vertex lies in exactly one.
  std::vector<SlabOwnership> cut_into_slabs(double Vec3::*axis) {
    const std::size_t stride = std::max<std::size_t>(1, pending_.size() / kQuantileSample);
    coordinates_.clear();
    for (std::size_t i = 0; i < pending_.size(); i += stride) coordinates_.push_back(p_[pending_[i]].*axis);
    std::vector<SlabOwnership> slabs(threads_, SlabOwnership{p_, axis, 0.0, 0.0});
    slabs.front().lo = -std::numeric_limits<double>::infinity();
    slabs.back().hi = std::numeric_limits<double>::infinity();
    auto from = coordinates_.begin();
    for (unsigned k = 1; k < threads_; ++k) {
      const auto at = coordinates_.begin() + static_cast<std::ptrdiff_t>(k * coordinates_.size() / threads_);
      std::nth_element(from, at, coordinates_.end());
      slabs[k - 1].hi = slabs[k].lo = *at;
      from = at;
    }
    return slabs;
  }

  // A kernel's last tetrahedron may have been deleted by another kernel since it was made:
  // restart such a kernel from a live one. Invariant between sub-rounds: every kernel's last
  // tetrahedron is alive, kernel 0's (the sequential one) always.
  void restart_dead_walks() {
    std::uint32_t alive = kNone;
    for (const CavityKernel& kernel : kernels_)
      if (records_[kernel.last()].vertex[0] != kNone) {
        alive = kernel.last();
        break;
      }
    DTLAB_ASSERT(alive != kNone);
    for (CavityKernel& kernel : kernels_)
      if (records_[kernel.last()].vertex[0] == kNone) kernel.set_last(alive);
  }

  // Each thread gets fresh slots for its share at the mesh's tetrahedra-per-point rate so far:
  // a thread that runs out defers, so the estimate only needs to be close, and slots handed out
  // but not used cost memory.
  void hand_out_slots() {
    std::size_t spare = 0;
    for (const CavityKernel& kernel : kernels_) spare += kernel.spare_slots();
    const double rate = static_cast<double>(records_.size() - spare) / static_cast<double>(inserted_);
    std::vector<std::size_t> give(threads_, 0);
    std::size_t total = 0;
    for (unsigned k = 0; k < threads_; ++k) {
      const auto need = static_cast<std::size_t>(rate * static_cast<double>(shares_[k].size())) + 64;
      give[k] = need > kernels_[k].spare_slots() ? need - kernels_[k].spare_slots() : 0;
      total += give[k];
    }
    std::size_t begin = records_.size();
    if (begin + total > T3::kMaxTetrahedra)
      throw InputError("the Delaunay tetrahedralization of these points needs more than " +
                       std::to_string(T3::kMaxTetrahedra) + " tetrahedra (32-bit facet handles)");
    if (begin + total > records_.capacity())
      records_.reserve(std::max(begin + total, records_.capacity() + records_.capacity() / 4));
    records_.resize(begin + total);  // writes nothing: each kernel faults its own slots in
    for (unsigned k = 0; k < threads_; ++k) {
      if (give[k] == 0) continue;
      kernels_[k].give_slots(static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(begin + give[k]));
      begin += give[k];
    }
  }

  // A tetrahedron thread k owns to start from: the base of one of its points, found by walking
  // (no thread runs). The candidates are its points 0, 1, 3, 7, 15, ...: the Hilbert curve may
  // run along the slab's side for a while before it turns inwards. The points before the one
  // found lie near the side and stay pending.
  void find_seed(unsigned k, const SlabOwnership& slab) {
    CavityKernel& kernel = kernels_[k];
    UninitializedVector<std::uint32_t>& share = shares_[k];
    seeds_[k] = kNone;
    for (std::size_t j = 0; j < share.size(); j = 2 * j + 1) {
      const std::uint32_t base = kernel.locate(pending_[share[j]]);
      kernel.set_last(base);
      if (slab.owns_all(records_[base].vertex)) {
        share.erase(share.begin(), share.begin() + static_cast<std::ptrdiff_t>(j));
        seeds_[k] = base;
        return;
      }
    }
  }

  const Vec3* p_;
  std::vector<T3::Record>& records_;
  unsigned threads_;
  WorkerTeam& team_;
  std::vector<CavityKernel> kernels_;
  UninitializedVector<std::uint32_t> pending_;               // insertion ranks, Hilbert order; kDone once in
  std::vector<UninitializedVector<std::uint32_t>> shares_;    // by thread: positions in pending_
  std::vector<std::uint32_t> seeds_;                  // by thread: where its walk starts
  std::vector<double> coordinates_;
  std::size_t inserted_ = 0;
};

}  // namespace

void delaunay3d_parallel(PreparedPoints3& input, const Delaunay3dOptions& options,
                         Tetrahedralization3& tetrahedralization) {
  if (options.threads <= 1) {
    delaunay3d_incremental(input, options, tetrahedralization);
    return;
  }
  std::vector<Vec3>& points = tetrahedralization.mutable_points();
  WorkerTeam team(options.threads);
  InsertionOrder order(input, &team, /*find_runs=*/true);
  input.release_distinct();  // 4 bytes a point off the peak
  order.reorder(points, &team);
  const std::size_t m = order.distinct_count();

  std::vector<T3::Record>& records = tetrahedralization.mutable_records();
  tetrahedralization.clear_tetrahedra();
  tetrahedralization.reserve_tetrahedra(std::min<std::size_t>(7 * m + m / 2 + 64, T3::kMaxTetrahedra));

  const unsigned threads = static_cast<unsigned>(std::min<std::size_t>(options.threads, m));
  ParallelInsertion insertion(points.data(), m, records, threads, team);
  if (order.first_simplex_positive()) {
    insertion.start(0, 1, 2, 3);
  } else {
    insertion.start(0, 1, 3, 2);
  }
  std::uint32_t first = 4;
  std::size_t longest = 0;
  for (const std::uint32_t end : order.run_ends()) longest = std::max<std::size_t>(longest, end - std::exchange(first, end));
  insertion.reserve_for_runs(longest);
  first = 4;
  // The BRIO rounds, as runs of increasing Hilbert rank.
  for (const std::uint32_t end : order.run_ends()) {
    insertion.insert_run(first, end);
    first = end;
  }
  insertion.finish();
  std::move(order).restore(points, records, &team);
}

}  // namespace dtlab
