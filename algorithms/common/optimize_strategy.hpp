// The round loop of the optimization strategy (book §8.6.3), written once for 2D and 3D: each
// round the dimension's operators in their sequence, by name from its registry, then a scan of
// the quality; rounds repeat while one improves the worst or the mean Q_K by `round_improvement`
// (relative) or changes the sizes, until a goal is met or max_rounds. The operators and their
// registries stay in optimize2d/ and optimize3d/ (registry.hpp).
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "algorithms/common/element_estimate.hpp"
#include "algorithms/common/registry.hpp"
#include "kernel/interrupt.hpp"

namespace dtlab {

// What the rounds read in every dimension, with the dimension's defaults of max_rounds and
// bad_quality; Optimize2dOptions and Optimize3dOptions add their operators' options.
template <class Defaults>  // Defaults::kMaxRounds, Defaults::kBadQuality (a double template
                           // argument would need clang 18)
struct OptimizeRoundOptions {
  std::uint32_t max_rounds = Defaults::kMaxRounds;
  // Another round while the worst or the mean Q_K drops by more than this, relative.
  double round_improvement = 1e-3;
  // Elements worse than this are treated one by one, worst first, at the start of each round.
  double bad_quality = Defaults::kBadQuality;
  bool swaps = true;
  bool relocation = true;
  std::uint32_t relocation_sweeps = 2;  // per round
  bool collapses = true;                // short edges (size) and needles (shape)
  bool splits = true;                   // long edges
  // A round's operators in order, names from the dimension's operator registry (registry.hpp);
  // empty: every operator of the registry in its order (the book's, as before the registries).
  std::vector<std::string> sequence{};
  // With splits toward a metric field, the elements it asks for are estimated before the first
  // round (element_estimate.hpp) and refused past this: 0, half this machine's memory at the
  // bytes an element costs; element_estimate::kNoElementLimit, no estimate (a mesher that made it).
  std::uint64_t max_elements = 0;
  // Asked before each round and each pass of a round (kernel/interrupt.hpp); yes: Interrupted.
  InterruptCheck interrupt{};
};

// What the rounds report in every dimension (Optimize2dStats and Optimize3dStats add the counts
// of their operators and elements). Q_K over the domain's elements (kernel/quality.hpp, in the
// vertex metrics); the mean over the finite values.
struct OptimizeRoundStats {
  std::uint32_t rounds = 0;
  double worst_before = 0.0, mean_before = 0.0;
  double worst_after = 0.0, mean_after = 0.0;
  std::uint64_t vertices_before = 0, vertices_after = 0;  // live
  // Why the rounds ended: "converged" (no further improvement), "goal" (3D), "max_rounds",
  // "swap_limit" or "vertex_limit" (a pass stopped at its bound; the mesh is valid all the same).
  std::string stopped_by;
  double seconds = 0.0;
};

// What one operator's pass tells the round: its size changes (collapses, splits), and whether it
// stopped at its bound (it then names the bound in stats.stopped_by; the round goes on, the rounds
// end after it).
struct OperatorResult {
  std::uint64_t size_changes = 0;
  bool limit = false;
};

// The registries' size operators, alike in both dimensions (optimize2d/registry.cpp,
// optimize3d/registry.cpp): `pass()` applies the operator once and returns its count, added to
// `count`; the relocation's sweeps repeat until one moves no vertex.
template <class Pass>
OperatorResult size_operator(bool enabled, std::uint64_t& count, const Pass& pass) {
  if (!enabled) return {};
  const std::uint64_t c = pass();
  count += c;
  return {c};
}
template <class Options, class Stats, class Sweep>
OperatorResult relocation_sweeps(const Options& options, Stats& stats, const Sweep& sweep) {
  for (std::uint32_t k = 0; options.relocation && k < options.relocation_sweeps; ++k) {
    const std::uint64_t moved = sweep();
    stats.relocations += moved;
    if (moved == 0) break;
  }
  return {};
}
inline constexpr std::string_view kCollapseDescription =
    "collapses of the edges shorter than 1/sqrt2 in the metric, shortest first (§8.3.5; collapse.cpp)";
inline constexpr std::string_view kSplitDescription =
    "splits of the edges longer than sqrt2, longest first, each followed by swaps (§8.3.6; split.cpp)";

namespace optimize_detail {

// The entries of `registry` named by `sequence` in its order (empty: all of them); InputError
// naming an unknown one and the known ones.
template <class Entry>
std::vector<Entry> operator_sequence(const Registry<Entry>& registry, std::span<const std::string> sequence) {
  if (sequence.empty()) return {registry.begin(), registry.end()};
  std::vector<Entry> out;
  for (const std::string& name : sequence) out.push_back(registry.at(name));
  return out;
}

// A round's operators in order, each run by `pass(entry)`, the interrupt polled after each
// ("<what>: after the <name> pass"): their size changes summed, and whether one reached its bound.
template <class Entry, class Pass>
OperatorResult run_operators(std::span<const Entry> operators, const InterruptCheck& interrupt, const char* what,
                             Pass pass) {
  OperatorResult round;
  for (const Entry& op : operators) {
    const OperatorResult r = pass(op);
    round.size_changes += r.size_changes;
    round.limit = round.limit || r.limit;
    if (interrupt && interrupt())
      throw Interrupted(std::string(what) + ": after the " + std::string(op.name) + " pass");
  }
  return round;
}

// A round's operators: the sizes changed (more than the dimension ignores), a pass stopped at
// its bound (and named it in stopped_by).
struct RoundResult {
  bool resized = false, limit = false;
};
// A round's goal: improved whatever the worst and the mean did, met (stop after this round).
struct RoundGoal {
  bool gained = false, met = false;
};

// The domain's elements among `capacity` slots with `quality(t)` above bad_quality, worst first
// (ties by slot), with their `vertices(t)` then (an earlier treatment may change the slot): the
// order in which a round treats them one by one.
template <class Vertices>
struct BadElement {
  double quality;
  std::uint32_t t;
  Vertices v;
};
template <class Mesh, class Quality, class Vertices>
auto bad_elements(const Mesh& mesh, std::uint32_t capacity, double bad_quality, Quality quality, Vertices vertices) {
  std::vector<BadElement<decltype(vertices(0u))>> bad;
  for (std::uint32_t t = 0; t < capacity; ++t) {
    if (!mesh.in_domain(t)) continue;
    const double q = quality(t);
    if (q > bad_quality) bad.push_back({q, t, vertices(t)});
  }
  std::sort(bad.begin(), bad.end(), [](const auto& x, const auto& y) {
    return x.quality > y.quality || (x.quality == y.quality && x.t < y.t);
  });
  return bad;
}

// What a run of the rounds works on: each dimension's policy derives from it.
template <class Mesh, class Options, class Field, class Stats>
struct RoundState {
  Mesh& mesh;
  const Options& options;  // an OptimizeRoundOptions
  const Field& field;
  Stats stats{};           // an OptimizeRoundStats, returned at the end
};

// The rounds. `Dim` derives from RoundState, names the point of an interrupt at the start of a
// round `kRoundStart` and its name in messages `kName`, and provides (its Summary has `worst` and `mean`):
//   Summary scan()                                      the quality before the rounds and after each;
//   RoundResult round(uint32_t r, const Summary& last)  round r's operators (run_operators);
//   RoundGoal goal(const Summary& now)                  asked once after each round's scan;
//   void finish(const Summary& before, Summary& last)   after the rounds (may change the mesh and
//                                                       `last`): the element counts into the stats.
template <class Dim>
auto optimize_rounds(Dim&& dim) {
  const auto start = std::chrono::steady_clock::now();
  const auto& options = dim.options;
  auto& stats = dim.stats;
  if (dim.field && options.splits) {
    element_estimate::check_elements(
        dim.kName, dim.mesh, [&](const auto& p) { return dim.field(p); }, options.max_elements);
  }
  const auto before = dim.scan();
  stats.worst_before = before.worst;
  stats.mean_before = before.mean;
  stats.vertices_before = dim.mesh.live_vertex_count();
  auto last = before;
  stats.stopped_by = "max_rounds";
  for (std::uint32_t round = 0; round < options.max_rounds; ++round) {
    poll_interrupt(options.interrupt, dim.kRoundStart);
    ++stats.rounds;
    const RoundResult r = dim.round(round, last);
    const auto now = dim.scan();
    const RoundGoal goal = dim.goal(now);
    const double keep = 1.0 - options.round_improvement;
    const bool improved = goal.gained || now.worst < last.worst * keep || now.mean < last.mean * keep;
    last = now;
    if (r.limit) break;
    if (goal.met || (!improved && !r.resized)) {
      stats.stopped_by = goal.met ? "goal" : "converged";
      break;
    }
  }
  dim.finish(before, last);
  stats.worst_after = last.worst;
  stats.mean_after = last.mean;
  stats.vertices_after = dim.mesh.live_vertex_count();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return std::move(stats);
}

}  // namespace optimize_detail
}  // namespace dtlab
