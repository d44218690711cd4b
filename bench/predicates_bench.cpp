// Cost per call of the four predicates (orient2d, incircle, orient3d, insphere), in ns and
// items/s, on the named input distributions of predicate_inputs.hpp, for:
//   plain       the same determinant in doubles, no filter (not robust: the baseline);
//   filtered    dtlab's predicate as algorithms call it (stage counters on);
//   uncounted   the same without counters: filtered - uncounted is what counting costs;
//   semistatic, adaptive, expansion, exact   each stage alone (undecided share reported by the
//               filters; expansion is stage 3, exact is GMP);
//   cgal_epick  CGAL's Exact_predicates_inexact_constructions_kernel, same cases, same binary
//               (predicates_cgal.cpp, only when CGAL is found).
// and two consumers of the sign (sum: the predicate's own cost; branch: as a caller that
// branches on it pays it; see predicate_inputs.hpp).
// Every benchmark is named "<predicate>/<implementation>/<distribution>/<consumer>";
// scripts/bench_predicates_table.py turns a JSON run into the README's table.
#include <benchmark/benchmark.h>

#include <string>
#include <string_view>

#include "bench/predicate_inputs.hpp"
#include "dtlab/build_info.hpp"
#include "kernel/predicates.hpp"
#include "kernel/predicates/plain.hpp"

#if DTLAB_BENCH_WITH_CGAL
#include "bench/predicates_cgal.hpp"
#endif

namespace dtlab::bench {
namespace {


// The predicates as a caller uses them get both consumers; the stages alone only Sum.
template <class Case, class F>
void add(const char* predicate, const char* impl, Dist d, const std::vector<Case>& cases, F f) {
  const bool as_caller = std::string_view(impl) == "plain" || std::string_view(impl) == "filtered" ||
                         std::string_view(impl) == "uncounted";
  for (const Consumer consumer : {Consumer::Sum, Consumer::Branch}) {
    if (consumer == Consumer::Branch && !as_caller) continue;
    benchmark::RegisterBenchmark(
        bench_name(predicate, impl, d, consumer).c_str(),
        [&cases, consumer, f](benchmark::State& state) { run_cases(state, cases, consumer, f); });
  }
}

void register_orient2d(Dist d) {
  const auto& cs = orient2d_cases(d);
  using C = Orient2dCase;
  const char* p = "orient2d";
  add(p, "plain", d, cs, [](const C& t) { return plain::orient2d(t[0], t[1], t[2]); });
  add(p, "filtered", d, cs, [](const C& t) { return orient2d(t[0], t[1], t[2]); });
  add(p, "uncounted", d, cs, [](const C& t) { return uncounted::orient2d(t[0], t[1], t[2]); });
  add(p, "semistatic", d, cs, [](const C& t) { return stage::orient2d_semistatic(t[0], t[1], t[2]); });
  add(p, "adaptive", d, cs, [](const C& t) { return stage::orient2d_adaptive(t[0], t[1], t[2]); });
  add(p, "expansion", d, cs, [](const C& t) { return stage::orient2d_expansion(t[0], t[1], t[2]); });
  add(p, "exact", d, cs, [](const C& t) { return stage::orient2d_exact(t[0], t[1], t[2]); });
}

void register_incircle(Dist d) {
  const auto& cs = incircle_cases(d);
  using C = IncircleCase;
  const char* p = "incircle";
  add(p, "plain", d, cs, [](const C& t) { return plain::incircle(t[0], t[1], t[2], t[3]); });
  add(p, "filtered", d, cs, [](const C& t) { return incircle(t[0], t[1], t[2], t[3]); });
  add(p, "uncounted", d, cs, [](const C& t) { return uncounted::incircle(t[0], t[1], t[2], t[3]); });
  add(p, "semistatic", d, cs,
      [](const C& t) { return stage::incircle_semistatic(t[0], t[1], t[2], t[3]); });
  add(p, "adaptive", d, cs, [](const C& t) { return stage::incircle_adaptive(t[0], t[1], t[2], t[3]); });
  add(p, "expansion", d, cs, [](const C& t) { return stage::incircle_expansion(t[0], t[1], t[2], t[3]); });
  add(p, "exact", d, cs, [](const C& t) { return stage::incircle_exact(t[0], t[1], t[2], t[3]); });
}

void register_orient3d(Dist d) {
  const auto& cs = orient3d_cases(d);
  using C = Orient3dCase;
  const char* p = "orient3d";
  add(p, "plain", d, cs, [](const C& t) { return plain::orient3d(t[0], t[1], t[2], t[3]); });
  add(p, "filtered", d, cs, [](const C& t) { return orient3d(t[0], t[1], t[2], t[3]); });
  add(p, "uncounted", d, cs, [](const C& t) { return uncounted::orient3d(t[0], t[1], t[2], t[3]); });
  add(p, "semistatic", d, cs,
      [](const C& t) { return stage::orient3d_semistatic(t[0], t[1], t[2], t[3]); });
  add(p, "adaptive", d, cs, [](const C& t) { return stage::orient3d_adaptive(t[0], t[1], t[2], t[3]); });
  add(p, "expansion", d, cs, [](const C& t) { return stage::orient3d_expansion(t[0], t[1], t[2], t[3]); });
  add(p, "exact", d, cs, [](const C& t) { return stage::orient3d_exact(t[0], t[1], t[2], t[3]); });
}

void register_insphere(Dist d) {
  const auto& cs = insphere_cases(d);
  using C = InsphereCase;
  const char* p = "insphere";
  add(p, "plain", d, cs, [](const C& t) { return plain::insphere(t[0], t[1], t[2], t[3], t[4]); });
  add(p, "filtered", d, cs, [](const C& t) { return insphere(t[0], t[1], t[2], t[3], t[4]); });
  add(p, "uncounted", d, cs,
      [](const C& t) { return uncounted::insphere(t[0], t[1], t[2], t[3], t[4]); });
  add(p, "semistatic", d, cs,
      [](const C& t) { return stage::insphere_semistatic(t[0], t[1], t[2], t[3], t[4]); });
  add(p, "adaptive", d, cs,
      [](const C& t) { return stage::insphere_adaptive(t[0], t[1], t[2], t[3], t[4]); });
  add(p, "expansion", d, cs, [](const C& t) { return stage::insphere_expansion(t[0], t[1], t[2], t[3], t[4]); });
  add(p, "exact", d, cs, [](const C& t) { return stage::insphere_exact(t[0], t[1], t[2], t[3], t[4]); });
}

}  // namespace
}  // namespace dtlab::bench

int main(int argc, char** argv) {
  using namespace dtlab::bench;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("dtlab_commit", dtlab::build_info::kCommit);
  benchmark::AddCustomContext("compiler", dtlab::build_info::kCompiler);
  benchmark::AddCustomContext("build_type", dtlab::build_info::kBuildType);
  benchmark::AddCustomContext("flags", dtlab::build_info::kFlags);
  benchmark::AddCustomContext("cases_per_iteration", std::to_string(kCases));
#if DTLAB_BENCH_WITH_CGAL
  benchmark::AddCustomContext("cgal", cgal_version());
#endif
  // Grouped by predicate and distribution, CGAL beside dtlab.
  for (const Dist d : kDists) {
    register_orient2d(d);
#if DTLAB_BENCH_WITH_CGAL
    register_cgal_orient2d(d);
#endif
  }
  for (const Dist d : kDists) {
    register_incircle(d);
#if DTLAB_BENCH_WITH_CGAL
    register_cgal_incircle(d);
#endif
  }
  for (const Dist d : kDists) {
    register_orient3d(d);
#if DTLAB_BENCH_WITH_CGAL
    register_cgal_orient3d(d);
#endif
  }
  for (const Dist d : kDists) {
    register_insphere(d);
#if DTLAB_BENCH_WITH_CGAL
    register_cgal_insphere(d);
#endif
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
