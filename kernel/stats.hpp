// Per-stage counters of the filtered predicates: how often each stage decided.
//
// Each thread counts into its own block (no atomics, no sharing), so the counters stay on in
// every build; one increment per call is their whole cost (bench/predicates_bench.cpp measures
// it against the uncounted predicates). An algorithm that runs threads sums their snapshots.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace dtlab {

enum class Predicate : std::uint8_t { Orient2d, Incircle, Orient3d, Insphere };
inline constexpr std::size_t kPredicateCount = 4;
const char* to_string(Predicate p) noexcept;

struct StageCounts {
  std::uint64_t semistatic = 0;  // decided by the semi-static filter
  std::uint64_t adaptive = 0;    // decided by the dynamic (expansion) stage
  std::uint64_t exact = 0;       // decided by an exact stage: expansions (stage 3) or GMP
  std::uint64_t perturbed = 0;   // exact zero resolved by the symbolic perturbation
  std::uint64_t gmp = 0;         // of the `exact` ones, those that needed GMP (stage 4)

  std::uint64_t calls() const noexcept { return semistatic + adaptive + exact; }
  StageCounts& operator+=(const StageCounts& o) noexcept;
  StageCounts& operator-=(const StageCounts& o) noexcept;
};

struct PredicateStats {
  std::array<StageCounts, kPredicateCount> counts{};

  StageCounts& operator[](Predicate p) noexcept { return counts[static_cast<std::size_t>(p)]; }
  const StageCounts& operator[](Predicate p) const noexcept { return counts[static_cast<std::size_t>(p)]; }
  StageCounts total() const noexcept;
  PredicateStats& operator+=(const PredicateStats& o) noexcept;
  PredicateStats& operator-=(const PredicateStats& o) noexcept;
  friend PredicateStats operator-(PredicateStats a, const PredicateStats& b) noexcept { return a -= b; }

  // {"orient2d":{"semistatic":..,"adaptive":..,"exact":..,"perturbed":..,"gmp":..}, ...}
  // semistatic + adaptive + exact = calls; perturbed and gmp count subsets of those.
  std::string to_json() const;
};

namespace detail {
inline thread_local PredicateStats tls_predicate_stats;
}

// This thread's counters since it started (or since the last reset).
inline const PredicateStats& predicate_stats() noexcept { return detail::tls_predicate_stats; }
inline void reset_predicate_stats() noexcept { detail::tls_predicate_stats = {}; }
// Adds counts made on other threads (a parallel algorithm's workers) to this thread's.
inline void add_predicate_stats(const PredicateStats& counts) noexcept { detail::tls_predicate_stats += counts; }

}  // namespace dtlab
