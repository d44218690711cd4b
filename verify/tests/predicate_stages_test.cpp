// Each stage of the predicates on its own (semi-static, adaptive, exact expansion, GMP), the counted slow path,
// and the expansion arithmetic underneath, checked against a reference that shares no code with
// them: the determinant of the lifted matrix by Gaussian elimination over GMP rationals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "kernel/exact_rational.hpp"
#include "kernel/predicates.hpp"
#include "kernel/predicates/expansion.hpp"
#include "verify/exact_reference.hpp"

namespace dtlab {
namespace {

// The rational reference (verify/exact_reference.hpp): textbook homogeneous determinants over
// GMP rationals, a different road from the scaled-integer exact stage.

// The reference's conventions are those of predicates.hpp.
TEST(Reference, SignConventions) {
  EXPECT_EQ(reference::orient2d({0, 0}, {1, 0}, {0, 1}), Sign::Positive);
  EXPECT_EQ(reference::incircle({0, 0}, {1, 0}, {0, 1}, {0.25, 0.25}), Sign::Positive);
  EXPECT_EQ(reference::incircle({0, 0}, {1, 0}, {0, 1}, {2, 2}), Sign::Negative);
  EXPECT_EQ(reference::orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}), Sign::Positive);
  EXPECT_EQ(reference::insphere({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.25, 0.25, 0.25}), Sign::Positive);
  EXPECT_EQ(reference::insphere({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 2, 2}), Sign::Negative);
}

// ---------------------------------------------------------------- all stages on one input

// What each stage said about one input; nullopt where a stage did not decide.
struct Verdicts {
  FilteredSign semistatic, adaptive, expansion;
  Sign exact, filtered, reference;
};

Verdicts judge(const Vec2& a, const Vec2& b, const Vec2& c) {
  return {stage::orient2d_semistatic(a, b, c), stage::orient2d_adaptive(a, b, c),
          stage::orient2d_expansion(a, b, c), stage::orient2d_exact(a, b, c), orient2d(a, b, c),
          reference::orient2d(a, b, c)};
}
Verdicts judge(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  return {stage::incircle_semistatic(a, b, c, d), stage::incircle_adaptive(a, b, c, d),
          stage::incircle_expansion(a, b, c, d), stage::incircle_exact(a, b, c, d), incircle(a, b, c, d),
          reference::incircle(a, b, c, d)};
}
Verdicts judge(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return {stage::orient3d_semistatic(a, b, c, d), stage::orient3d_adaptive(a, b, c, d),
          stage::orient3d_expansion(a, b, c, d), stage::orient3d_exact(a, b, c, d), orient3d(a, b, c, d),
          reference::orient3d(a, b, c, d)};
}
Verdicts judge(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) {
  return {stage::insphere_semistatic(a, b, c, d, e), stage::insphere_adaptive(a, b, c, d, e),
          stage::insphere_expansion(a, b, c, d, e), stage::insphere_exact(a, b, c, d, e),
          insphere(a, b, c, d, e), reference::insphere(a, b, c, d, e)};
}

// How often each stage was the first to decide, over a family of inputs. Stage 3 (expansion)
// must decide every input on its own; GMP is never needed.
struct Tally {
  int semistatic = 0, adaptive = 0, expansion = 0;
  int zeros = 0;

  void add(const Verdicts& v, const std::string& what) {
    EXPECT_EQ(v.exact, v.reference) << what;
    EXPECT_EQ(v.filtered, v.reference) << what;
    if (v.semistatic) {
      EXPECT_EQ(*v.semistatic, v.reference) << what;
    }
    if (v.adaptive) {
      EXPECT_EQ(*v.adaptive, v.reference) << what;
    }
    EXPECT_EQ(v.expansion, v.reference) << what;
    if (v.semistatic) {
      ++semistatic;
    } else if (v.adaptive) {
      ++adaptive;
    } else {
      ++expansion;
    }
    if (v.reference == Sign::Zero) ++zeros;
  }
};

std::string describe(std::initializer_list<Vec2> points) {
  std::string s;
  char buf[64];
  for (const Vec2& p : points) {
    std::snprintf(buf, sizeof buf, "(%a, %a) ", p.x, p.y);
    s += buf;
  }
  return s;
}
std::string describe(std::initializer_list<Vec3> points) {
  std::string s;
  char buf[96];
  for (const Vec3& p : points) {
    std::snprintf(buf, sizeof buf, "(%a, %a, %a) ", p.x, p.y, p.z);
    s += buf;
  }
  return s;
}

// ---------------------------------------------------------------- hand-made cases

// Exact zeros on grid points: stage 1 cannot tell 0 from a tiny value, stage 2 can, since
// the differences are exact.
TEST(Stage2, DecidesExactZeroOnGridPoints) {
  const Vec2 a{0, 0}, b{1, 1}, c{2, 2};
  EXPECT_FALSE(stage::orient2d_semistatic(a, b, c));
  EXPECT_EQ(stage::orient2d_adaptive(a, b, c), Sign::Zero);

  const Vec2 p{0, 0}, q{1, 0}, r{1, 1}, s{0, 1};
  EXPECT_FALSE(stage::incircle_semistatic(p, q, r, s));
  EXPECT_EQ(stage::incircle_adaptive(p, q, r, s), Sign::Zero);

  const Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, xy{1, 1, 0}, z{0, 0, 1}, xyz{1, 1, 1};
  EXPECT_FALSE(stage::orient3d_semistatic(o, x, y, xy));
  EXPECT_EQ(stage::orient3d_adaptive(o, x, y, xy), Sign::Zero);
  EXPECT_FALSE(stage::insphere_semistatic(o, x, y, z, xyz));
  EXPECT_EQ(stage::insphere_adaptive(o, x, y, z, xyz), Sign::Zero);
}

// Exact zeros whose differences are exact but carry ~50 significant bits (points in [1, 2)):
// the expansions are long, the double-word estimate cannot decide, the exact expansion must.
TEST(Stage2, DecidesExactZeroWithLongMantissas) {
  // Multiples of 2^-51 with about 50 significant bits, so that p + 2s etc. are exact in [1, 2).
  const double s = 0x1.3c5a7e91d2b40p-3, t = 0x1.9e2d4b7c1a3f0p-3, w = 0x1.7a3b9c2d4e5f0p-4;
  const double p = 1.0, q = 1.0 + 0x1.5p-5, r = 1.0 + 0x1.9p-4;
  const Vec2 a{p, q}, b{p + s, q + t}, c{p + 2 * s, q + 2 * t};
  ASSERT_EQ(reference::orient2d(a, b, c), Sign::Zero);
  EXPECT_EQ(stage::orient2d_adaptive(a, b, c), Sign::Zero);
  // A rectangle is cocircular; a box's vertices are cospherical; a box face is coplanar.
  const Vec2 r0{p, q}, r1{p + s, q}, r2{p + s, q + t}, r3{p, q + t};
  ASSERT_EQ(reference::incircle(r0, r1, r2, r3), Sign::Zero);
  EXPECT_FALSE(stage::incircle_semistatic(r0, r1, r2, r3));
  EXPECT_EQ(stage::incircle_adaptive(r0, r1, r2, r3), Sign::Zero);
  const Vec3 o{p, q, r}, x{p + s, q, r}, y{p, q + t, r}, z{p, q, r + w}, xy{p + s, q + t, r};
  const Vec3 xyz{p + s, q + t, r + w};
  EXPECT_EQ(stage::orient3d_adaptive(o, x, y, xy), Sign::Zero);
  ASSERT_EQ(reference::insphere(o, x, y, z, xyz), Sign::Zero);
  EXPECT_FALSE(stage::insphere_semistatic(o, x, y, z, xyz));
  EXPECT_EQ(stage::insphere_adaptive(o, x, y, z, xyz), Sign::Zero);
  // One ulp off the sphere: the estimate decides, with the exact sign.
  const Vec3 off{p + s, q + t, std::nextafter(r + w, 2.0)};
  EXPECT_EQ(stage::insphere_adaptive(o, x, y, z, off), reference::insphere(o, x, y, z, off));
  EXPECT_TRUE(stage::insphere_adaptive(o, x, y, z, off));
}

// Four points in a plane x, y or z = const (the flat faces of axis-aligned parts), three on a
// line x or y = const, with long mantissas whose differences round: stage 2 decides the zero from
// the equal coordinate; one ulp off the plane it returns the exact sign (or defers).
TEST(Stage2, DecidesZeroInACoordinatePlane) {
  const double z = 0.1, u = 1e10 + 0.3, v = 3.7e-5, w = -2.2e7 + 0.77;
  const Vec3 a{u, v, z}, b{w, 0.123456789, z}, c{v, w, z}, d{u + 0.5, -w, z};
  ASSERT_EQ(reference::orient3d(a, b, c, d), Sign::Zero);
  EXPECT_FALSE(stage::orient3d_semistatic(a, b, c, d));
  EXPECT_EQ(stage::orient3d_adaptive(a, b, c, d), Sign::Zero);
  const Vec3 ax{z, u, v}, bx{z, w, 0.123456789}, cx{z, v, w}, dx{z, u + 0.5, -w};  // x = const
  EXPECT_EQ(stage::orient3d_adaptive(ax, bx, cx, dx), Sign::Zero);
  EXPECT_EQ(orient3d(ax, bx, cx, dx), Sign::Zero);
  const Vec2 p{v, z}, q{w, z}, r{u, z}, px{z, v}, qx{z, w}, rx{z, u};  // a line y or x = const
  ASSERT_EQ(reference::orient2d(p, q, r), Sign::Zero);
  EXPECT_EQ(stage::orient2d_adaptive(p, q, r), Sign::Zero);
  EXPECT_EQ(stage::orient2d_adaptive(px, qx, rx), Sign::Zero);
  const Vec3 off{d.x, d.y, std::nextafter(z, 1.0)};
  const Sign want = reference::orient3d(a, b, c, off);
  ASSERT_NE(want, Sign::Zero);
  if (const auto got = stage::orient3d_adaptive(a, b, c, off)) {
    EXPECT_EQ(*got, want);
  }
  EXPECT_EQ(orient3d(a, b, c, off), want);
}

// Nonzero but tiny determinants with exact differences: stage 2 returns the exact sign.
TEST(Stage2, DecidesNearlyDegenerateWithExactDifferences) {
  const double big = 0x1p30;
  // det = 2^30 * 2^30 - (2^30 + 1)(2^30 - 1) = 1, against a stage-1 bound near 2^10.
  const Vec2 a{0, 0}, b{big, big + 1}, c{big - 1, big};
  EXPECT_FALSE(stage::orient2d_semistatic(a, b, c));
  EXPECT_EQ(stage::orient2d_adaptive(a, b, c), Sign::Positive);
  EXPECT_EQ(stage::orient2d_adaptive(a, c, b), Sign::Negative);

  // A point 2^-40 off the circle of radius 2^20 through (±2^20, 0), (0, 2^20).
  const double r = 0x1p20;
  const Vec2 p{r, 0}, q{0, r}, s{-r, 0};
  const Vec2 in{0, -r + 0x1p-30}, out{0, -r - 0x1p-30};
  EXPECT_FALSE(stage::incircle_semistatic(p, q, s, in));
  EXPECT_EQ(stage::incircle_adaptive(p, q, s, in), Sign::Positive);
  EXPECT_EQ(stage::incircle_adaptive(p, q, s, out), Sign::Negative);

  // det = big^2 * 2^-20 = 2^40 against a stage-1 bound near 2^42.
  const Vec3 o{0, 0, 0}, x{big, 0, 0}, y{0, big, big}, lifted{big, big, big + 0x1p-20};
  EXPECT_FALSE(stage::orient3d_semistatic(o, x, y, lifted));
  EXPECT_EQ(stage::orient3d_adaptive(o, x, y, lifted), Sign::Positive);
  EXPECT_EQ(stage::orient3d_adaptive(o, y, x, lifted), Sign::Negative);

  const Vec3 e{r, 0, 0}, f{0, r, 0}, g{0, 0, r}, h{-r, 0, 0};
  const Vec3 inside{0, 0, -r + 0x1p-30}, outside{0, 0, -r - 0x1p-30};
  ASSERT_EQ(orient3d(e, f, g, h), Sign::Negative);  // so inside gives a negative insphere
  EXPECT_FALSE(stage::insphere_semistatic(e, f, g, h, inside));
  EXPECT_EQ(stage::insphere_adaptive(e, f, g, h, inside), Sign::Negative);
  EXPECT_EQ(stage::insphere_adaptive(e, f, g, h, outside), Sign::Positive);
}

// Rounded differences, but far enough from zero for the rounding bound: stage 2 certifies
// where stage 1's cruder bound (column maxima from different rows) cannot.
TEST(Stage2, CertifiesDespiteRoundedDifferences) {
  // d1 = (1 - 2^-80 -> 1, 2^-10), d2 = (2^-10 - 2^-80 -> 2^-10, 2^-20 + 2^-65): E = 2^-65,
  // rounding bound ~2^-71, stage-1 bound ~2^-60.
  const Vec2 a{0x1p-80, 0}, b{1, 0x1p-10}, c{0x1p-10, 0x1p-20 + 0x1p-65};
  const Verdicts v = judge(a, b, c);
  EXPECT_FALSE(v.semistatic);
  EXPECT_EQ(v.adaptive, Sign::Positive);
  EXPECT_EQ(v.reference, Sign::Positive);
}

// Differences that round, and a determinant of the rounded differences that is exactly zero
// while the exact one is not: stage 2 estimates on the exact differences (rounded value and
// tail), so it still certifies the sign; the expansion stage agrees.
TEST(Stage2, CertifiesWhenOnlyTheRoundedDifferencesAreDegenerate) {
  const double r = 0x1p50, delta = 0x1p-10;  // r - delta rounds to r
  {  // rounded differences (2r,0), (r,r), (r,-r) are cocircular with d; d itself is inside
    const Vec2 a{2 * r, 0}, b{r, r}, c{r, -r}, d{delta, 0};
    const Verdicts v = judge(a, b, c, d);
    EXPECT_FALSE(v.semistatic);
    EXPECT_EQ(v.adaptive, Sign::Positive);
    EXPECT_EQ(v.expansion, Sign::Positive);
    EXPECT_EQ(v.exact, Sign::Positive);
    EXPECT_EQ(v.reference, Sign::Positive);
  }
  {  // rounded differences lie in the plane x = y; the exact ones give det = delta r^2
    const Vec3 a{delta, 0, 0}, b{r, r, 0}, c{r, r, r}, d{2 * r, 2 * r, r};
    const Verdicts v = judge(a, b, c, d);
    EXPECT_FALSE(v.semistatic);
    EXPECT_EQ(v.adaptive, Sign::Positive);
    EXPECT_EQ(v.expansion, Sign::Positive);
    EXPECT_EQ(v.exact, Sign::Positive);
    EXPECT_EQ(v.reference, Sign::Positive);
  }
  {  // rounded differences on the sphere of center (r,0,0) through the origin; e is inside
    const Vec3 a{2 * r, 0, 0}, b{r, r, 0}, c{r, -r, 0}, d{r, 0, r}, e{delta, 0, 0};
    const Sign inside = orient3d(a, b, c, d);  // insphere > 0 inside a positive tetrahedron
    ASSERT_NE(inside, Sign::Zero);
    const Verdicts v = judge(a, b, c, d, e);
    EXPECT_FALSE(v.semistatic);
    EXPECT_EQ(v.adaptive, inside);
    EXPECT_EQ(v.expansion, inside);
    EXPECT_EQ(v.exact, inside);
    EXPECT_EQ(v.reference, inside);
  }
}

// Exact zeros with rounded differences: no estimate can certify zero, so stage 2 defers and
// stage 3 (exact expansions on two-component differences) decides.
TEST(Stage3, DecidesExactZeroWithRoundedDifferences) {
  const double big = 0x1p60, one = 1.0, t = 3 * 0x1p-60;  // big + one rounds
  {  // collinear along y = x, mixed magnitudes
    const Verdicts v = judge(Vec2{t, t}, Vec2{1e15, 1e15}, Vec2{2e15, 2e15});
    EXPECT_FALSE(v.semistatic);
    EXPECT_FALSE(v.adaptive);
    EXPECT_EQ(v.expansion, Sign::Zero);
    EXPECT_EQ(v.exact, Sign::Zero);
    EXPECT_EQ(v.reference, Sign::Zero);
  }
  {  // (A, B), (B, A), (-A, -B), (-B, -A) lie on the circle x^2 + y^2 = A^2 + B^2
    const Verdicts v = judge(Vec2{big, one}, Vec2{one, big}, Vec2{-big, -one}, Vec2{-one, -big});
    EXPECT_FALSE(v.semistatic);
    EXPECT_FALSE(v.adaptive);
    EXPECT_EQ(v.expansion, Sign::Zero);
    EXPECT_EQ(v.reference, Sign::Zero);
  }
  {  // four points of the plane x = y, one of them tiny
    const Verdicts v = judge(Vec3{t, t, 0}, Vec3{1e15, 1e15, 0}, Vec3{0, 0, 1e15}, Vec3{2e15, 2e15, 5e14});
    EXPECT_FALSE(v.semistatic);
    EXPECT_FALSE(v.adaptive);
    EXPECT_EQ(v.expansion, Sign::Zero);
    EXPECT_EQ(v.reference, Sign::Zero);
  }
  {  // five points of the sphere |p|^2 = A^2 + B^2, not coplanar
    const Verdicts v = judge(Vec3{big, one, 0}, Vec3{one, 0, big}, Vec3{0, big, one}, Vec3{-big, -one, 0},
                             Vec3{-one, -big, 0});
    EXPECT_FALSE(v.semistatic);
    EXPECT_FALSE(v.adaptive);
    EXPECT_EQ(v.expansion, Sign::Zero);
    EXPECT_EQ(v.reference, Sign::Zero);
  }
}

// Stage 2 evaluates exact differences that are small multiples of one power of two in integers
// (small_integers.hpp), up to 2^24 (insphere) or 2^30 (the others) units. At and just past those
// limits, scaled to both ends of the range, every stage must still agree with the reference.
TEST(Stage2, IntegerEvaluationAtItsLimits) {
  for (const double unit : {1.0, 0x1p-160, 0x1p100}) {
    for (const double half : {0x1p23 - 1, 0x1p23, 0x1p29 - 1, 0x1p29}) {
      const double r = half * unit, u = unit;
      // Points of the sphere (circle) of radius r about the origin: differences up to 2r.
      const Vec3 a{r, 0, 0}, b{0, r, 0}, c{0, 0, r}, d{-r, 0, 0}, on{0, -r, 0};
      const Vec3 in{0, -r + u, 0}, out{0, -r - u, 0}, off{u, -r, u};
      Tally t;
      for (const Vec3& e : {on, in, out, off}) {
        t.add(judge(a, b, c, d, e), describe({a, b, c, d, e}));
        t.add(judge(a, b, c, e), describe({a, b, c, e}));
        const Vec2 e2{e.x, e.y};
        t.add(judge(Vec2{r, 0}, Vec2{0, r}, Vec2{-r, 0}, e2), describe({Vec2{r, 0}, Vec2{0, r}, Vec2{-r, 0}, e2}));
        t.add(judge(Vec2{r, 0}, Vec2{0, r}, e2), describe({Vec2{r, 0}, Vec2{0, r}, e2}));
      }
      EXPECT_GT(t.zeros, 0);
      EXPECT_EQ(t.expansion, 0) << "exact differences never reach stage 3";
    }
  }
}

// ---------------------------------------------------------------- counters

TEST(SlowPath, CountsTheStageThatDecided) {
  auto delta_of = [](const std::function<void()>& call) {
    const PredicateStats before = predicate_stats();
    call();
    return predicate_stats() - before;
  };
  const double r = 0x1p50, delta = 0x1p-10, big = 0x1p60;
  struct Case {
    const char* name;
    Predicate predicate;
    std::function<Sign()> call;
    Sign expected;
    int stage;  // 0 semistatic, 1 adaptive, 2 exact (stage 3: expansions; GMP is never needed)
  };
  const std::vector<Case> cases = {
      {"orient2d easy", Predicate::Orient2d, [] { return orient2d({0, 0}, {1, 0}, {0, 1}); }, Sign::Positive, 0},
      {"orient2d grid", Predicate::Orient2d, [] { return orient2d({0, 0}, {1, 1}, {2, 2}); }, Sign::Zero, 1},
      {"orient2d rounded zero", Predicate::Orient2d,
       [] { return orient2d({3 * 0x1p-60, 3 * 0x1p-60}, {1e15, 1e15}, {2e15, 2e15}); }, Sign::Zero, 2},
      {"incircle easy", Predicate::Incircle, [] { return incircle({0, 0}, {1, 0}, {0, 1}, {5, 5}); }, Sign::Negative, 0},
      {"incircle grid", Predicate::Incircle, [] { return incircle({0, 0}, {1, 0}, {1, 1}, {0, 1}); }, Sign::Zero, 1},
      {"incircle rounded", Predicate::Incircle,
       [=] { return incircle({2 * r, 0}, {r, r}, {r, -r}, {delta, 0}); }, Sign::Positive, 1},
      {"incircle rounded zero", Predicate::Incircle,
       [=] { return incircle({big, 1}, {1, big}, {-big, -1}, {-1, -big}); }, Sign::Zero, 2},
      {"orient3d easy", Predicate::Orient3d,
       [] { return orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}); }, Sign::Positive, 0},
      {"orient3d grid", Predicate::Orient3d,
       [] { return orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}); }, Sign::Zero, 1},
      {"orient3d rounded", Predicate::Orient3d,
       [=] { return orient3d({delta, 0, 0}, {r, r, 0}, {r, r, r}, {2 * r, 2 * r, r}); }, Sign::Positive, 1},
      {"orient3d rounded zero", Predicate::Orient3d,
       [=] { return orient3d({0x1p-60, 0x1p-60, 0}, {1e15, 1e15, 0}, {0, 0, 1e15}, {2e15, 2e15, 5e14}); },
       Sign::Zero, 2},
      {"insphere easy", Predicate::Insphere,
       [] { return insphere({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {9, 9, 9}); }, Sign::Negative, 0},
      {"insphere grid", Predicate::Insphere,
       [] { return insphere({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}); }, Sign::Zero, 1},
      {"insphere rounded zero", Predicate::Insphere,
       [=] { return insphere({big, 1, 0}, {1, 0, big}, {0, big, 1}, {-big, -1, 0}, {-1, -big, 0}); }, Sign::Zero, 2},
  };
  for (const Case& c : cases) {
    Sign got = Sign::Zero;
    const PredicateStats d = delta_of([&] { got = c.call(); });
    EXPECT_EQ(got, c.expected) << c.name;
    const StageCounts& s = d[c.predicate];
    EXPECT_EQ(s.semistatic, c.stage == 0 ? 1u : 0u) << c.name;
    EXPECT_EQ(s.adaptive, c.stage == 1 ? 1u : 0u) << c.name;
    EXPECT_EQ(s.exact, c.stage == 2 ? 1u : 0u) << c.name;
    EXPECT_EQ(s.gmp, 0u) << c.name;
    EXPECT_EQ(d.total().calls(), 1u) << c.name << ": no other predicate counted";
  }
}

// ---------------------------------------------------------------- random and near-degenerate

class Inputs {
 public:
  explicit Inputs(std::uint64_t seed) : rng_(seed) {}

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  // A scale 2^k and an offset, so that differences are sometimes exact, sometimes rounded.
  double scale() { return std::ldexp(1.0, kScales[integer(0, 6)]); }
  double offset() { return kOffsets[integer(0, 4)]; }

 private:
  static constexpr int kScales[7] = {-120, -40, -1, 0, 10, 40, 120};
  static constexpr double kOffsets[5] = {0.0, 0.0, 1.0, 1e15, -3.0e30};
  std::mt19937_64 rng_;
};

// Points on a line, circle, plane or sphere computed in doubles (hence a few ulps off), at
// many scales and offsets; plus small-integer grids (exact degeneracies) and mixed magnitudes.
TEST(AllStages, AgreeWithExactSignOnNearDegenerate2d) {
  Inputs in(20240611);
  Tally orient, circle;
  for (int trial = 0; trial < 3000; ++trial) {
    const int family = trial % 4;
    const double s = in.scale(), o = in.offset();
    auto pt = [&](double x, double y) { return Vec2{o + s * x, o + s * y}; };
    if (family == 0) {  // nearly collinear / cocircular
      const Vec2 a = pt(in.uniform(-1, 1), in.uniform(-1, 1)), b = pt(in.uniform(-1, 1), in.uniform(-1, 1));
      const double t = in.uniform(-2, 2);
      const Vec2 c{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
      orient.add(judge(a, b, c), describe({a, b, c}));
      Vec2 q[4];
      const double cx = in.uniform(-1, 1), cy = in.uniform(-1, 1), r = in.uniform(0.1, 1);
      for (Vec2& p : q) {
        const double th = in.uniform(0, 6.283185307179586);
        p = pt(cx + r * std::cos(th), cy + r * std::sin(th));
      }
      circle.add(judge(q[0], q[1], q[2], q[3]), describe({q[0], q[1], q[2], q[3]}));
    } else if (family == 1) {  // integer grid: exact zeros
      Vec2 q[4];
      for (Vec2& p : q) p = pt(in.integer(-3, 3), in.integer(-3, 3));
      orient.add(judge(q[0], q[1], q[2]), describe({q[0], q[1], q[2]}));
      circle.add(judge(q[0], q[1], q[2], q[3]), describe({q[0], q[1], q[2], q[3]}));
    } else if (family == 2) {  // mixed magnitudes: a tiny point with large ones nearly on a line
      const Vec2 a{in.uniform(-1, 1) * 0x1p-30, in.uniform(-1, 1) * 0x1p-30};
      const double m = in.integer(1, 5) / 3.0, big = 1e15 * in.integer(1, 4);
      const Vec2 b{big, big * m}, c{2 * big, 2 * big * m};
      orient.add(judge(a, b, c), describe({a, b, c}));
      // rounded differences cocircular through the tiny point, as in the hand-made case
      const double rr = std::ldexp(1.0, in.integer(40, 60));
      const Vec2 p{2 * rr, 0}, q{rr, rr}, w{rr, -rr}, d{in.uniform(-1, 1) * 0x1p-12, 0};
      circle.add(judge(p, q, w, d), describe({p, q, w, d}));
      // (A, B), (B, A), (-A, -B), (-B, -A): cocircular, with rounded differences
      const double one = in.integer(1, 9);
      const Vec2 c0{rr, one}, c1{one, rr}, c2{-rr, -one}, c3{-one, -rr};
      circle.add(judge(c0, c1, c2, c3), describe({c0, c1, c2, c3}));
    } else if (trial % 8 == 3) {  // rectangles in [1, 2)^2: exact zeros, long mantissas
      const double x0 = in.uniform(1, 1.5), y0 = in.uniform(1, 1.5);
      const double w = in.uniform(0, 0.5), h = in.uniform(0, 0.5);
      const Vec2 a{x0, y0}, b{x0 + w, y0}, c{x0 + w, y0 + h}, d{x0, y0 + h};
      orient.add(judge(a, b, Vec2{x0 + h, y0}), describe({a, b}));
      circle.add(judge(a, b, c, d), describe({a, b, c, d}));
    } else {  // uniform random points
      Vec2 q[4];
      for (Vec2& p : q) p = pt(in.uniform(-1, 1), in.uniform(-1, 1));
      orient.add(judge(q[0], q[1], q[2]), describe({q[0], q[1], q[2]}));
      circle.add(judge(q[0], q[1], q[2], q[3]), describe({q[0], q[1], q[2], q[3]}));
    }
  }
  for (const Tally* t : {&orient, &circle}) {
    EXPECT_GT(t->semistatic, 0);
    EXPECT_GT(t->adaptive, 0);
    EXPECT_GT(t->expansion, 0);
    EXPECT_GT(t->zeros, 0);
  }
}

TEST(AllStages, AgreeWithExactSignOnNearDegenerate3d) {
  Inputs in(977);
  Tally orient, sphere;
  for (int trial = 0; trial < 2000; ++trial) {
    const int family = trial % 4;
    const double s = in.scale(), o = in.offset();
    auto pt = [&](double x, double y, double z) { return Vec3{o + s * x, o + s * y, o + s * z}; };
    auto random_point = [&] { return pt(in.uniform(-1, 1), in.uniform(-1, 1), in.uniform(-1, 1)); };
    if (family == 0) {  // nearly coplanar / cospherical
      const Vec3 a = random_point(), b = random_point(), c = random_point();
      const double u = in.uniform(-2, 2), v = in.uniform(-2, 2);
      const Vec3 d = a + u * (b - a) + v * (c - a);
      orient.add(judge(a, b, c, d), describe({a, b, c, d}));
      Vec3 q[5];
      const double cx = in.uniform(-1, 1), cy = in.uniform(-1, 1), cz = in.uniform(-1, 1);
      const double r = in.uniform(0.1, 1);
      for (Vec3& p : q) {
        const double th = in.uniform(0, 6.283185307179586), z = in.uniform(-1, 1);
        const double rho = std::sqrt(1 - z * z);
        p = pt(cx + r * rho * std::cos(th), cy + r * rho * std::sin(th), cz + r * z);
      }
      sphere.add(judge(q[0], q[1], q[2], q[3], q[4]), describe({q[0], q[1], q[2], q[3], q[4]}));
    } else if (family == 1) {  // integer grid
      Vec3 q[5];
      for (Vec3& p : q) p = pt(in.integer(-2, 2), in.integer(-2, 2), in.integer(-2, 2));
      orient.add(judge(q[0], q[1], q[2], q[3]), describe({q[0], q[1], q[2], q[3]}));
      sphere.add(judge(q[0], q[1], q[2], q[3], q[4]), describe({q[0], q[1], q[2], q[3], q[4]}));
    } else if (family == 2) {  // mixed magnitudes, rounded differences nearly degenerate
      const double rr = std::ldexp(1.0, in.integer(40, 60)), delta = in.uniform(-1, 1) * 0x1p-12;
      const Vec3 a{delta, 0, 0}, b{rr, rr, 0}, c{rr, rr, rr}, d{2 * rr, 2 * rr, rr};
      orient.add(judge(a, b, c, d), describe({a, b, c, d}));
      const Vec3 p{2 * rr, 0, 0}, q{rr, rr, 0}, w{rr, -rr, 0}, x{rr, 0, rr};
      sphere.add(judge(p, q, w, x, a), describe({p, q, w, x, a}));
      // exact zeros whose differences round: stage 3's cases
      const double t = in.uniform(-1, 1) * 0x1p-30, one = in.integer(1, 9);
      const Vec3 f{t, t, 0}, g{rr, rr, 0}, h{0, 0, rr}, k{2 * rr, 2 * rr, rr};
      orient.add(judge(f, g, h, k), describe({f, g, h, k}));
      const Vec3 s0{rr, one, 0}, s1{one, 0, rr}, s2{0, rr, one}, s3{-rr, -one, 0}, s4{-one, -rr, 0};
      sphere.add(judge(s0, s1, s2, s3, s4), describe({s0, s1, s2, s3, s4}));
    } else if (trial % 8 == 3) {  // boxes in [1, 2)^3: exact zeros, long mantissas
      const double x0 = in.uniform(1, 1.5), y0 = in.uniform(1, 1.5), z0 = in.uniform(1, 1.5);
      const double w = in.uniform(0, 0.5), h = in.uniform(0, 0.5), l = in.uniform(0, 0.5);
      const Vec3 a{x0, y0, z0}, b{x0 + w, y0, z0}, c{x0, y0 + h, z0}, d{x0, y0, z0 + l};
      const Vec3 e{x0 + w, y0 + h, z0 + l}, f{x0 + w, y0 + h, z0};
      orient.add(judge(a, b, c, f), describe({a, b, c, f}));
      sphere.add(judge(a, b, c, d, e), describe({a, b, c, d, e}));
    } else {
      Vec3 q[5];
      for (Vec3& p : q) p = random_point();
      orient.add(judge(q[0], q[1], q[2], q[3]), describe({q[0], q[1], q[2], q[3]}));
      sphere.add(judge(q[0], q[1], q[2], q[3], q[4]), describe({q[0], q[1], q[2], q[3], q[4]}));
    }
  }
  for (const Tally* t : {&orient, &sphere}) {
    EXPECT_GT(t->semistatic, 0);
    EXPECT_GT(t->adaptive, 0);
    EXPECT_GT(t->expansion, 0);
    EXPECT_GT(t->zeros, 0);
  }
}

// ---------------------------------------------------------------- extreme magnitudes

// The ends of the supported range: differences down to 2^-194 (products of five near 2^-970)
// and up to 2^143 (products near 2^715). Every stage must still agree with the reference.
TEST(AllStages, ExtremeMagnitudes) {
  const double lo = 0x1p-142, step = 0x1p-194, hi = 0x1p138;
  // Integer points k mapped to lo + k * step (exact: the ulp of lo is step) and to k * hi.
  auto tiny = [&](int x, int y, int z) { return Vec3{lo + x * step, lo + y * step, lo + z * step}; };
  auto huge = [&](int x, int y, int z) { return Vec3{x * hi, y * hi, z * hi}; };
  for (auto map : {std::function<Vec3(int, int, int)>(tiny), std::function<Vec3(int, int, int)>(huge)}) {
    // Octahedron around (2,2,2) of radius 1, and points inside / outside its sphere.
    const Vec3 a = map(1, 2, 2), b = map(3, 2, 2), c = map(2, 1, 2), d = map(2, 2, 1);
    const Vec3 on = map(2, 2, 3), inside = map(2, 2, 2), outside = map(3, 3, 3);
    const Sign orientation = reference::orient3d(a, b, c, d);
    ASSERT_NE(orientation, Sign::Zero);
    Tally t;
    t.add(judge(a, b, c, d, on), "on");
    t.add(judge(a, b, c, d, inside), "inside");
    t.add(judge(a, b, c, d, outside), "outside");
    EXPECT_EQ(insphere(a, b, c, d, on), Sign::Zero);
    EXPECT_EQ(insphere(a, b, c, d, inside), orientation);
    EXPECT_EQ(insphere(a, b, c, d, outside), -orientation);
    t.add(judge(a, b, c, d), "orient3d");
    t.add(judge(map(0, 0, 0), map(1, 1, 1), map(3, 3, 3), map(1, 2, 3)), "collinear");
    const Vec2 p{a.x, a.y}, q{b.x, b.y}, r{c.x, c.y}, s{map(2, 3, 0).x, map(2, 3, 0).y};
    t.add(judge(p, q, r, s), "incircle on");
    t.add(judge(p, q, r, Vec2{inside.x, inside.y}), "incircle inside");
    t.add(judge(p, q, r), "orient2d");
    EXPECT_EQ(incircle(p, q, r, s), Sign::Zero);
  }
  // Tiny coordinates whose differences carry 29 significant bits (not short): the double-word
  // estimate or its underflow guard, then the exact expansion.
  const double longer = 0x1.3c5a7e9p-166;  // a multiple of 2^-194
  Tally tiny_long;
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = tiny(1, 2, 2), b = tiny(3, 2, 2), c = tiny(2, 1, 2), d = tiny(2, 2, 1);
    const Vec3 e{lo + 2 * step + k * longer, lo + 2 * step, lo + (2 + k) * step};
    tiny_long.add(judge(a, b, c, d, e), "tiny long insphere");
    tiny_long.add(judge(a, b, c, e), "tiny long orient3d");
    tiny_long.add(judge(Vec2{a.x, a.y}, Vec2{b.x, b.y}, Vec2{c.x, c.y}, Vec2{e.x, e.y}), "tiny long incircle");
    tiny_long.add(judge(Vec2{a.x, a.y}, Vec2{b.x, b.y}, Vec2{e.x, e.y}), "tiny long orient2d");
  }
  // Both ends in one call: the differences round, only the exact stage may decide.
  const double top = 0x1p142;
  Tally mixed;
  mixed.add(judge(Vec2{lo, lo}, Vec2{top, top}, Vec2{-top, -top}), "mixed orient2d");
  mixed.add(judge(Vec2{lo, 0}, Vec2{top, 0}, Vec2{0, top}, Vec2{-top, 0}), "mixed incircle");
  mixed.add(judge(Vec3{lo, lo, lo}, Vec3{top, 0, 0}, Vec3{0, top, 0}, Vec3{0, 0, top}), "mixed orient3d");
  mixed.add(judge(Vec3{top, 0, 0}, Vec3{0, top, 0}, Vec3{0, 0, top}, Vec3{-top, 0, 0}, Vec3{0, 0, lo}),
            "mixed insphere");
  mixed.add(judge(Vec3{top, 0, 0}, Vec3{0, top, 0}, Vec3{0, 0, top}, Vec3{-top, 0, 0}, Vec3{0, -top, lo}),
            "mixed insphere near");
}

// ---------------------------------------------------------------- expansion arithmetic

Rational value(const double* c, int n) {
  Rational v(0.0);
  for (int i = 0; i < n; ++i) v = v + Rational(c[i]);
  return v;
}

// Nonoverlapping: each component's magnitude is below the lowest set bit of the next.
bool nonoverlapping(const double* c, int n) {
  for (int i = 0; i + 1 < n; ++i) {
    if (c[i] == 0.0 || c[i + 1] == 0.0) return false;  // zeros are eliminated
    int e = 0;
    const double m = std::frexp(c[i + 1], &e);  // c = m 2^e, m has 53 bits
    long long mantissa = std::llabs(static_cast<long long>(std::ldexp(m, 53)));
    int low = e - 53;
    while ((mantissa & 1) == 0) {
      mantissa >>= 1;
      ++low;
    }
    if (!(std::fabs(c[i]) < std::ldexp(1.0, low))) return false;
  }
  return true;
}

TEST(Expansion, ProductsAndSumsAreExactAndNonoverlapping) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> expo(-60, 60);
  for (int trial = 0; trial < 2000; ++trial) {
    double v[6];
    for (double& x : v) x = std::ldexp(unit(rng), expo(rng));
    const auto p = expansion::product(v[0], v[1]);
    EXPECT_EQ((value(p.c, p.size) - Rational(v[0]) * Rational(v[1])).sign(), Sign::Zero);
    const auto m = expansion::cross_difference(v[0], v[1], v[2], v[3]);
    ASSERT_TRUE(nonoverlapping(m.c, m.size));
    EXPECT_EQ((value(m.c, m.size) - (Rational(v[0]) * Rational(v[1]) - Rational(v[2]) * Rational(v[3]))).sign(), Sign::Zero);
    const auto l = expansion::sum(expansion::square(v[4]), expansion::square(v[5]));
    const auto lm = expansion::product(l, m);
    ASSERT_TRUE(nonoverlapping(lm.c, lm.size));
    EXPECT_EQ((value(lm.c, lm.size) - value(l.c, l.size) * value(m.c, m.size)).sign(), Sign::Zero);
    const auto s = expansion::scale(lm, v[2]);
    ASSERT_TRUE(nonoverlapping(s.c, s.size));
    EXPECT_EQ((value(s.c, s.size) - value(lm.c, lm.size) * Rational(v[2])).sign(), Sign::Zero);
    auto compressed = lm;
    compressed.size = expansion::compress_raw(compressed.c, compressed.size);
    ASSERT_TRUE(nonoverlapping(compressed.c, compressed.size));
    EXPECT_LE(compressed.size, lm.size);
    EXPECT_EQ((value(compressed.c, compressed.size) - value(lm.c, lm.size)).sign(), Sign::Zero);
    EXPECT_EQ(compressed.sign(), lm.sign());
    const auto z = expansion::difference(lm, lm);
    EXPECT_EQ(z.size, 0);
    EXPECT_EQ(z.sign(), Sign::Zero);
    EXPECT_EQ(s.sign(), value(s.c, s.size).sign());
  }
}

}  // namespace
}  // namespace dtlab
