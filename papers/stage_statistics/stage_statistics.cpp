// Which predicate stage decides inside our Delaunay variants: the question of Devillers and Pion,
// "Efficient exact geometric predicates for Delaunay triangulations" (ALENEX 2003), who count
// how often their filters fail while CGAL triangulates random, grid and circle inputs. For every
// registered 2D variant (algorithms/delaunay2d/registry.hpp) and the named distributions uniform,
// grid, circle and exact_circle (verify/generators/points2d.hpp), it prints the calls per point of
// orient2d and incircle and the share decided by each stage (Delaunay2dResult.predicate_stats).
//
//   stage_statistics            n = 10^5
//   stage_statistics --large    n = 10^5 and 10^6
//   stage_statistics --quick    n = 2000: the consistency checks only (CTest)
//   --n N, --variant NAME, --distribution NAME: one size, one variant, one distribution.
//
// Exit status 1 if a check fails: all variants return the same triangles, the first variant's are
// the Delaunay triangulation (verify/checks2d.hpp), an in-circle zero that the perturbation
// resolved was certified by the adaptive or exact stage (the semi-static filter never certifies
// zero), every exact_circle run resolves at least one zero, and no 3D predicate was called.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/delaunay2d/registry.hpp"
#include "dtlab/build_info.hpp"
#include "kernel/stats.hpp"
#include "verify/checks2d.hpp"
#include "verify/generators/points2d.hpp"

namespace dtlab::papers {
namespace {

constexpr std::uint64_t kSeed = 0xA1E2'0003'D3B1'0001ull;  // one point set per (distribution, n)
constexpr const char* kDistributions[] = {"uniform", "grid", "circle", "exact_circle"};

int g_failures = 0;

void fail(std::string_view variant, std::string_view distribution, std::size_t n, const std::string& what) {
  ++g_failures;
  std::fprintf(stderr, "CHECK FAILED: %.*s/%.*s/n=%zu: %s\n", int(variant.size()), variant.data(),
               int(distribution.size()), distribution.data(), n, what.c_str());
}

double percent(std::uint64_t part, std::uint64_t whole) {
  return whole == 0 ? 0.0 : 100.0 * static_cast<double>(part) / static_cast<double>(whole);
}

double per_point(std::uint64_t calls, std::size_t n) { return static_cast<double>(calls) / static_cast<double>(n); }

void print_header() {
  std::printf("| variant | distribution | n | orient2d calls/pt | semi-static %% | adaptive %% | exact %% "
              "| incircle calls/pt | semi-static %% | adaptive %% | exact %% | perturbed %% | seconds |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
}

void print_row(std::string_view variant, const std::string& distribution, std::size_t n, const Delaunay2dResult& r) {
  const StageCounts& o = r.predicate_stats[Predicate::Orient2d];
  const StageCounts& c = r.predicate_stats[Predicate::Incircle];
  std::printf("| %.*s | %s | %zu | %.2f | %.4f | %.4f | %.4f | %.2f | %.4f | %.4f | %.4f | %.4f | %.3f |\n",
              int(variant.size()), variant.data(), distribution.c_str(), n, per_point(o.calls(), n),
              percent(o.semistatic, o.calls()), percent(o.adaptive, o.calls()), percent(o.exact, o.calls()),
              per_point(c.calls(), n), percent(c.semistatic, c.calls()), percent(c.adaptive, c.calls()),
              percent(c.exact, c.calls()), percent(c.perturbed, c.calls()), r.seconds);
  std::fflush(stdout);  // a row at a time: some runs at 10^6 take minutes
}

// The checks that hold for any one run.
void check_run(std::string_view variant, std::string_view distribution, std::size_t n, const Delaunay2dResult& r) {
  const StageCounts& c = r.predicate_stats[Predicate::Incircle];
  if (!r.degenerate_message.empty()) fail(variant, distribution, n, "no triangulation: " + r.degenerate_message);
  if (c.perturbed > c.adaptive + c.exact)
    fail(variant, distribution, n,
         std::to_string(c.perturbed) + " perturbed in-circle zeros but only " + std::to_string(c.adaptive + c.exact) +
             " in-circle signs from the stages that can certify zero");
  if (distribution == "exact_circle" && n >= 4 && c.perturbed == 0)
    fail(variant, distribution, n, "all points are cocircular, yet no in-circle zero was perturbed");
  if (r.predicate_stats[Predicate::Orient3d].calls() + r.predicate_stats[Predicate::Insphere].calls() != 0)
    fail(variant, distribution, n, "a 3D predicate was called");
}

void run_distribution(const std::string& distribution, std::size_t n,
                      const std::vector<const Delaunay2dVariant*>& variants) {
  const std::vector<Vec2> points = generate_points2d(distribution, n, kSeed);
  std::vector<TriangleIds> reference;  // the first variant's triangles
  std::string_view reference_variant;
  for (const Delaunay2dVariant* v : variants) {
    const Delaunay2dVariant& variant = *v;
    const Delaunay2dResult r = delaunay2d(points, {.algorithm = std::string(variant.name)});
    print_row(variant.name, distribution, n, r);
    check_run(variant.name, distribution, n, r);
    std::vector<TriangleIds> triangles = canonical_triangle_set(r.triangulation.finite_triangles());
    if (reference_variant.empty()) {
      // Checked once per point set: the others must then return the very same triangles.
      const CheckReport2 report = verify_delaunay2d(points, triangles, r.duplicates);
      if (!report.ok) fail(variant.name, distribution, n, "not the Delaunay triangulation: " + to_text(report));
      reference = std::move(triangles);
      reference_variant = variant.name;
    } else if (triangles != reference) {
      fail(variant.name, distribution, n, "triangles differ from " + std::string(reference_variant) + "'s");
    }
  }
}

}  // namespace
}  // namespace dtlab::papers

int main(int argc, char** argv) {
  using namespace dtlab::papers;
  std::vector<std::size_t> sizes = {100'000};
  std::vector<std::string> distributions(std::begin(kDistributions), std::end(kDistributions));
  std::vector<const dtlab::Delaunay2dVariant*> variants;
  for (const dtlab::Delaunay2dVariant& v : dtlab::delaunay2d_variants()) variants.push_back(&v);
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (std::strcmp(argv[i], "--quick") == 0) {
      quick = true;
      sizes = {2000};
    } else if (std::strcmp(argv[i], "--large") == 0) {
      sizes = {100'000, 1'000'000};
    } else if (std::strcmp(argv[i], "--n") == 0 && has_value) {
      sizes = {static_cast<std::size_t>(std::strtoull(argv[++i], nullptr, 10))};
      if (sizes[0] < 3) {
        std::fprintf(stderr, "--n needs at least 3 points\n");
        return 2;
      }
    } else if (std::strcmp(argv[i], "--variant") == 0 && has_value) {
      const dtlab::Delaunay2dVariant* v = dtlab::delaunay2d_variants().find(argv[++i]);
      if (v == nullptr) {
        std::fprintf(stderr, "unknown variant '%s'\n", argv[i]);
        return 2;
      }
      variants = {v};
    } else if (std::strcmp(argv[i], "--distribution") == 0 && has_value) {
      distributions = {argv[++i]};
    } else {
      std::fprintf(stderr,
                   "usage: %s [--quick | --large | --n N] [--variant NAME] [--distribution NAME]\n"
                   "  --quick   n = 2000 (the CTest mode)\n  --large   n = 10^5 and 10^6 (default: 10^5)\n",
                   argv[0]);
      return 2;
    }
  }
  std::printf("# Predicate stages in the 2D Delaunay variants: dtlab %s (%s), %s, %s build%s\n\n",
              dtlab::build_info::kVersion, dtlab::build_info::kCommit, dtlab::build_info::kCompiler,
              dtlab::build_info::kBuildType, quick ? " (--quick)" : "");
  std::printf("Shares are of each predicate's calls; orient2d includes the calls the in-circle perturbation "
              "makes; perturbed = in-circle zeros resolved symbolically.\n\n");
  print_header();
  try {
    for (const std::size_t n : sizes)
      for (const std::string& distribution : distributions) run_distribution(distribution, n, variants);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("\n%s: %d consistency check(s) failed\n", g_failures == 0 ? "PASS" : "FAIL", g_failures);
  return g_failures == 0 ? 0 : 1;
}
