// `dtlab selfcheck`: the kernel against exact rational arithmetic on the bundled
// near-degenerate input families (verify/generators/near_degenerate.hpp: exactly and nearly
// collinear / cocircular / coplanar / cospherical sets, at the ends of the coordinate range and
// far from the origin, and Kettner et al.'s ulp grids), with the stage that decided each call and
// the time per call of the filtered predicate beside the exact (GMP) stage alone.
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

#include "apps/cli_util.hpp"
#include "apps/subcommands.hpp"
#include "kernel/predicates.hpp"
#include "verify/exact_reference.hpp"
#include "verify/generators/near_degenerate.hpp"

namespace dtlab::cli {

namespace {

struct Row {
  const char* predicate = "";
  std::size_t calls = 0;
  std::size_t disagreements = 0;
  StageCounts stages;
  double filtered_ns = 0.0;
  double exact_ns = 0.0;
};

template <class Case, class Filtered, class Exact, class Reference>
Row check(const char* name, Predicate p, const std::vector<Case>& cases, Filtered filtered, Exact exact,
          Reference reference) {
  Row row;
  row.predicate = name;
  const PredicateStats before = predicate_stats();
  for (const Case& c : cases) {
    const Sign s = std::apply(filtered, c);
    const Sign e = std::apply(exact, c);
    const Sign r = std::apply(reference, c);
    row.disagreements += (s != r || e != r) ? 1 : 0;
  }
  row.calls = cases.size();
  row.stages = (predicate_stats() - before)[p];
  using Clock = std::chrono::steady_clock;
  // Timing: the same cases again, filtered and exact-only.
  int checksum = 0;
  auto t0 = Clock::now();
  for (int rep = 0; rep < 5; ++rep)
    for (const Case& c : cases) checksum += to_int(std::apply(filtered, c));
  auto t1 = Clock::now();
  for (const Case& c : cases) checksum += to_int(std::apply(exact, c));
  auto t2 = Clock::now();
  row.filtered_ns = std::chrono::duration<double, std::nano>(t1 - t0).count() / (5.0 * cases.size());
  row.exact_ns = std::chrono::duration<double, std::nano>(t2 - t1).count() / static_cast<double>(cases.size());
  if (checksum == 0x7fffffff) std::puts("");  // keeps the timed loops alive
  return row;
}

int run_selfcheck(std::size_t per_family) {
  using namespace gen;
  Rng rng(kDefaultSeed);
  std::vector<std::tuple<Vec2, Vec2, Vec2>> o2;
  std::vector<std::tuple<Vec2, Vec2, Vec2, Vec2>> ic;
  std::vector<std::tuple<Vec3, Vec3, Vec3, Vec3>> o3;
  std::vector<std::tuple<Vec3, Vec3, Vec3, Vec3, Vec3>> is;
  for (int f = 0; f < kFamilyCount; ++f) {
    for (Shape shape : {Shape::Flat, Shape::Round}) {
      const auto p2 = family_points2(rng, static_cast<Family>(f), shape, 48);
      const auto p3 = family_points3(rng, static_cast<Family>(f), shape, 48);
      auto pick2 = [&] { return p2[static_cast<std::size_t>(integer(rng, 0, 47))]; };
      auto pick3 = [&] { return p3[static_cast<std::size_t>(integer(rng, 0, 47))]; };
      for (std::size_t k = 0; k < per_family; ++k) {
        if (shape == Shape::Flat) {
          o2.emplace_back(pick2(), pick2(), pick2());
          o3.emplace_back(pick3(), pick3(), pick3(), pick3());
        } else {
          ic.emplace_back(pick2(), pick2(), pick2(), pick2());
          is.emplace_back(pick3(), pick3(), pick3(), pick3(), pick3());
        }
      }
    }
  }
  const KettnerGrid grid;
  for (int i = 0; i < KettnerGrid::kSize; ++i)
    for (int j = 0; j < KettnerGrid::kSize; ++j) o2.emplace_back(grid.p(i, j), grid.q, grid.r);

  std::vector<Row> rows;
  rows.push_back(check("orient2d", Predicate::Orient2d, o2, [](auto... p) { return orient2d(p...); },
                       [](auto... p) { return stage::orient2d_exact(p...); },
                       [](auto... p) { return reference::orient2d(p...); }));
  rows.push_back(check("incircle", Predicate::Incircle, ic, [](auto... p) { return incircle(p...); },
                       [](auto... p) { return stage::incircle_exact(p...); },
                       [](auto... p) { return reference::incircle(p...); }));
  rows.push_back(check("orient3d", Predicate::Orient3d, o3, [](auto... p) { return orient3d(p...); },
                       [](auto... p) { return stage::orient3d_exact(p...); },
                       [](auto... p) { return reference::orient3d(p...); }));
  rows.push_back(check("insphere", Predicate::Insphere, is, [](auto... p) { return insphere(p...); },
                       [](auto... p) { return stage::insphere_exact(p...); },
                       [](auto... p) { return reference::insphere(p...); }));

  std::printf("dtlab selfcheck: %d near-degenerate families x 2 shapes, %zu cases each, plus Kettner's "
              "256x256-ulp grid for orient2d\n\n",
              kFamilyCount, per_family);
  std::printf("| predicate | calls | semi-static | adaptive | exact (GMP) | disagreements | filtered ns/call | "
              "GMP-only ns/call |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
  std::size_t bad = 0;
  for (const Row& r : rows) {
    std::printf("| %s | %zu | %llu | %llu | %llu | %zu | %.1f | %.1f |\n", r.predicate, r.calls,
                static_cast<unsigned long long>(r.stages.semistatic), static_cast<unsigned long long>(r.stages.adaptive),
                static_cast<unsigned long long>(r.stages.exact), r.disagreements, r.filtered_ns, r.exact_ns);
    bad += r.disagreements;
  }
  std::printf("\n%s: %zu disagreement(s) with exact rational arithmetic\n", bad == 0 ? "PASS" : "FAIL", bad);
  return bad == 0 ? 0 : 4;
}

}  // namespace

void add_selfcheck(CLI::App& app) {
  auto per_family = std::make_shared<std::size_t>(2000);
  CLI::App* cmd = app.add_subcommand(
      "selfcheck", "Check every predicate and stage against exact rational arithmetic on the bundled "
                   "near-degenerate inputs, with stage counts and time per call");
  cmd->add_option("--cases", *per_family, "Cases per input family")
      ->capture_default_str()
      ->check(integer_in(1, 10'000'000));
  cmd->callback([per_family] { exit_code() = run_selfcheck(*per_family); });
}

}  // namespace dtlab::cli
