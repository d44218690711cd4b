// The symbolic perturbation of incircle and insphere (kernel/predicates/perturbation.hpp):
// (1) it never answers zero outside the documented case and behaves as a determinant under
// permutations; (2) it is the sign of a real perturbation, checked against GMP rationals with
// eps = 2^-60; (3) on cocircular and cospherical sets, the simplices it calls empty form exactly
// one triangulation of the convex hull, whatever the order of the points or the arguments.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "kernel/exact_rational.hpp"
#include "kernel/predicates.hpp"
#include "verify/exact_reference.hpp"

namespace dtlab {
namespace {

// ---------------------------------------------------------------- point sets

std::vector<Vec2> circle_points(int r2) {  // integer points on x^2 + y^2 = r2
  std::vector<Vec2> out;
  for (int x = -r2; x <= r2; ++x) {
    for (int y = -r2; y <= r2; ++y) {
      if (x * x + y * y == r2) out.push_back({double(x), double(y)});
    }
  }
  return out;
}

std::vector<Vec3> sphere_points(int r2) {  // integer points on x^2 + y^2 + z^2 = r2
  std::vector<Vec3> out;
  for (int x = -r2; x <= r2; ++x) {
    for (int y = -r2; y <= r2; ++y) {
      for (int z = -r2; z <= r2; ++z) {
        if (x * x + y * y + z * z == r2) out.push_back({double(x), double(y), double(z)});
      }
    }
  }
  return out;
}

std::vector<Vec2> grid2(int n) {
  std::vector<Vec2> out;
  for (int x = 0; x < n; ++x) {
    for (int y = 0; y < n; ++y) out.push_back({double(x), double(y)});
  }
  return out;
}

std::vector<Vec3> grid3(int n) {
  std::vector<Vec3> out;
  for (int x = 0; x < n; ++x) {
    for (int y = 0; y < n; ++y) {
      for (int z = 0; z < n; ++z) out.push_back({double(x), double(y), double(z)});
    }
  }
  return out;
}

std::vector<Vec3> cube() {
  std::vector<Vec3> out;
  for (int k = 0; k < 8; ++k) out.push_back({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)});
  return out;
}

const std::vector<Vec3> kOctahedron = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

int parity(const std::vector<int>& perm) {
  int inversions = 0;
  for (std::size_t i = 0; i < perm.size(); ++i) {
    for (std::size_t j = i + 1; j < perm.size(); ++j) inversions += perm[i] > perm[j];
  }
  return inversions % 2 ? -1 : 1;
}

Sign perturbed(const std::array<Vec2, 4>& p) { return incircle_perturbed(p[0], p[1], p[2], p[3]); }
Sign perturbed(const std::array<Vec3, 5>& p) { return insphere_perturbed(p[0], p[1], p[2], p[3], p[4]); }

bool all_collinear(const std::array<Vec2, 4>& p) {
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      for (int k = j + 1; k < 4; ++k) {
        if (orient2d(p[i], p[j], p[k]) != Sign::Zero) return false;
      }
    }
  }
  return true;
}

bool all_coplanar(const std::array<Vec3, 5>& p) {
  for (int i = 0; i < 5; ++i) {
    std::array<Vec3, 4> q;
    int n = 0;
    for (int j = 0; j < 5; ++j) {
      if (j != i) q[n++] = p[j];
    }
    if (orient3d(q[0], q[1], q[2], q[3]) != Sign::Zero) return false;
  }
  return true;
}

// ---------------------------------------------------------------- (1) never zero, alternating

template <std::size_t N, class Point>
void check_alternating(const std::array<Point, N>& p) {
  const Sign base = perturbed(p);
  std::vector<int> perm(N);
  std::iota(perm.begin(), perm.end(), 0);
  do {
    std::array<Point, N> q;
    for (std::size_t i = 0; i < N; ++i) q[i] = p[perm[i]];
    const Sign expected = parity(perm) > 0 ? base : -base;
    ASSERT_EQ(perturbed(q), expected);
  } while (std::next_permutation(perm.begin(), perm.end()));
}

TEST(Perturbation, IncircleNeverZeroAndAlternating) {
  std::mt19937_64 rng(11);
  const std::vector<Vec2> pool = [] {  // distinct points: the scheme's precondition
    std::vector<Vec2> v = grid2(4);
    for (const Vec2& p : circle_points(25)) {
      if (std::find(v.begin(), v.end(), p) == v.end()) v.push_back(p);
    }
    return v;
  }();
  std::uniform_int_distribution<std::size_t> pick(0, pool.size() - 1);
  int zeros_resolved = 0, collinear = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::array<Vec2, 4> p;
    std::set<std::size_t> used;
    for (Vec2& q : p) {
      std::size_t i;
      do i = pick(rng); while (!used.insert(i).second);
      q = pool[i];
    }
    if (all_collinear(p)) {
      ++collinear;
      EXPECT_EQ(perturbed(p), Sign::Zero);  // the documented exception
      continue;
    }
    ASSERT_NE(perturbed(p), Sign::Zero);
    if (incircle(p[0], p[1], p[2], p[3]) == Sign::Zero) ++zeros_resolved;
    check_alternating(p);
  }
  EXPECT_GT(zeros_resolved, 100);  // the pool is degenerate enough to exercise the scheme
  EXPECT_GT(collinear, 0);
}

TEST(Perturbation, InsphereNeverZeroAndAlternating) {
  std::mt19937_64 rng(12);
  const std::vector<Vec3> pool = [] {  // distinct points: the scheme's precondition
    std::vector<Vec3> v = grid3(3);
    for (const Vec3& p : sphere_points(9)) {
      if (std::find(v.begin(), v.end(), p) == v.end()) v.push_back(p);
    }
    return v;
  }();
  std::uniform_int_distribution<std::size_t> pick(0, pool.size() - 1);
  int zeros_resolved = 0, coplanar = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    std::array<Vec3, 5> p;
    std::set<std::size_t> used;
    for (Vec3& q : p) {
      std::size_t i;
      do i = pick(rng); while (!used.insert(i).second);
      q = pool[i];
    }
    if (all_coplanar(p)) {
      ++coplanar;
      EXPECT_EQ(perturbed(p), Sign::Zero);
      continue;
    }
    ASSERT_NE(perturbed(p), Sign::Zero);
    if (insphere(p[0], p[1], p[2], p[3], p[4]) == Sign::Zero) ++zeros_resolved;
    check_alternating(p);
  }
  EXPECT_GT(zeros_resolved, 50);
  EXPECT_GT(coplanar, 0);
}

TEST(Perturbation, CountsOnlyResolvedZeros) {
  const PredicateStats before = predicate_stats();
  incircle_perturbed({0, 0}, {1, 0}, {0, 1}, {5, 5});  // decided without perturbation
  incircle_perturbed({0, 0}, {1, 0}, {1, 1}, {0, 1});  // cocircular
  insphere_perturbed({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1});  // cospherical
  const PredicateStats d = predicate_stats() - before;
  EXPECT_EQ(d[Predicate::Incircle].perturbed, 1u);
  EXPECT_EQ(d[Predicate::Insphere].perturbed, 1u);
  EXPECT_EQ(d[Predicate::Incircle].calls(), 2u);
}

// Stage 2's integer evaluation hands the perturbation the cofactors it computed on the way: they
// must be the signs of the orientations that perturbation.hpp defines them as, on every zero.
TEST(Perturbation, CofactorsFromStage2AreTheOrientations) {
  std::mt19937_64 rng(77);
  std::uniform_int_distribution<int> coordinate(-2, 2);
  const double scales[3] = {1.0, 0x1p-60, 0x1p40};
  int zeros2 = 0, zeros3 = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double s = scales[trial % 3];
    std::array<Vec3, 5> p;
    for (Vec3& q : p) q = {s * coordinate(rng), s * coordinate(rng), s * coordinate(rng)};
    const Vec3 &a = p[0], &b = p[1], &c = p[2], &d = p[3], &e = p[4];
    detail::LiftCofactors known;
    if (detail::insphere_adaptive(a, b, c, d, e, &known) == Sign::Zero) {
      ASSERT_TRUE(known.known);
      const std::array<Sign, 5> want = {-reference::orient3d(b, c, d, e), reference::orient3d(a, c, d, e),
                                        -reference::orient3d(a, b, d, e), reference::orient3d(a, b, c, e),
                                        -reference::orient3d(a, b, c, d)};
      EXPECT_EQ(known.sign, want);
      ++zeros3;
    } else {
      EXPECT_FALSE(known.known);
    }
    const Vec2 a2{a.x, a.y}, b2{b.x, b.y}, c2{c.x, c.y}, d2{d.x, d.y};
    detail::LiftCofactors known2;
    if (detail::incircle_adaptive(a2, b2, c2, d2, &known2) == Sign::Zero) {
      ASSERT_TRUE(known2.known);
      EXPECT_EQ(known2.sign[0], reference::orient2d(b2, c2, d2));
      EXPECT_EQ(known2.sign[1], -reference::orient2d(a2, c2, d2));
      EXPECT_EQ(known2.sign[2], reference::orient2d(a2, b2, d2));
      EXPECT_EQ(known2.sign[3], -reference::orient2d(a2, b2, c2));
      ++zeros2;
    }
  }
  EXPECT_GT(zeros2, 100);
  EXPECT_GT(zeros3, 100);
}

// ---------------------------------------------------------------- (2) a real perturbation

// delta^rank, rank 1 for the lexicographically largest of the points.
template <class Point, std::size_t N>
std::array<Rational, N> perturbations(const std::array<Point, N>& p) {
  const Rational delta(0x1p-60);
  std::array<Rational, N> out;
  for (std::size_t i = 0; i < N; ++i) {
    int rank = 1;
    for (std::size_t j = 0; j < N; ++j) rank += p[i] < p[j];
    Rational power(1.0);
    for (int k = 0; k < rank; ++k) power = power * delta;
    out[i] = power;
  }
  return out;
}

// Rows (x, y, x^2 + y^2 + delta^rank, 1): positive iff d is inside circle(a, b, c) for a, b, c
// counter-clockwise, like incircle.
Sign real_perturbed(const std::array<Vec2, 4>& p) {
  const std::array<Rational, 4> eps = perturbations(p);
  std::vector<std::vector<Rational>> m;
  for (std::size_t i = 0; i < 4; ++i) {
    const Rational x(p[i].x), y(p[i].y);
    m.push_back({x, y, x * x + y * y + eps[i], Rational(1.0)});
  }
  return reference::determinant_sign(m);
}

// Rows (x, y, z, |p|^2 + delta^rank, 1), negated: insphere's convention.
Sign real_perturbed(const std::array<Vec3, 5>& p) {
  const std::array<Rational, 5> eps = perturbations(p);
  std::vector<std::vector<Rational>> m;
  for (std::size_t i = 0; i < 5; ++i) {
    const Rational x(p[i].x), y(p[i].y), z(p[i].z);
    m.push_back({x, y, z, x * x + y * y + z * z + eps[i], Rational(1.0)});
  }
  return -reference::determinant_sign(m);
}

TEST(Perturbation, IncircleIsTheSignOfARealPerturbation) {
  std::vector<Vec2> pool = circle_points(25);
  for (const Vec2& p : {Vec2{0, 0}, Vec2{1, 1}, Vec2{5, 5}, Vec2{-5, 5}, Vec2{3, 0}}) pool.push_back(p);
  int degenerate = 0;
  const std::size_t n = pool.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t k = 0; k < n; ++k) {
        for (std::size_t l = 0; l < n; ++l) {
          if (i == j || i == k || i == l || j == k || j == l || k == l) continue;
          const std::array<Vec2, 4> p{pool[i], pool[j], pool[k], pool[l]};
          degenerate += incircle(p[0], p[1], p[2], p[3]) == Sign::Zero;
          ASSERT_EQ(perturbed(p), real_perturbed(p))
              << i << " " << j << " " << k << " " << l;
        }
      }
    }
  }
  EXPECT_GT(degenerate, 1000);
}

TEST(Perturbation, InsphereIsTheSignOfARealPerturbation) {
  std::vector<std::vector<Vec3>> sets = {kOctahedron, cube(), sphere_points(9)};
  sets[1].push_back({0.5, 0.5, 0.5});
  std::mt19937_64 rng(3);
  int degenerate = 0;
  for (const std::vector<Vec3>& pool : sets) {
    const std::size_t n = pool.size();
    std::vector<int> idx(n);
    std::iota(idx.begin(), idx.end(), 0);
    const int trials = n <= 9 ? 4000 : 15000;
    for (int t = 0; t < trials; ++t) {
      std::shuffle(idx.begin(), idx.end(), rng);
      const std::array<Vec3, 5> p{pool[idx[0]], pool[idx[1]], pool[idx[2]], pool[idx[3]], pool[idx[4]]};
      degenerate += insphere(p[0], p[1], p[2], p[3], p[4]) == Sign::Zero;
      ASSERT_EQ(perturbed(p), real_perturbed(p)) << idx[0] << " " << idx[1] << " " << idx[2] << " "
                                                 << idx[3] << " " << idx[4];
    }
  }
  EXPECT_GT(degenerate, 1000);
}

// ---------------------------------------------------------------- (3) one triangulation

// Indices of the strict convex hull vertices of pts, counter-clockwise (Andrew's monotone chain
// with the exact orient2d).
std::vector<int> hull2(const std::vector<Vec2>& pts) {
  std::vector<int> order(pts.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return pts[a] < pts[b]; });
  std::vector<int> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = hull.size();
    for (const int i : order) {
      while (hull.size() >= start + 2 &&
             orient2d(pts[hull[hull.size() - 2]], pts[hull.back()], pts[i]) != Sign::Positive) {
        hull.pop_back();
      }
      hull.push_back(i);
    }
    hull.pop_back();
    std::reverse(order.begin(), order.end());
  }
  return hull;
}

double twice_area(const Vec2& a, const Vec2& b, const Vec2& c) { return cross(b - a, c - a); }

// Triangles (i, j, k), counter-clockwise, whose perturbed circle has no other point inside,
// decided with the arguments in the order given by `rotation` (0..5).
std::set<std::array<int, 3>> empty_triangles(const std::vector<Vec2>& pts, int rotation) {
  std::set<std::array<int, 3>> out;
  const int n = static_cast<int>(pts.size());
  static const int kPerm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int k = j + 1; k < n; ++k) {
        std::array<int, 3> t{i, j, k};
        const Sign o = orient2d(pts[i], pts[j], pts[k]);
        if (o == Sign::Zero) continue;
        if (o == Sign::Negative) std::swap(t[1], t[2]);
        const int* perm = kPerm[rotation];
        const Vec2 &a = pts[t[perm[0]]], &b = pts[t[perm[1]]], &c = pts[t[perm[2]]];
        const int side = rotation < 3 ? 1 : -1;  // odd rotations turn clockwise
        bool empty = true;
        for (int l = 0; l < n && empty; ++l) {
          if (l == i || l == j || l == k) continue;
          empty = to_int(incircle_perturbed(a, b, c, pts[l])) * side < 0;
        }
        if (empty) out.insert(t);
      }
    }
  }
  return out;
}

void expect_one_triangulation(const std::vector<Vec2>& pts, const std::set<std::array<int, 3>>& tris) {
  const std::vector<int> hull = hull2(pts);
  double hull_area = 0;
  for (std::size_t i = 1; i + 1 < hull.size(); ++i) {
    hull_area += twice_area(pts[hull[0]], pts[hull[i]], pts[hull[i + 1]]);
  }
  // Points on the hull boundary, collinear ones included.
  int h = 0;
  for (const Vec2& p : pts) {
    bool on = false;
    for (std::size_t e = 0; e < hull.size() && !on; ++e) {
      const Vec2 &u = pts[hull[e]], &v = pts[hull[(e + 1) % hull.size()]];
      on = orient2d(u, v, p) == Sign::Zero && std::min(u.x, v.x) <= p.x && p.x <= std::max(u.x, v.x) &&
           std::min(u.y, v.y) <= p.y && p.y <= std::max(u.y, v.y);
    }
    h += on;
  }
  const int n = static_cast<int>(pts.size());
  EXPECT_EQ(static_cast<int>(tris.size()), 2 * n - 2 - h);
  double area = 0;
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : tris) {
    area += twice_area(pts[t[0]], pts[t[1]], pts[t[2]]);
    for (int e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
  }
  EXPECT_EQ(area, hull_area);
  // Every edge is used once in each direction, or once if all points lie on one side of it.
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1);
    if (directed.count({edge.second, edge.first})) continue;
    for (const Vec2& p : pts) {
      EXPECT_NE(orient2d(pts[edge.first], pts[edge.second], p), Sign::Negative)
          << "edge " << edge.first << "-" << edge.second << " has one triangle but is not on the hull";
    }
  }
}

TEST(Perturbation, CocircularPointsGetExactlyOneTriangulation) {
  const std::vector<Vec2> twelve = circle_points(25);
  ASSERT_EQ(twelve.size(), 12u);
  std::vector<std::vector<Vec2>> sets = {
      {{5, 0}, {3, 4}, {0, 5}, {-4, 3}, {-3, -4}}, twelve, twelve, grid2(4), grid2(5)};
  sets[2].push_back({0, 0});  // the centre: interior, cocircular with nothing
  std::mt19937_64 rng(8);
  for (std::vector<Vec2> pts : sets) {
    const std::set<std::array<int, 3>> tris = empty_triangles(pts, 0);
    expect_one_triangulation(pts, tris);
    for (int rotation = 1; rotation < 6; ++rotation) EXPECT_EQ(empty_triangles(pts, rotation), tris);
    // The same triangles, by coordinates, for shuffled input.
    auto by_coordinates = [](const std::vector<Vec2>& p, const std::set<std::array<int, 3>>& ts) {
      std::set<std::array<std::pair<double, double>, 3>> out;
      for (const auto& t : ts) {
        std::array<std::pair<double, double>, 3> c;
        for (int e = 0; e < 3; ++e) c[e] = {p[t[e]].x, p[t[e]].y};
        std::sort(c.begin(), c.end());
        out.insert(c);
      }
      return out;
    };
    const auto reference = by_coordinates(pts, tris);
    for (int shuffle = 0; shuffle < 3; ++shuffle) {
      std::shuffle(pts.begin(), pts.end(), rng);
      EXPECT_EQ(by_coordinates(pts, empty_triangles(pts, 0)), reference);
    }
  }
}

// 6 * signed volume of (a, b, c, d) = det(b - a, c - a, d - a); exact for small integers.
double six_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return dot(b - a, cross(c - a, d - a));
}

// 6 * volume of the convex hull, independently of any tetrahedralization: for each facet (the
// points on a supporting plane), its polygon ordered by a 2D hull in a coordinate projection,
// fanned from its first vertex and coned to pts[0].
double six_hull_volume(const std::vector<Vec3>& pts) {
  const int n = static_cast<int>(pts.size());
  std::map<std::vector<int>, Vec3> facets;  // the points on a supporting plane, and its normal
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int k = j + 1; k < n; ++k) {
        bool pos = false, neg = false;
        std::vector<int> on;
        for (int l = 0; l < n; ++l) {
          const Sign s = orient3d(pts[i], pts[j], pts[k], pts[l]);
          pos |= s == Sign::Positive;
          neg |= s == Sign::Negative;
          if (s == Sign::Zero) on.push_back(l);
        }
        if (pos && neg) continue;
        if (!pos && !neg) continue;  // collinear i, j, k
        facets[on] = cross(pts[j] - pts[i], pts[k] - pts[i]);
      }
    }
  }
  double volume = 0;
  for (const auto& [f, normal] : facets) {
    int drop = 0;  // the axis the facet is projected along
    if (std::fabs(normal.y) > std::fabs(normal.x)) drop = 1;
    if (std::fabs(normal.z) > std::max(std::fabs(normal.x), std::fabs(normal.y))) drop = 2;
    std::vector<Vec2> flat;
    for (const int v : f) {
      const Vec3& p = pts[v];
      flat.push_back(drop == 0 ? Vec2{p.y, p.z} : (drop == 1 ? Vec2{p.x, p.z} : Vec2{p.x, p.y}));
    }
    const std::vector<int> polygon = hull2(flat);
    double cone = 0;
    for (std::size_t t = 1; t + 1 < polygon.size(); ++t) {
      cone += six_volume(pts[0], pts[f[polygon[0]]], pts[f[polygon[t]]], pts[f[polygon[t + 1]]]);
    }
    volume += std::fabs(cone);
  }
  return volume;
}

// Tetrahedra, positively oriented, with no point inside their perturbed sphere. The tetrahedron
// is handed to insphere in one of its 12 even orderings, chosen by `ordering`.
std::vector<std::array<int, 4>> empty_tetrahedra(const std::vector<Vec3>& pts, int ordering) {
  static const int kEven[12][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 0, 3, 2},
                                   {1, 2, 0, 3}, {1, 3, 2, 0}, {2, 0, 1, 3}, {2, 1, 3, 0},
                                   {2, 3, 0, 1}, {3, 0, 2, 1}, {3, 1, 0, 2}, {3, 2, 1, 0}};
  std::vector<std::array<int, 4>> out;
  const int n = static_cast<int>(pts.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int k = j + 1; k < n; ++k) {
        for (int m = k + 1; m < n; ++m) {
          std::array<int, 4> t{i, j, k, m};
          const Sign o = orient3d(pts[i], pts[j], pts[k], pts[m]);
          if (o == Sign::Zero) continue;
          if (o == Sign::Negative) std::swap(t[2], t[3]);
          const int* perm = kEven[ordering];
          const Vec3 &a = pts[t[perm[0]]], &b = pts[t[perm[1]]], &c = pts[t[perm[2]]], &d = pts[t[perm[3]]];
          bool empty = true;
          for (int l = 0; l < n && empty; ++l) {
            if (l == i || l == j || l == k || l == m) continue;
            empty = insphere_perturbed(a, b, c, d, pts[l]) == Sign::Negative;
          }
          if (empty) out.push_back(t);
        }
      }
    }
  }
  return out;
}

void expect_one_tetrahedralization(const std::vector<Vec3>& pts, const std::vector<std::array<int, 4>>& tets) {
  ASSERT_FALSE(tets.empty());
  double volume = 0;
  // Faces by sorted vertices, with the side (orient3d of the sorted face and the opposite vertex)
  // of every selected tetrahedron that has it.
  std::map<std::array<int, 3>, std::vector<Sign>> faces;
  for (const auto& t : tets) {
    const double v = six_volume(pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]]);
    EXPECT_GT(v, 0);
    volume += v;
    for (int opposite = 0; opposite < 4; ++opposite) {
      std::array<int, 3> f;
      int n = 0;
      for (int e = 0; e < 4; ++e) {
        if (e != opposite) f[n++] = t[e];
      }
      std::sort(f.begin(), f.end());
      faces[f].push_back(orient3d(pts[f[0]], pts[f[1]], pts[f[2]], pts[t[opposite]]));
    }
  }
  EXPECT_EQ(volume, six_hull_volume(pts));
  for (const auto& [f, sides] : faces) {
    if (sides.size() == 2) {
      EXPECT_EQ(sides[0], -sides[1]) << "face " << f[0] << " " << f[1] << " " << f[2] << " on one side";
      continue;
    }
    ASSERT_EQ(sides.size(), 1u) << "face " << f[0] << " " << f[1] << " " << f[2] << " in " << sides.size();
    for (const Vec3& p : pts) {  // a face with one tetrahedron must lie on the hull
      EXPECT_NE(orient3d(pts[f[0]], pts[f[1]], pts[f[2]], p), -sides[0])
          << "face " << f[0] << " " << f[1] << " " << f[2] << " is inside but has one tetrahedron";
    }
  }
}

TEST(Perturbation, CosphericalPointsGetExactlyOneTetrahedralization) {
  const std::vector<Vec3> nine = sphere_points(9);
  ASSERT_EQ(nine.size(), 30u);
  const std::vector<std::vector<Vec3>> sets = {kOctahedron, cube(), nine, grid3(3)};
  std::mt19937_64 rng(21);
  for (std::vector<Vec3> pts : sets) {
    const std::vector<std::array<int, 4>> tets = empty_tetrahedra(pts, 0);
    expect_one_tetrahedralization(pts, tets);
    // The same selection for other argument orders, and by coordinates for shuffled input.
    const int orderings = pts.size() <= 8 ? 12 : 2;
    for (int ordering = 1; ordering < orderings; ++ordering) EXPECT_EQ(empty_tetrahedra(pts, ordering), tets);
    auto by_coordinates = [](const std::vector<Vec3>& p, const std::vector<std::array<int, 4>>& ts) {
      std::set<std::array<std::array<double, 3>, 4>> out;
      for (const auto& t : ts) {
        std::array<std::array<double, 3>, 4> c;
        for (int e = 0; e < 4; ++e) c[e] = {p[t[e]].x, p[t[e]].y, p[t[e]].z};
        std::sort(c.begin(), c.end());
        out.insert(c);
      }
      return out;
    };
    const auto reference = by_coordinates(pts, tets);
    std::shuffle(pts.begin(), pts.end(), rng);
    EXPECT_EQ(by_coordinates(pts, empty_tetrahedra(pts, 0)), reference);
  }
}

}  // namespace
}  // namespace dtlab
