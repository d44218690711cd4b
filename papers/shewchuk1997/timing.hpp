// Timed loops of papers/shewchuk1997: nanoseconds per call of a predicate over a fixed array of
// tuples, the minimum over repetitions, in this thread's CPU time (the machine may be shared, and
// CPU time does not charge us for the time another process held the core).
//
// The loop adds each sign to a checksum that is forced into a register after every call (the
// empty asm below, what Google Benchmark's DoNotOptimize does): the compiler can neither
// vectorise across tuples nor hoist work out of the loop, and nothing branches on the sign, so
// the time is the predicate's own (bench/predicate_inputs.hpp, consumer "sum").
#pragma once

#include <time.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "kernel/sign.hpp"

namespace dtlab::papers {

struct TimingBudget {
  int repetitions = 5;        // the minimum over these is reported
  double min_seconds = 0.05;  // each repetition repeats whole passes until it has run this long
};

inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <class T>
inline void keep_in_register(T& value) {
  __asm__ __volatile__("" : "+r"(value));
}

// Busy work for `seconds` of CPU time before the first timed loop: a core that has been idle runs
// at a low clock for a while, and the first predicate measured would pay for it.
inline void warm_up(double seconds) {
  const double start = thread_cpu_seconds();
  double x = 1.0;
  while (thread_cpu_seconds() - start < seconds)
    for (int i = 0; i < 100000; ++i) {
      x = x * 1.0000001 + 1e-9;
      keep_in_register(x);
    }
}

inline int score(Sign s) { return to_int(s); }
inline int score(FilteredSign s) { return s ? to_int(*s) : 0; }

// Nanoseconds per call of f over `cases` (at least one whole pass per repetition).
template <class Case, class F>
double ns_per_call(const std::vector<Case>& cases, const TimingBudget& budget, F f) {
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < budget.repetitions; ++r) {
    long checksum = 0;
    std::size_t calls = 0;
    const double start = thread_cpu_seconds();
    double elapsed = 0.0;
    do {
      for (const Case& c : cases) {
        checksum += score(f(c));
        keep_in_register(checksum);
      }
      calls += cases.size();
      elapsed = thread_cpu_seconds() - start;
    } while (elapsed < budget.min_seconds);
    best = std::min(best, 1e9 * elapsed / static_cast<double>(calls));
  }
  return best;
}

}  // namespace dtlab::papers
