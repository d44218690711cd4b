// One harness for every registered 3D Delaunay variant (STYLE.md, guideline 8): each variant in
// delaunay3d_variants() is fed every named 3D distribution (verify/generators/points3d) and
// RapidCheck generators of adversarial sets (subsets of tiny integer grids, exactly cospherical
// integer points with their centre, coplanar sets with one to three points off the plane,
// duplicates, tiny sets, all-collinear and all-coplanar sets, power-of-two scalings and
// translations by 1e9). On each input the variant's output must pass verify_delaunay3d (closed
// 3-manifold, positive tetrahedra, perturbed empty sphere, convex hull under the ghost rule,
// exact coverage, duplicates unreferenced) and equal, as a canonical tetrahedron set, the output
// of "incremental", with the same duplicates and degenerate message. A new variant is picked up
// without editing this file; a variant whose run throws InternalError "... not built yet" (a
// registered stub) is skipped with that message.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "kernel/error.hpp"
#include "verify/checks3d.hpp"
#include "verify/generators/points3d.hpp"

namespace dtlab {
namespace {

constexpr const char* kReference = "incremental";

// --- running and checking one variant -----------------------------------------------------------

std::string describe(const std::vector<Vec3>& P) {
  constexpr std::size_t kShown = 48;
  std::string s = std::to_string(P.size()) + " points:";
  char buf[128];
  for (std::size_t i = 0; i < P.size() && i < kShown; ++i) {
    std::snprintf(buf, sizeof buf, " (%.17g, %.17g, %.17g)", P[i].x, P[i].y, P[i].z);
    s += buf;
  }
  if (P.size() > kShown) s += " ...";
  return s;
}

std::string show(const TetrahedronIds& t) {
  std::ostringstream s;
  s << "(" << t[0] << ", " << t[1] << ", " << t[2] << ", " << t[3] << ")";
  return s.str();
}

// The first tetrahedron in one canonical set and not the other, for the failure message.
std::string first_difference(const std::vector<TetrahedronIds>& a, const std::vector<TetrahedronIds>& b) {
  std::vector<TetrahedronIds> only_a, only_b;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(only_a));
  std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(only_b));
  return std::to_string(only_a.size()) + " tetrahedra only in the variant" +
         (only_a.empty() ? "" : " (first " + show(only_a.front()) + ")") + ", " + std::to_string(only_b.size()) +
         " only in the reference" + (only_b.empty() ? "" : " (first " + show(only_b.front()) + ")");
}

// The message of a registered stub, if `e` is one.
std::optional<std::string> not_built(const std::exception& e) {
  if (dynamic_cast<const InternalError*>(&e) == nullptr) return std::nullopt;
  const std::string what = e.what();
  if (what.find("not built yet") == std::string::npos) return std::nullopt;
  return what;
}

struct Expectation {
  std::string degenerate;  // "", or a word the degenerate message must contain ("collinear", "coplanar")
};

// Runs `variant` on P and checks it; returns "" or what went wrong (naming the check).
std::string check_variant(const std::string& variant, const std::vector<Vec3>& P, const Expectation& expect = {}) {
  Delaunay3dResult r;
  try {
    r = delaunay3d(P, {.algorithm = variant});
  } catch (const std::exception& e) {
    return variant + " threw: " + e.what();
  }
  const Tetrahedralization3& tet = r.tetrahedralization;
  if (!r.degenerate_message.empty() && tet.tetrahedron_count() != 0) {
    return variant + ": degenerate message '" + r.degenerate_message + "' but tetrahedra were made";
  }
  if (!expect.degenerate.empty() &&
      (r.degenerate_message.find(expect.degenerate) == std::string::npos || tet.tetrahedron_count() != 0)) {
    return variant + ": expected no tetrahedra and a message naming '" + expect.degenerate + "', got " +
           std::to_string(tet.tetrahedron_count()) + " tetrahedra and message '" + r.degenerate_message + "'";
  }
  const CheckReport3 report = verify_delaunay3d(P, tet, r.duplicates);
  if (!report.ok) {
    std::string text = to_text(report);
    if (text.size() > 2000) text.resize(2000);
    return variant + ": verify_delaunay3d: " + text;
  }
  if (variant == kReference) return "";
  Delaunay3dResult ref;
  try {
    ref = delaunay3d(P, {.algorithm = kReference});
  } catch (const std::exception& e) {
    return std::string("reference ") + kReference + " threw: " + e.what();
  }
  if (ref.degenerate_message != r.degenerate_message) {
    return variant + ": message '" + r.degenerate_message + "', reference: '" + ref.degenerate_message + "'";
  }
  if (ref.duplicates != r.duplicates || ref.duplicate_of != r.duplicate_of) {
    return variant + ": duplicates differ from the reference";
  }
  const auto mine = canonical_tetrahedron_set(tet);
  const auto theirs = canonical_tetrahedron_set(ref.tetrahedralization);
  if (mine != theirs) {
    return variant + ": canonical tetrahedron set differs from the reference: " + first_difference(mine, theirs);
  }
  return "";
}

// --- RapidCheck plumbing ------------------------------------------------------------------------

// Runs a property `cases` times (the seed and sizes still come from RC_PARAMS) and reports a
// failure, with rapidcheck's minimised counterexample, as a GoogleTest failure.
template <class Testable>
void check_property(const std::string& name, int cases, Testable&& testable) {
  rc::detail::TestParams params = rc::detail::configuration().testParams;
  params.maxSuccess = cases;
  const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info();
  rc::detail::TestMetadata metadata;
  metadata.id = std::string(info->test_suite_name()) + "/" + info->name() + "/" + name;
  metadata.description = name;
  const rc::detail::TestResult result =
      rc::detail::checkTestable(std::forward<Testable>(testable), metadata, params);
  if (!result.template is<rc::detail::SuccessResult>()) {
    std::ostringstream s;
    rc::detail::printResultMessage(result, s);
    ADD_FAILURE() << name << ": " << s.str();
  }
}

void rc_check(const std::string& variant, const std::vector<Vec3>& P, const Expectation& expect = {}) {
  const std::string failure = check_variant(variant, P, expect);
  if (!failure.empty()) RC_FAIL(failure + "\n  input: " + describe(P));
}

// Uniform over [lo, hi] whatever rapidcheck's current size.
template <class T>
T uniform_in(T lo, T hi) {
  return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange<T>(lo, hi + 1));
}

// Point counts grow with rapidcheck's size, so the first cases are the small ones.
int count_in(int lo, int hi) { return *rc::gen::inRange(lo, hi + 1); }

std::mt19937_64 shuffler() { return std::mt19937_64(*rc::gen::arbitrary<std::uint64_t>()); }

void shuffle_points(std::vector<Vec3>& P, std::mt19937_64& rng) {
  for (std::size_t i = P.size(); i > 1; --i) std::swap(P[i - 1], P[rng() % i]);
}

double pow2(int e) { return std::ldexp(1.0, e); }

// A power-of-two scale: exact, so every degeneracy survives.
void scale(std::vector<Vec3>& P) {
  const double s = pow2(uniform_in(-40, 40));
  for (Vec3& p : P) p = s * p;
}

// A power-of-two scale and, one time in three, a translation by a multiple of 1e9, which rounds
// small coordinates (new coincidences and degeneracies; still a valid input).
void scale_and_shift(std::vector<Vec3>& P) {
  scale(P);
  if (*rc::gen::element(0, 0, 1) == 0) return;
  const double o = static_cast<double>(uniform_in(-3, 3)) * 1e9;
  for (Vec3& p : P) p = Vec3{o, o, o} + p;
}

// Every integer point of x^2 + y^2 + z^2 = r^2.
std::vector<Vec3> integer_sphere(int r) {
  std::vector<Vec3> out;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y)
      for (int z = -r; z <= r; ++z)
        if (x * x + y * y + z * z == r * r) out.push_back({double(x), double(y), double(z)});
  return out;
}

// --- the harness ---------------------------------------------------------------------------------

class Delaunay3dVariants : public testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    // A registered stub refuses every input: skip it (with its message) until it is written.
    const std::vector<Vec3> probe = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    try {
      delaunay3d(probe, {.algorithm = GetParam()});
    } catch (const std::exception& e) {
      if (const auto message = not_built(e)) GTEST_SKIP() << *message;
    }
  }
};

TEST_P(Delaunay3dVariants, NamedDistributions) {
  for (const std::string& name : distribution_names3d()) {
    for (const std::size_t n : {0, 1, 2, 3, 4, 5, 8, 30, 200, 2000}) {
      const std::vector<Vec3> P = generate_points3d(name, n, 1);
      EXPECT_EQ(check_variant(GetParam(), P), "") << name << " n=" << n << " seed=1";
    }
  }
  const std::vector<Vec3> P = generate_points3d("uniform", 20000, 3);
  EXPECT_EQ(check_variant(GetParam(), P), "") << "uniform n=20000 seed=3";
}

// 4 to 40 points of a 4 x 4 x 4 integer grid (repeats allowed): cospherical, coplanar and
// collinear subsets everywhere.
TEST_P(Delaunay3dVariants, TinyGridSubsets) {
  check_property("tiny grid subsets", 200, [&] {
    std::mt19937_64 rng = shuffler();
    const int n = count_in(4, 40);
    const int side = uniform_in(2, 4);
    std::vector<Vec3> P;
    for (int i = 0; i < n; ++i) {
      P.push_back({static_cast<double>(rng() % side), static_cast<double>(rng() % side),
                   static_cast<double>(rng() % side)});
    }
    scale_and_shift(P);
    rc_check(GetParam(), P);
  });
}

// A random subset of the integer points of one sphere, maybe with its centre and a few points
// inside: every 5-subset of the sphere's points is cospherical, the perturbation alone decides.
TEST_P(Delaunay3dVariants, Cospherical) {
  check_property("cospherical", 150, [&] {
    std::mt19937_64 rng = shuffler();
    const int r = *rc::gen::element(3, 5, 9, 15, 21);
    std::vector<Vec3> P = integer_sphere(r);
    shuffle_points(P, rng);
    P.resize(static_cast<std::size_t>(count_in(4, static_cast<int>(P.size()))));
    if (*rc::gen::arbitrary<bool>()) P.push_back({0, 0, 0});
    const int inside = uniform_in(0, 3);
    for (int k = 0; k < inside; ++k) P.push_back({static_cast<double>(uniform_in(-2, 2)), 1.0, 0.0});
    const double cx = uniform_in(-1 << 20, 1 << 20), cy = uniform_in(-1 << 20, 1 << 20);
    for (Vec3& p : P) p = p + Vec3{cx, cy, 0.0};
    scale_and_shift(P);
    shuffle_points(P, rng);
    rc_check(GetParam(), P);
  });
}

// Integer points of one plane (a lattice patch or random) and one to three points off it: the
// hull has a big flat face, triangulated by the ghost rule.
TEST_P(Delaunay3dVariants, CoplanarPlusFew) {
  check_property("coplanar plus a few", 150, [&] {
    std::mt19937_64 rng = shuffler();
    const std::array<int, 3> u = {uniform_in(-3, 3), uniform_in(-3, 3), 1};
    const std::array<int, 3> v = {1, uniform_in(-3, 3), uniform_in(-3, 3)};
    const int n = count_in(3, 120);
    const int spread = uniform_in(2, 30);
    std::vector<Vec3> P;
    for (int i = 0; i < n; ++i) {
      const auto s = static_cast<double>(static_cast<int>(rng() % spread)),
                 t = static_cast<double>(static_cast<int>(rng() % spread));
      P.push_back({s * u[0] + t * v[0], s * u[1] + t * v[1], s * u[2] + t * v[2]});
    }
    const int off = uniform_in(1, 3);
    for (int i = 0; i < off; ++i) {
      P.push_back({static_cast<double>(uniform_in(-40, 40)), static_cast<double>(uniform_in(-40, 40)),
                   static_cast<double>(uniform_in(-40, 40))});
    }
    scale_and_shift(P);
    shuffle_points(P, rng);
    rc_check(GetParam(), P);
  });
}

// A random fraction of the points repeated (1 to 3 copies each), or every point equal.
TEST_P(Delaunay3dVariants, Duplicates) {
  check_property("duplicates", 150, [&] {
    std::mt19937_64 rng = shuffler();
    std::vector<Vec3> P;
    if (*rc::gen::element(0, 0, 0, 1) == 1) {
      P.assign(static_cast<std::size_t>(count_in(1, 30)), Vec3{0.375, -2.0, 1e9});
    } else {
      const int m = count_in(1, 150);
      const bool integer = *rc::gen::arbitrary<bool>();
      for (int i = 0; i < m; ++i) {
        const auto c = [&] { return integer ? static_cast<double>(rng() % 5) : static_cast<double>(rng() >> 11) * 0x1.0p-53; };
        const double x = c(), y = c(), z = c();
        P.push_back({x, y, z});
      }
      const int percent = uniform_in(0, 100);
      for (int i = 0; i < m; ++i) {
        if (static_cast<int>(rng() % 100) >= percent) continue;
        const std::size_t copies = 1 + rng() % 3;
        for (std::size_t c = 0; c < copies; ++c) P.push_back(P[static_cast<std::size_t>(i)]);
      }
    }
    shuffle_points(P, rng);
    rc_check(GetParam(), P);
  });
}

// All collinear (at least two distinct points) or all coplanar (at least three non-collinear):
// no tetrahedra and a message naming it. Fewer than four distinct points: "fewer than 4".
TEST_P(Delaunay3dVariants, DegenerateOutcomes) {
  check_property("all collinear", 100, [&] {
    std::mt19937_64 rng = shuffler();
    const std::array<int, 3> d = {uniform_in(-5, 5), uniform_in(-5, 5), uniform_in(1, 5)};
    std::vector<int> ts = {0, 1, -1, 2};  // four distinct points at least
    const int more = count_in(0, 60);
    for (int i = 0; i < more; ++i) ts.push_back(static_cast<int>(rng() % 201) - 100);
    std::vector<Vec3> P;
    for (const int t : ts) P.push_back({3.0 + t * d[0], -7.0 + t * d[1], 1.0 * t * d[2]});
    scale(P);
    shuffle_points(P, rng);
    rc_check(GetParam(), P, {.degenerate = "collinear"});
  });
  check_property("all coplanar", 100, [&] {
    std::mt19937_64 rng = shuffler();
    const std::array<int, 3> u = {1, uniform_in(-4, 4), uniform_in(-4, 4)};
    const std::array<int, 3> v = {0, 1, uniform_in(-4, 4)};
    std::vector<Vec3> P = {{0, 0, 0}, {1.0 * u[0], 1.0 * u[1], 1.0 * u[2]}, {1.0 * v[0], 1.0 * v[1], 1.0 * v[2]},
                           {1.0 * (u[0] + v[0]), 1.0 * (u[1] + v[1]), 1.0 * (u[2] + v[2])}};
    const int more = count_in(0, 60);
    for (int i = 0; i < more; ++i) {
      const double s = static_cast<double>(rng() % 41) - 20, t = static_cast<double>(rng() % 41) - 20;
      P.push_back({s * u[0] + t * v[0], s * u[1] + t * v[1], s * u[2] + t * v[2]});
    }
    scale(P);
    shuffle_points(P, rng);
    rc_check(GetParam(), P, {.degenerate = "coplanar"});
  });
  for (const auto& few : {std::vector<Vec3>{}, std::vector<Vec3>{{1, 2, 3}}, std::vector<Vec3>{{0, 0, 0}, {1, 2, 3}, {1, 2, 3}},
                          std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}, {0, 0, 0}}}) {
    EXPECT_EQ(check_variant(GetParam(), few, {.degenerate = "fewer than 4"}), "") << describe(few);
  }
}

// Duplicates are reported (ascending, with the first index of each) and left unreferenced.
TEST_P(Delaunay3dVariants, DuplicatesReported) {
  std::vector<Vec3> P = generate_points3d("uniform", 300, 4);
  P.push_back(P[10]);
  P.push_back(P[20]);
  P.push_back(P[10]);
  const Delaunay3dResult r = delaunay3d(P, {.algorithm = GetParam()});
  EXPECT_EQ(r.duplicates, (std::vector<std::uint32_t>{300, 301, 302}));
  EXPECT_EQ(r.duplicate_of, (std::vector<std::uint32_t>{10, 20, 10}));
  EXPECT_EQ(check_variant(GetParam(), P), "");
}

std::vector<std::string> variant_names() {
  std::vector<std::string> names;
  for (const Delaunay3dVariant& v : delaunay3d_variants()) names.emplace_back(v.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Registered, Delaunay3dVariants, testing::ValuesIn(variant_names()),
                         [](const testing::TestParamInfo<std::string>& param_info) {
                           std::string name = param_info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

// The registry itself: names unique and findable, and the reference is registered.
TEST(Delaunay3dVariantRegistry, NamesAreUniqueAndFindable) {
  const std::vector<std::string> names = variant_names();
  ASSERT_FALSE(names.empty());
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
  for (const std::string& n : names) {
    EXPECT_FALSE(n.empty());
    ASSERT_NE(delaunay3d_variants().find(n), nullptr) << n;
    EXPECT_EQ(delaunay3d_variants().find(n)->name, n);
  }
  EXPECT_NE(delaunay3d_variants().find(kReference), nullptr);
}

}  // namespace
}  // namespace dtlab
