// Properties of the four predicates and of each of their stages, against the independent exact
// reference (verify/exact_reference.hpp, GMP rationals): on random, exactly degenerate and
// near-degenerate inputs, on Kettner et al.'s grid (exhaustively), at extreme magnitudes and far
// from the origin; antisymmetry under permutations; the symbolic perturbation; the counters.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "kernel/predicates.hpp"
#include "verify/exact_reference.hpp"
#include "verify/generators/near_degenerate.hpp"

namespace {

using dtlab::FilteredSign;
using dtlab::Predicate;
using dtlab::PredicateStats;
using dtlab::Sign;
using dtlab::StageCounts;
using dtlab::Vec2;
using dtlab::Vec3;
namespace gen = dtlab::gen;
namespace ref = dtlab::reference;
namespace stage = dtlab::stage;

// --- the four predicates, behind one interface -------------------------------------------------

struct Orient2d {
  using Point = Vec2;
  static constexpr std::size_t kArity = 3;
  static constexpr Predicate kId = Predicate::Orient2d;
  static constexpr gen::Shape kShape = gen::Shape::Flat;
  using Tuple = std::array<Point, kArity>;
  static Sign filtered(const Tuple& p) { return std::apply(dtlab::orient2d, p); }
  static Sign uncounted(const Tuple& p) { return std::apply(dtlab::uncounted::orient2d, p); }
  static FilteredSign semistatic(const Tuple& p) { return std::apply(stage::orient2d_semistatic, p); }
  static FilteredSign adaptive(const Tuple& p) { return std::apply(stage::orient2d_adaptive, p); }
  static FilteredSign expansion(const Tuple& p) { return std::apply(stage::orient2d_expansion, p); }
  static Sign exact(const Tuple& p) { return std::apply(stage::orient2d_exact, p); }
  static Sign reference(const Tuple& p) { return std::apply(ref::orient2d, p); }
};

struct Incircle {
  using Point = Vec2;
  static constexpr std::size_t kArity = 4;
  static constexpr Predicate kId = Predicate::Incircle;
  static constexpr gen::Shape kShape = gen::Shape::Round;
  using Tuple = std::array<Point, kArity>;
  static Sign filtered(const Tuple& p) { return std::apply(dtlab::incircle, p); }
  static Sign uncounted(const Tuple& p) { return std::apply(dtlab::uncounted::incircle, p); }
  static FilteredSign semistatic(const Tuple& p) { return std::apply(stage::incircle_semistatic, p); }
  static FilteredSign adaptive(const Tuple& p) { return std::apply(stage::incircle_adaptive, p); }
  static FilteredSign expansion(const Tuple& p) { return std::apply(stage::incircle_expansion, p); }
  static Sign exact(const Tuple& p) { return std::apply(stage::incircle_exact, p); }
  static Sign reference(const Tuple& p) { return std::apply(ref::incircle, p); }
  static Sign perturbed(const Tuple& p) { return std::apply(dtlab::incircle_perturbed, p); }
  static Sign reference_perturbed(const Tuple& p) { return std::apply(ref::incircle_perturbed, p); }
  static bool lower_dimensional(const Tuple& p) { return ref::all_collinear(p); }
};

struct Orient3d {
  using Point = Vec3;
  static constexpr std::size_t kArity = 4;
  static constexpr Predicate kId = Predicate::Orient3d;
  static constexpr gen::Shape kShape = gen::Shape::Flat;
  using Tuple = std::array<Point, kArity>;
  static Sign filtered(const Tuple& p) { return std::apply(dtlab::orient3d, p); }
  static Sign uncounted(const Tuple& p) { return std::apply(dtlab::uncounted::orient3d, p); }
  static FilteredSign semistatic(const Tuple& p) { return std::apply(stage::orient3d_semistatic, p); }
  static FilteredSign adaptive(const Tuple& p) { return std::apply(stage::orient3d_adaptive, p); }
  static FilteredSign expansion(const Tuple& p) { return std::apply(stage::orient3d_expansion, p); }
  static Sign exact(const Tuple& p) { return std::apply(stage::orient3d_exact, p); }
  static Sign reference(const Tuple& p) { return std::apply(ref::orient3d, p); }
};

struct Insphere {
  using Point = Vec3;
  static constexpr std::size_t kArity = 5;
  static constexpr Predicate kId = Predicate::Insphere;
  static constexpr gen::Shape kShape = gen::Shape::Round;
  using Tuple = std::array<Point, kArity>;
  static Sign filtered(const Tuple& p) { return std::apply(dtlab::insphere, p); }
  static Sign uncounted(const Tuple& p) { return std::apply(dtlab::uncounted::insphere, p); }
  static FilteredSign semistatic(const Tuple& p) { return std::apply(stage::insphere_semistatic, p); }
  static FilteredSign adaptive(const Tuple& p) { return std::apply(stage::insphere_adaptive, p); }
  static FilteredSign expansion(const Tuple& p) { return std::apply(stage::insphere_expansion, p); }
  static Sign exact(const Tuple& p) { return std::apply(stage::insphere_exact, p); }
  static Sign reference(const Tuple& p) { return std::apply(ref::insphere, p); }
  static Sign perturbed(const Tuple& p) { return std::apply(dtlab::insphere_perturbed, p); }
  static Sign reference_perturbed(const Tuple& p) { return std::apply(ref::insphere_perturbed, p); }
  static bool lower_dimensional(const Tuple& p) { return ref::all_coplanar(p); }
};

// --- helpers ---------------------------------------------------------------------------------

std::string describe(const Vec2& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%a, %a)", p.x, p.y);
  return buf;
}
std::string describe(const Vec3& p) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "(%a, %a, %a)", p.x, p.y, p.z);
  return buf;
}
template <class T>
std::string describe(const T& tuple) {
  std::string out;
  for (const auto& p : tuple) out += (out.empty() ? "" : ", ") + describe(p);
  return out;
}

// Which stage should decide `p`: the first one that certifies a sign (Gmp: none before it).
enum class Decider { Semistatic, Adaptive, Expansion, Gmp };

// Compares every stage with the reference on one tuple, and checks that the counted predicate
// counted exactly one call, in the stage that decides, while the uncounted one counted nothing.
// Returns "" or a description of every disagreement. `decider` receives the deciding stage.
template <class P>
std::string stage_disagreement(const typename P::Tuple& p, Decider* decider = nullptr) {
  const Sign want = P::reference(p);
  std::string out;
  const auto expect = [&](const char* what, Sign got) {
    if (got != want) out += std::string("; ") + what + " says " + dtlab::to_string(got);
  };
  const FilteredSign s1 = P::semistatic(p);
  const FilteredSign s2 = P::adaptive(p);
  const FilteredSign s3 = P::expansion(p);
  if (s1) expect("semistatic", *s1);
  if (s2) expect("adaptive", *s2);
  if (s3) expect("expansion", *s3);
  // Stage 3 claims to decide everything on the supported range (GMP is the fallback for an
  // expansion that would outgrow its buffer): a deferral is reported too.
  if (!s3) out += "; the expansion stage deferred";
  expect("exact", P::exact(p));

  const PredicateStats before = dtlab::predicate_stats();
  expect("filtered", P::filtered(p));
  const PredicateStats counted = dtlab::predicate_stats() - before;
  expect("uncounted", P::uncounted(p));
  const PredicateStats after = dtlab::predicate_stats() - before;

  const Decider d = s1 ? Decider::Semistatic
                      : (s2 ? Decider::Adaptive : (s3 ? Decider::Expansion : Decider::Gmp));
  if (decider) *decider = d;
  StageCounts one;
  (d == Decider::Semistatic ? one.semistatic : (d == Decider::Adaptive ? one.adaptive : one.exact)) = 1;
  one.gmp = d == Decider::Gmp ? 1 : 0;
  PredicateStats want_counts;
  want_counts[P::kId] = one;
  if (counted.to_json() != want_counts.to_json()) out += "; counters moved by " + counted.to_json();
  // The uncounted predicates count nothing, whichever stage decides.
  const PredicateStats by_uncounted = after - counted;
  const bool uncounted_ok = by_uncounted.to_json() == PredicateStats{}.to_json();
  if (!uncounted_ok) out += "; the uncounted predicate moved the counters by " + by_uncounted.to_json();

  if (!out.empty()) out = "points " + describe(p) + ": reference " + dtlab::to_string(want) + out;
  return out;
}

template <class P>
typename P::Tuple tuple_of(const std::vector<typename P::Point>& v, std::size_t first = 0) {
  typename P::Tuple t;
  std::copy_n(v.begin() + static_cast<std::ptrdiff_t>(first), P::kArity, t.begin());
  return t;
}

template <class P>
std::vector<typename P::Point> family_points(gen::Rng& rng, gen::Family f, gen::Shape s, std::size_t n) {
  if constexpr (std::is_same_v<typename P::Point, Vec2>) {
    return gen::family_points2(rng, f, s, n);
  } else {
    return gen::family_points3(rng, f, s, n);
  }
}

// A tuple from family f: all points from one set of the family's shape, or (mixed) all but the
// last, which comes from the other shape's set: degenerate subsets inside non-degenerate calls.
template <class P>
typename P::Tuple random_tuple(gen::Rng& rng, gen::Family f) {
  const int variant = static_cast<int>(gen::integer(rng, 0, 2));
  const gen::Shape own = P::kShape;
  const gen::Shape other = own == gen::Shape::Flat ? gen::Shape::Round : gen::Shape::Flat;
  if (variant == 0) return tuple_of<P>(family_points<P>(rng, f, own, P::kArity));
  if (variant == 1) return tuple_of<P>(family_points<P>(rng, f, other, P::kArity));
  std::vector<typename P::Point> v = family_points<P>(rng, f, own, P::kArity);
  v.back() = family_points<P>(rng, f, other, 1).front();
  return tuple_of<P>(v);
}

int permutation_parity(const std::vector<int>& perm) {
  int inversions = 0;
  for (std::size_t i = 0; i < perm.size(); ++i)
    for (std::size_t j = i + 1; j < perm.size(); ++j) inversions += perm[i] > perm[j];
  return inversions % 2 == 0 ? 1 : -1;
}

// f(permuted p) == parity * f(p) for every permutation; "" or the first counterexample.
template <class T, class F>
std::string permutation_disagreement(const T& p, F f) {
  const Sign s = f(p);
  std::vector<int> perm(p.size());
  std::iota(perm.begin(), perm.end(), 0);
  while (std::next_permutation(perm.begin(), perm.end())) {
    T q;
    for (std::size_t i = 0; i < p.size(); ++i) q[i] = p[static_cast<std::size_t>(perm[i])];
    const Sign want = permutation_parity(perm) > 0 ? s : -s;
    if (const Sign got = f(q); got != want) {
      std::string order;
      for (int i : perm) order += std::to_string(i);
      return "points " + describe(p) + " give " + dtlab::to_string(s) + ", permuted " + order + " give " +
             dtlab::to_string(got);
    }
  }
  return "";
}

template <class T>
bool has_duplicates(T p) {
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) { return a < b; });
  return std::adjacent_find(p.begin(), p.end()) != p.end();
}

gen::Family family_at(int i) { return static_cast<gen::Family>(i); }

// --- sign conventions, pinned by hand-checked configurations ---------------------------------

template <class P>
void expect_convention(const typename P::Tuple& p, Sign want) {
  EXPECT_EQ(P::reference(p), want) << "reference, points " << describe(p);
  EXPECT_EQ(stage_disagreement<P>(p), "");
}

TEST(PredicateConventions, HandCheckedSigns) {
  expect_convention<Orient2d>({Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}}, Sign::Positive);
  expect_convention<Orient2d>({Vec2{0, 0}, Vec2{0, 1}, Vec2{1, 0}}, Sign::Negative);
  expect_convention<Orient2d>({Vec2{0, 0}, Vec2{1, 1}, Vec2{3, 3}}, Sign::Zero);
  // Unit circle through (1,0), (0,1), (-1,0), counter-clockwise.
  expect_convention<Incircle>({Vec2{1, 0}, Vec2{0, 1}, Vec2{-1, 0}, Vec2{0, 0}}, Sign::Positive);
  expect_convention<Incircle>({Vec2{1, 0}, Vec2{0, 1}, Vec2{-1, 0}, Vec2{2, 2}}, Sign::Negative);
  expect_convention<Incircle>({Vec2{1, 0}, Vec2{0, 1}, Vec2{-1, 0}, Vec2{0, -1}}, Sign::Zero);
  expect_convention<Incircle>({Vec2{0, 1}, Vec2{1, 0}, Vec2{-1, 0}, Vec2{0, 0}}, Sign::Negative);
  // det(b - a, c - a, d - a) = det(I) = 1.
  expect_convention<Orient3d>({Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}, Sign::Positive);
  expect_convention<Orient3d>({Vec3{0, 0, 0}, Vec3{0, 1, 0}, Vec3{1, 0, 0}, Vec3{0, 0, 1}}, Sign::Negative);
  expect_convention<Orient3d>({Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{1, 1, 0}}, Sign::Zero);
  // Circumsphere of the unit corner tetrahedron: centre (1/2, 1/2, 1/2), radius^2 3/4.
  const Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  expect_convention<Insphere>({o, x, y, z, Vec3{0.25, 0.25, 0.25}}, Sign::Positive);
  expect_convention<Insphere>({o, x, y, z, Vec3{2, 2, 2}}, Sign::Negative);
  expect_convention<Insphere>({o, x, y, z, Vec3{1, 1, 0}}, Sign::Zero);
  expect_convention<Insphere>({o, y, x, z, Vec3{0.25, 0.25, 0.25}}, Sign::Negative);
}

// The reference against plain integer arithmetic, where that is exact (small-grid points).
TEST(ExactReference, AgreesWithIntegerDeterminantsOnSmallGrids) {
  gen::Rng rng(gen::kDefaultSeed);
  const auto sgn = [](long long v) { return v > 0 ? Sign::Positive : (v < 0 ? Sign::Negative : Sign::Zero); };
  for (int k = 0; k < 2000; ++k) {
    const auto p2 = gen::family_points2(rng, gen::Family::SmallGrid, gen::Shape::Flat, 4);
    const auto p3 = gen::family_points3(rng, gen::Family::SmallGrid, gen::Shape::Flat, 5);
    const auto d2 = [&](int i, int j) { return static_cast<long long>(j == 0 ? p2[i].x - p2[3].x : p2[i].y - p2[3].y); };
    const auto l2 = [&](int i) { return d2(i, 0) * d2(i, 0) + d2(i, 1) * d2(i, 1); };
    const long long o2 = (d2(1, 0) - d2(0, 0)) * (d2(2, 1) - d2(0, 1)) - (d2(1, 1) - d2(0, 1)) * (d2(2, 0) - d2(0, 0));
    const long long ic = l2(0) * (d2(1, 0) * d2(2, 1) - d2(1, 1) * d2(2, 0)) -
                         l2(1) * (d2(0, 0) * d2(2, 1) - d2(0, 1) * d2(2, 0)) +
                         l2(2) * (d2(0, 0) * d2(1, 1) - d2(0, 1) * d2(1, 0));
    EXPECT_EQ(ref::orient2d(p2[0], p2[1], p2[2]), sgn(o2)) << describe(p2);
    EXPECT_EQ(ref::incircle(p2[0], p2[1], p2[2], p2[3]), sgn(ic)) << describe(p2);

    // 3x3 determinants by the rule of Sarrus, over rows r[0..2].
    using Row = std::array<long long, 3>;
    const auto det3 = [](const Row& a, const Row& b, const Row& c) {
      return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    };
    const auto diff = [&](int i, int base) {
      return Row{static_cast<long long>(p3[i].x - p3[base].x), static_cast<long long>(p3[i].y - p3[base].y),
                 static_cast<long long>(p3[i].z - p3[base].z)};
    };
    EXPECT_EQ(ref::orient3d(p3[0], p3[1], p3[2], p3[3]), sgn(det3(diff(1, 0), diff(2, 0), diff(3, 0)))) << describe(p3);
    // insphere: rows (p - e, |p - e|^2); minus the 4x4 determinant, expanded along the last column.
    std::array<Row, 4> r;
    std::array<long long, 4> l;
    for (int i = 0; i < 4; ++i) {
      r[static_cast<std::size_t>(i)] = diff(i, 4);
      const Row& q = r[static_cast<std::size_t>(i)];
      l[static_cast<std::size_t>(i)] = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    }
    const long long det4 = -l[0] * det3(r[1], r[2], r[3]) + l[1] * det3(r[0], r[2], r[3]) -
                           l[2] * det3(r[0], r[1], r[3]) + l[3] * det3(r[0], r[1], r[2]);
    EXPECT_EQ(ref::insphere(p3[0], p3[1], p3[2], p3[3], p3[4]), sgn(-det4)) << describe(p3);
  }
}

// --- every stage against the reference, every family -----------------------------------------

// A fixed-seed sweep: every family, both shapes and mixed tuples, every predicate.
template <class P>
void sweep_families(int tuples_per_family) {
  gen::Rng rng(gen::kDefaultSeed + static_cast<std::uint64_t>(P::kId));
  std::array<int, 4> decided{};
  for (int f = 0; f < gen::kFamilyCount; ++f) {
    int failures = 0;
    for (int k = 0; k < tuples_per_family && failures < 5; ++k) {
      const typename P::Tuple p = random_tuple<P>(rng, family_at(f));
      Decider d{};
      const std::string msg = stage_disagreement<P>(p, &d);
      ++decided[static_cast<std::size_t>(d)];
      if (!msg.empty()) {
        ++failures;
        ADD_FAILURE() << gen::to_string(family_at(f)) << ": " << msg;
      }
    }
  }
  // The sweep must reach every stage, or it tests less than it claims.
  EXPECT_GT(decided[0], 0) << "no call decided by the semi-static filter";
  EXPECT_GT(decided[1], 0) << "no call decided by the dynamic filter";
  EXPECT_GT(decided[2], 0) << "no call decided by the expansion stage";
  EXPECT_EQ(decided[3], 0) << "calls left to GMP: an expansion outgrew its buffer";
  std::printf("  %s stages deciding: semistatic %d, adaptive %d, expansion %d, gmp %d\n",
              dtlab::to_string(P::kId), decided[0], decided[1], decided[2], decided[3]);
}

TEST(PredicateStages, Orient2dAllFamilies) { sweep_families<Orient2d>(1500); }
TEST(PredicateStages, IncircleAllFamilies) { sweep_families<Incircle>(1500); }
TEST(PredicateStages, Orient3dAllFamilies) { sweep_families<Orient3d>(1500); }
TEST(PredicateStages, InsphereAllFamilies) { sweep_families<Insphere>(1000); }

// The same with seeds and families chosen by RapidCheck.
template <class P>
void stages_property() {
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const auto f = family_at(*rc::gen::inRange(0, gen::kFamilyCount));
  gen::Rng rng(seed);
  for (int k = 0; k < 20; ++k) {
    const typename P::Tuple p = random_tuple<P>(rng, f);
    const std::string msg = stage_disagreement<P>(p);
    if (!msg.empty()) {
      RC_FAIL(std::string(gen::to_string(f)) + ": " + msg);
    }
  }
}

RC_GTEST_PROP(PredicateStages, Orient2dMatchesReference, ()) { stages_property<Orient2d>(); }
RC_GTEST_PROP(PredicateStages, IncircleMatchesReference, ()) { stages_property<Incircle>(); }
RC_GTEST_PROP(PredicateStages, Orient3dMatchesReference, ()) { stages_property<Orient3d>(); }
RC_GTEST_PROP(PredicateStages, InsphereMatchesReference, ()) { stages_property<Insphere>(); }

// Raw RapidCheck doubles, mapped into the supported range.
RC_GTEST_PROP(PredicateStages, ArbitraryBitsMatchReference, (std::array<std::uint64_t, 15> bits)) {
  std::array<double, 15> v;
  std::transform(bits.begin(), bits.end(), v.begin(), gen::coordinate_from_bits);
  const Orient2d::Tuple t2{Vec2{v[0], v[1]}, Vec2{v[2], v[3]}, Vec2{v[4], v[5]}};
  const Incircle::Tuple t4{Vec2{v[0], v[1]}, Vec2{v[2], v[3]}, Vec2{v[4], v[5]}, Vec2{v[6], v[7]}};
  const Orient3d::Tuple u4{Vec3{v[0], v[1], v[2]}, Vec3{v[3], v[4], v[5]}, Vec3{v[6], v[7], v[8]},
                           Vec3{v[9], v[10], v[11]}};
  const Insphere::Tuple u5{u4[0], u4[1], u4[2], u4[3], Vec3{v[12], v[13], v[14]}};
  RC_ASSERT(stage_disagreement<Orient2d>(t2) == "");
  RC_ASSERT(stage_disagreement<Incircle>(t4) == "");
  RC_ASSERT(stage_disagreement<Orient3d>(u4) == "");
  RC_ASSERT(stage_disagreement<Insphere>(u5) == "");
}

// --- Kettner et al.'s grid, exhaustively -----------------------------------------------------

TEST(KettnerGrid, Orient2dEveryPoint) {
  const gen::KettnerGrid g;
  int failures = 0, naive_wrong = 0, undecided_by_filter = 0;
  for (int i = 0; i < g.kSize; ++i) {
    for (int j = 0; j < g.kSize; ++j) {
      const Orient2d::Tuple t{g.p(i, j), g.q, g.r};
      const std::string msg = stage_disagreement<Orient2d>(t);
      if (!msg.empty() && ++failures <= 5) ADD_FAILURE() << "grid (" << i << ", " << j << "): " << msg;
      // The plain double evaluation of the paper, to show the grid is adversarial.
      const Vec2 p = t[0];
      const double naive = (g.q.x - p.x) * (g.r.y - p.y) - (g.q.y - p.y) * (g.r.x - p.x);
      naive_wrong += dtlab::sign_of(naive) != ref::orient2d(p, g.q, g.r);
      undecided_by_filter += !Orient2d::semistatic(t).has_value();
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(naive_wrong, 0) << "the grid should defeat plain double arithmetic";
  EXPECT_GT(undecided_by_filter, 0);
  std::printf("  orient2d grid: plain doubles wrong on %d of 65536, semi-static undecided on %d\n",
              naive_wrong, undecided_by_filter);
}

TEST(KettnerGrid, IncircleEveryPoint) {
  const gen::KettnerCircleGrid g;
  ASSERT_EQ(ref::incircle(g.a, g.b, g.c, g.corner), Sign::Zero) << "the square's corners are cocircular";
  ASSERT_EQ(ref::orient2d(g.a, g.b, g.c), Sign::Positive);
  int failures = 0, inside = 0, outside = 0, on = 0;
  for (int i = 0; i < g.kSize; ++i) {
    for (int j = 0; j < g.kSize; ++j) {
      const Incircle::Tuple t{g.a, g.b, g.c, g.p(i, j)};
      const std::string msg = stage_disagreement<Incircle>(t);
      if (!msg.empty() && ++failures <= 5) ADD_FAILURE() << "grid (" << i << ", " << j << "): " << msg;
      const Sign s = ref::incircle(g.a, g.b, g.c, g.p(i, j));
      (s == Sign::Positive ? inside : (s == Sign::Negative ? outside : on)) += 1;
    }
  }
  EXPECT_EQ(failures, 0);
  // The circle crosses the grid: both sides occur, and the corner itself is on it.
  ASSERT_EQ(g.p(g.kSize / 2, g.kSize / 2), g.corner);
  EXPECT_GT(inside, 0);
  EXPECT_GT(outside, 0);
  EXPECT_GT(on, 0);
  std::printf("  incircle grid: inside %d, outside %d, on the circle %d\n", inside, outside, on);
}

// --- permutations ----------------------------------------------------------------------------

template <class P>
void permutation_property() {
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const auto f = family_at(*rc::gen::inRange(0, gen::kFamilyCount));
  gen::Rng rng(seed);
  for (int k = 0; k < 3; ++k) {
    const typename P::Tuple p = random_tuple<P>(rng, f);
    const std::string msg = permutation_disagreement(p, [](const auto& q) { return P::filtered(q); });
    if (!msg.empty()) {
      RC_FAIL(std::string(gen::to_string(f)) + ": " + msg);
    }
  }
}

RC_GTEST_PROP(PredicatePermutations, Orient2dAlternates, ()) { permutation_property<Orient2d>(); }
RC_GTEST_PROP(PredicatePermutations, IncircleAlternates, ()) { permutation_property<Incircle>(); }
RC_GTEST_PROP(PredicatePermutations, Orient3dAlternates, ()) { permutation_property<Orient3d>(); }
RC_GTEST_PROP(PredicatePermutations, InsphereAlternates, ()) { permutation_property<Insphere>(); }

// --- symbolic perturbation -------------------------------------------------------------------

// Degenerate-rich tuples for the perturbation: small grids, exact circles/spheres and lines/
// planes, at all scales.
template <class P>
typename P::Tuple degenerate_tuple(gen::Rng& rng) {
  static constexpr gen::Family kFamilies[] = {gen::Family::SmallGrid, gen::Family::Exact, gen::Family::ExactLarge,
                                              gen::Family::ExactSmall, gen::Family::ExactFar};
  const gen::Family f = kFamilies[gen::integer(rng, 0, 4)];
  return random_tuple<P>(rng, f);
}

// The perturbed sign equals the reference's evaluation of the documented scheme, is zero only for
// collinear (coplanar) points, and alternates under permutations like a determinant.
template <class P>
std::string perturbation_disagreement(const typename P::Tuple& p) {
  const Sign got = P::perturbed(p);
  const Sign want = P::reference_perturbed(p);
  std::string out;
  if (got != want)
    out += std::string("; perturbed ") + dtlab::to_string(got) + ", reference " + dtlab::to_string(want);
  if ((got == Sign::Zero) != P::lower_dimensional(p))
    out += std::string("; zero iff lower-dimensional fails, got ") + dtlab::to_string(got);
  if (!out.empty()) return "points " + describe(p) + out;
  return permutation_disagreement(p, [](const auto& q) { return P::perturbed(q); });
}

template <class P>
void sweep_perturbation(int tuples) {
  gen::Rng rng(gen::kDefaultSeed ^ 0x9e3779b97f4a7c15ULL);
  int failures = 0, resolved = 0;
  for (int k = 0; k < tuples && failures < 5; ++k) {
    const typename P::Tuple p = degenerate_tuple<P>(rng);
    if (has_duplicates(p)) continue;
    resolved += P::reference(p) == Sign::Zero && !P::lower_dimensional(p);
    if (const std::string msg = perturbation_disagreement<P>(p); !msg.empty()) {
      ++failures;
      ADD_FAILURE() << msg;
    }
  }
  EXPECT_GT(resolved, tuples / 10) << "too few exact zeros resolved by the perturbation";
}

TEST(Perturbation, IncircleSweep) { sweep_perturbation<Incircle>(3000); }
TEST(Perturbation, InsphereSweep) { sweep_perturbation<Insphere>(1500); }

template <class P>
void perturbation_property() {
  gen::Rng rng(*rc::gen::arbitrary<std::uint64_t>());
  for (int k = 0; k < 5; ++k) {
    const typename P::Tuple p = degenerate_tuple<P>(rng);
    if (has_duplicates(p)) continue;
    const std::string msg = perturbation_disagreement<P>(p);
    if (!msg.empty()) {
      RC_FAIL(msg);
    }
  }
}

RC_GTEST_PROP(Perturbation, IncircleNeverZeroOffALine, ()) { perturbation_property<Incircle>(); }
RC_GTEST_PROP(Perturbation, InsphereNeverZeroOffAPlane, ()) { perturbation_property<Insphere>(); }

// Cocircular (cospherical) sets in general position of the lower dimension: never zero.
TEST(Perturbation, ExactCircleAndSpherePointsNeverTie) {
  gen::Rng rng(gen::kDefaultSeed + 7);
  for (int k = 0; k < 300; ++k) {
    const auto c = gen::exact_cocircular2(rng, 4);
    const Incircle::Tuple t{c[0], c[1], c[2], c[3]};
    ASSERT_EQ(ref::incircle(c[0], c[1], c[2], c[3]), Sign::Zero);
    EXPECT_NE(Incircle::perturbed(t), Sign::Zero) << describe(t);
    const auto s = gen::exact_cospherical3(rng, 5);
    const Insphere::Tuple u{s[0], s[1], s[2], s[3], s[4]};
    ASSERT_EQ(ref::insphere(s[0], s[1], s[2], s[3], s[4]), Sign::Zero);
    if (!ref::all_coplanar(u)) {
      EXPECT_NE(Insphere::perturbed(u), Sign::Zero) << describe(u);
    }
  }
}

// --- counters --------------------------------------------------------------------------------

TEST(PredicateCounters, StageCountsAddUpToCalls) {
  gen::Rng rng(gen::kDefaultSeed + 11);
  dtlab::reset_predicate_stats();
  std::array<std::uint64_t, dtlab::kPredicateCount> calls{};
  for (int k = 0; k < 400; ++k) {
    const auto f = family_at(static_cast<int>(gen::integer(rng, 0, gen::kFamilyCount - 1)));
    Orient2d::filtered(random_tuple<Orient2d>(rng, f));
    Incircle::filtered(random_tuple<Incircle>(rng, f));
    Incircle::filtered(random_tuple<Incircle>(rng, f));
    Orient3d::filtered(random_tuple<Orient3d>(rng, f));
    Insphere::filtered(random_tuple<Insphere>(rng, f));
    // The uncounted predicate counts nothing, whichever stage decides.
    Insphere::uncounted(random_tuple<Insphere>(rng, f));
    calls[0] += 1;
    calls[1] += 2;
    calls[2] += 1;
    calls[3] += 1;
  }
  const PredicateStats s = dtlab::predicate_stats();
  for (std::size_t i = 0; i < dtlab::kPredicateCount; ++i) {
    const StageCounts& c = s.counts[i];
    EXPECT_EQ(c.semistatic + c.adaptive + c.exact, calls[i]) << s.to_json();
    EXPECT_EQ(c.calls(), calls[i]) << s.to_json();
    EXPECT_EQ(c.perturbed, 0u) << s.to_json();
  }
  EXPECT_EQ(s.total().calls(), calls[0] + calls[1] + calls[2] + calls[3]);
}

TEST(PredicateCounters, PerturbedCountsTheResolvedZeros) {
  gen::Rng rng(gen::kDefaultSeed + 13);
  for (int round = 0; round < 2; ++round) {
    dtlab::reset_predicate_stats();
    std::uint64_t calls = 0, zeros = 0;
    for (int k = 0; k < 500; ++k) {
      if (round == 0) {
        const Incircle::Tuple p = degenerate_tuple<Incircle>(rng);
        Incircle::perturbed(p);
        zeros += Incircle::reference(p) == Sign::Zero;
      } else {
        const Insphere::Tuple p = degenerate_tuple<Insphere>(rng);
        Insphere::perturbed(p);
        zeros += Insphere::reference(p) == Sign::Zero;
      }
      ++calls;
    }
    const StageCounts c = dtlab::predicate_stats()[round == 0 ? Predicate::Incircle : Predicate::Insphere];
    EXPECT_EQ(c.calls(), calls) << dtlab::predicate_stats().to_json();
    EXPECT_EQ(c.perturbed, zeros) << dtlab::predicate_stats().to_json();
    EXPECT_GT(zeros, 0u);
  }
}

}  // namespace
