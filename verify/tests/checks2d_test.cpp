// The exact 2D checkers: they accept valid Delaunay triangulations (hand-made ones, and brute
// force ones on degenerate random sets) and catch each kind of broken one.
#include <algorithm>
#include <set>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "kernel/predicates.hpp"
#include "verify/checks2d.hpp"
#include "verify/generators/points2d.hpp"

namespace dtlab {
namespace {

using Tris = std::vector<TriangleIds>;

bool mentions(const CheckReport2& r, const std::string& text) {
  return std::any_of(r.problems.begin(), r.problems.end(),
                     [&](const std::string& p) { return p.find(text) != std::string::npos; });
}

#define EXPECT_MENTIONS(report, text) \
  EXPECT_TRUE(mentions(report, text)) << "no problem mentions '" << (text) << "' in:\n" << to_text(report)
#define EXPECT_VALID(report) EXPECT_TRUE((report).ok) << to_text(report)

// Every counter-clockwise triple whose perturbed circumcircle holds no other point: by the
// perturbation's uniqueness, exactly the triangles of the Delaunay triangulation. O(n^4).
Tris brute_force_delaunay(const std::vector<Vec2>& p) {
  Tris out;
  const auto n = static_cast<std::uint32_t>(p.size());
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t b = 0; b < n; ++b) {
      for (std::uint32_t c = 0; c < n; ++c) {
        if (!(a < b && a < c) || orient2d(p[a], p[b], p[c]) != Sign::Positive) continue;
        bool empty = true;
        for (std::uint32_t d = 0; d < n && empty; ++d) {
          if (d != a && d != b && d != c) empty = incircle_perturbed(p[a], p[b], p[c], p[d]) == Sign::Negative;
        }
        if (empty) out.push_back({a, b, c});
      }
    }
  }
  return out;
}

const std::vector<Vec2> kSquare = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
const Tris kSquareDiagonal02 = {{0, 1, 2}, {0, 2, 3}};
const Tris kSquareDiagonal13 = {{0, 1, 3}, {1, 2, 3}};

// The quarter disc of radius 65: the centre and the ten lattice points of x^2 + y^2 = 65^2 with
// x, y >= 0, fanned from the centre. Each fan triangle's circumcircle cuts the big circle
// exactly at its two outer vertices and holds the short arc between them, so every other point
// is strictly outside: a Delaunay triangulation with no tie to break.
const std::vector<Vec2> kQuarterDisc = {{0, 0},   {65, 0},  {63, 16}, {60, 25}, {56, 33}, {52, 39},
                                        {39, 52}, {33, 56}, {25, 60}, {16, 63}, {0, 65}};
Tris quarter_disc_fan() {
  Tris t;
  for (std::uint32_t i = 1; i + 1 < kQuarterDisc.size(); ++i) t.push_back({0, i, i + 1});
  return t;
}

// 3 x 3 lattice, each cell split on its rising diagonal.
std::vector<Vec2> lattice3() {
  std::vector<Vec2> p;
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 3; ++x) p.push_back({static_cast<double>(x), static_cast<double>(y)});
  }
  return p;
}
Tris lattice3_triangles() {
  Tris t;
  for (std::uint32_t y = 0; y < 2; ++y) {
    for (std::uint32_t x = 0; x < 2; ++x) {
      const std::uint32_t a = 3 * y + x, b = a + 1, c = a + 4, d = a + 3;
      t.push_back({a, b, c});
      t.push_back({a, c, d});
    }
  }
  return t;
}

// --- valid triangulations ------------------------------------------------------------------------

TEST(Checks2d, SquareBothDiagonalsAreValidTriangulations) {
  for (const Tris& t : {kSquareDiagonal02, kSquareDiagonal13}) {
    EXPECT_VALID(check_topology2(kSquare, t));
    EXPECT_VALID(check_orientation2(kSquare, t));
    EXPECT_VALID(check_hull_coverage2(kSquare, t));
    EXPECT_VALID(check_unreferenced(kSquare, t, {}));
  }
}

TEST(Checks2d, SquareOnlyThePerturbedDiagonalIsDelaunay) {
  const bool d02 = check_empty_circle2(kSquare, kSquareDiagonal02).ok;
  const bool d13 = check_empty_circle2(kSquare, kSquareDiagonal13).ok;
  EXPECT_NE(d02, d13) << "exactly one diagonal must pass the perturbed empty-circle test";
  // The one that passes is the one the perturbed incircle picks for the first triangle.
  const bool picks_02 = incircle_perturbed(kSquare[0], kSquare[1], kSquare[2], kSquare[3]) == Sign::Negative;
  EXPECT_EQ(d02, picks_02);
  const Tris& chosen = d02 ? kSquareDiagonal02 : kSquareDiagonal13;
  EXPECT_EQ(canonical_triangle_set(chosen), canonical_triangle_set(brute_force_delaunay(kSquare)));
  const CheckReport2 r = verify_delaunay2d(kSquare, chosen);
  EXPECT_VALID(r);
  EXPECT_EQ(r.interior_edges, 1u);
  EXPECT_EQ(r.boundary_edges, 4u);
  EXPECT_EQ(r.hull_points, 4u);
  EXPECT_EQ(r.incircle_tests, 1u);
}

TEST(Checks2d, ConvexFanFromTheCentreIsDelaunay) {
  const CheckReport2 r = verify_delaunay2d(kQuarterDisc, quarter_disc_fan());
  EXPECT_VALID(r);
  EXPECT_EQ(r.triangles, 9u);
  EXPECT_EQ(r.hull_points, 11u);
  EXPECT_EQ(r.interior_edges, 8u);
}

TEST(Checks2d, ConvexFanFromAVertexIsATriangulationButNotDelaunay) {
  // Fan of the outer arc from (65,0): a valid triangulation of the hull, but its diagonals cut
  // across circles that hold other arc points.
  Tris t = {{0, 1, 10}};
  for (std::uint32_t i = 2; i < 10; ++i) t.push_back({1, i, i + 1});
  EXPECT_VALID(check_topology2(kQuarterDisc, t));
  EXPECT_VALID(check_orientation2(kQuarterDisc, t));
  EXPECT_VALID(check_hull_coverage2(kQuarterDisc, t));
  EXPECT_VALID(check_unreferenced(kQuarterDisc, t, {}));
  EXPECT_FALSE(check_empty_circle2(kQuarterDisc, t).ok);
}

TEST(Checks2d, CollinearHullPointsMustBeVertices) {
  // (1,0) lies on the hull edge (0,0)-(2,0): a triangle skipping it leaves it uncovered.
  const std::vector<Vec2> p = {{0, 0}, {2, 0}, {1, 2}, {1, 0}};
  EXPECT_VALID(verify_delaunay2d(p, Tris{{0, 3, 2}, {3, 1, 2}}));
  const CheckReport2 r = check_hull_coverage2(p, Tris{{0, 1, 2}});
  EXPECT_VALID(r);  // the hull of the referenced points has no (1,0) ...
  const CheckReport2 all = verify_delaunay2d(p, Tris{{0, 1, 2}});
  EXPECT_MENTIONS(all, "point 3 is a vertex of no triangle");  // ... but the point is lost
}

TEST(Checks2d, EmptyTriangulationOfCollinearPointsIsValid) {
  const std::vector<Vec2> p = {{0, 0}, {1, 1}, {3, 3}, {2, 2}, {1, 1}};
  const std::vector<std::uint32_t> dup = {4};
  EXPECT_VALID(verify_delaunay2d(p, {}, dup));
  const std::vector<Vec2> q = {{0, 0}, {1, 1}, {3, 3}, {2, 2.5}};
  EXPECT_MENTIONS(verify_delaunay2d(q, {}), "not collinear");
}

// --- broken triangulations ----------------------------------------------------------------------

TEST(Checks2d, CatchesFlippedAndFlatTriangles) {
  Tris t = quarter_disc_fan();
  std::swap(t[3][1], t[3][2]);
  const CheckReport2 r = check_orientation2(kQuarterDisc, t);
  EXPECT_MENTIONS(r, "triangle 3 (0,5,4) is clockwise");
  EXPECT_EQ(r.problem_count, 1u);
  EXPECT_MENTIONS(check_topology2(kQuarterDisc, t), "same direction");
  EXPECT_FALSE(verify_delaunay2d(kQuarterDisc, t).ok);

  const std::vector<Vec2> p = {{0, 0}, {1, 1}, {2, 2}, {0, 2}};
  EXPECT_MENTIONS(check_orientation2(p, Tris{{0, 1, 2}, {0, 2, 3}}), "triangle 0 (0,1,2) is flat");
}

TEST(Checks2d, CatchesANonDelaunayEdge) {
  // A kite whose long diagonal (0,2) is not locally Delaunay.
  const std::vector<Vec2> p = {{0, 0}, {2, -1}, {4, 0}, {2, 1}};
  const Tris long_diagonal = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_VALID(check_topology2(p, long_diagonal));
  EXPECT_VALID(check_orientation2(p, long_diagonal));
  EXPECT_VALID(check_hull_coverage2(p, long_diagonal));
  const CheckReport2 r = check_empty_circle2(p, long_diagonal);
  EXPECT_MENTIONS(r, "edge (0,2) is not locally Delaunay");
  EXPECT_EQ(r.problem_count, 1u);
  EXPECT_VALID(verify_delaunay2d(p, Tris{{0, 1, 3}, {1, 2, 3}}));
}

TEST(Checks2d, CatchesAHoleAndAMissingBoundaryTriangle) {
  const std::vector<Vec2> p = lattice3();
  EXPECT_VALID(check_topology2(p, lattice3_triangles()));
  EXPECT_VALID(check_orientation2(p, lattice3_triangles()));
  EXPECT_VALID(check_hull_coverage2(p, lattice3_triangles()));

  // Removing triangle (0,1,4) leaves the hull edge (0,1) uncovered.
  Tris missing = lattice3_triangles();
  missing.erase(missing.begin());
  const CheckReport2 r = check_hull_coverage2(p, missing);
  EXPECT_MENTIONS(r, "convex hull edge (0,1) is not a boundary edge");
  EXPECT_MENTIONS(r, "boundary edge (0,4)");
  EXPECT_MENTIONS(r, "boundary edge (4,1)");
  EXPECT_EQ(r.problem_count, 3u) << to_text(r);

  // A 4 x 4 lattice with the centre cell's two triangles removed: the outer boundary is the
  // hull, but the hole's edges are boundary edges that are no hull edges.
  std::vector<Vec2> q;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) q.push_back({static_cast<double>(x), static_cast<double>(y)});
  }
  Tris holed;
  for (std::uint32_t y = 0; y < 3; ++y) {
    for (std::uint32_t x = 0; x < 3; ++x) {
      if (x == 1 && y == 1) continue;
      const std::uint32_t a = 4 * y + x;
      holed.push_back({a, a + 1, a + 5});
      holed.push_back({a, a + 5, a + 4});
    }
  }
  const CheckReport2 h = check_hull_coverage2(q, holed);
  EXPECT_EQ(h.problem_count, 4u) << to_text(h);
  EXPECT_MENTIONS(h, "boundary edge (5,9)");
  EXPECT_MENTIONS(check_topology2(q, holed), "not a triangulated disk");
}

TEST(Checks2d, CatchesReferencedDuplicatesAndLostPoints) {
  std::vector<Vec2> p = kSquare;
  p.push_back(p[0]);  // point 4 duplicates point 0
  const Tris uses_duplicate = {{4, 1, 2}, {4, 2, 3}};
  const std::vector<std::uint32_t> dup = {4};
  EXPECT_VALID(check_unreferenced(p, kSquareDiagonal02, dup));
  EXPECT_MENTIONS(check_unreferenced(p, uses_duplicate, dup), "duplicate point 4 is a vertex of triangle 0");
  EXPECT_MENTIONS(check_unreferenced(p, kSquareDiagonal02, {}), "point 4 is a vertex of no triangle");
  EXPECT_MENTIONS(check_unreferenced(p, kSquareDiagonal02, {}), "points 0 and 4 coincide");
  const std::vector<std::uint32_t> wrong = {3};
  EXPECT_MENTIONS(check_unreferenced(kSquare, Tris{{0, 1, 2}}, wrong), "coincides with no kept point");
  const std::vector<std::uint32_t> out_of_range = {9};
  EXPECT_MENTIONS(check_unreferenced(kSquare, kSquareDiagonal02, out_of_range), "duplicate index 9 out of range");
}

TEST(Checks2d, CatchesBadIdsTwinsAndNonManifoldEdges) {
  const std::vector<Vec2> p = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 2}, {3, 0}};
  EXPECT_MENTIONS(check_topology2(p, Tris{{0, 1, 7}}), "triangle 0 (0,1,7) has a vertex id out of range");
  EXPECT_MENTIONS(check_topology2(p, Tris{{0, 1, 1}}), "repeats a vertex");
  // Edge (0,2) in three triangles.
  EXPECT_MENTIONS(check_topology2(p, Tris{{0, 1, 2}, {0, 2, 3}, {2, 0, 4}}), "shared by 3 triangles");
  // Two triangles meeting at vertex 2 only: a bow tie.
  const CheckReport2 bow = check_topology2(p, Tris{{0, 1, 2}, {2, 5, 4}});
  EXPECT_MENTIONS(bow, "vertex 2 is not manifold");
  EXPECT_MENTIONS(bow, "2 edge-connected components");
  // The geometric checks skip bad triangles and say so rather than crash.
  EXPECT_MENTIONS(check_orientation2(p, Tris{{0, 1, 7}}), "not checked");
  EXPECT_MENTIONS(check_empty_circle2(p, Tris{{0, 1, 7}}), "not checked");
  EXPECT_MENTIONS(check_hull_coverage2(p, Tris{{0, 1, 7}}), "not checked");
}

TEST(Checks2d, CatchesAnAnnulus) {
  // A square ring around an unused centre: manifold, connected, but not a disk.
  const std::vector<Vec2> p = {{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
  Tris ring;
  for (std::uint32_t i = 0; i < 4; ++i) {
    const std::uint32_t j = (i + 1) % 4;
    ring.push_back({i, j, 4 + j});
    ring.push_back({i, 4 + j, 4 + i});
  }
  EXPECT_MENTIONS(check_topology2(p, ring), "not a triangulated disk");
}

TEST(Checks2d, RefusesOutOfRangeCoordinates) {
  std::vector<Vec2> p = kSquare;
  p[2].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_MENTIONS(verify_delaunay2d(p, kSquareDiagonal02), "point 2: coordinate x is NaN");
  EXPECT_MENTIONS(check_empty_circle2(p, kSquareDiagonal02), "point 2: coordinate x is NaN");
}

TEST(Checks2d, CanonicalSetIgnoresRotationAndOrder) {
  const Tris a = {{2, 0, 1}, {3, 0, 2}};
  const Tris b = {{0, 2, 3}, {0, 1, 2}};
  EXPECT_EQ(canonical_triangle_set(a), canonical_triangle_set(b));
  EXPECT_NE(canonical_triangle_set(a), canonical_triangle_set(Tris{{0, 2, 1}, {0, 2, 3}}));  // orientation kept
  EXPECT_EQ(canonical_triangle_set(a), (Tris{{0, 1, 2}, {0, 2, 3}}));
}

TEST(Checks2d, ReportPrinters) {
  const CheckReport2 good = verify_delaunay2d(kQuarterDisc, quarter_disc_fan());
  EXPECT_EQ(to_json(good).rfind("{\"ok\":true,\"problem_count\":0,\"counts\":{\"points\":11,", 0), 0u) << to_json(good);
  const std::vector<Vec2> p = {{0, 0}, {2, -1}, {4, 0}, {2, 1}};
  const CheckReport2 bad = verify_delaunay2d(p, Tris{{0, 1, 2}, {0, 2, 3}});
  const std::string json = to_json(bad);
  EXPECT_NE(json.find("\"ok\":false"), std::string::npos);
  EXPECT_NE(json.find("edge (0,2) is not locally Delaunay"), std::string::npos);
  EXPECT_NE(to_text(bad).find("1 problems"), std::string::npos) << to_text(bad);
}

TEST(Checks2d, StoresAtMostTheCapButCountsAll) {
  CheckReport2 r;
  for (std::size_t i = 0; i < CheckReport2::kMaxStoredProblems + 5; ++i) r.add_problem("p");
  EXPECT_EQ(r.problems.size(), CheckReport2::kMaxStoredProblems);
  EXPECT_EQ(r.problem_count, CheckReport2::kMaxStoredProblems + 5);
  EXPECT_NE(to_text(r).find("and 5 more"), std::string::npos);
}

// --- brute force on degenerate random sets ----------------------------------------------------------

// Distinct points, small integer coordinates: collinear and cocircular sets are frequent.
std::vector<Vec2> small_lattice_set() {
  // Full size from the first case: inRange would otherwise start near its lower end.
  const auto n = *rc::gen::resize(100, rc::gen::inRange<std::size_t>(0, 11));
  std::set<std::pair<int, int>> seen;
  std::vector<Vec2> p;
  for (std::size_t i = 0; i < n; ++i) {
    const int x = *rc::gen::resize(100, rc::gen::inRange(-3, 4));
    const int y = *rc::gen::resize(100, rc::gen::inRange(-3, 4));
    if (seen.insert({x, y}).second) p.push_back({static_cast<double>(x), static_cast<double>(y)});
  }
  return p;
}

RC_GTEST_PROP(Checks2d, BruteForceDelaunayPassesEveryCheck, ()) {
  const std::vector<Vec2> p = small_lattice_set();
  const Tris t = brute_force_delaunay(p);
  const CheckReport2 r = verify_delaunay2d(p, t);
  RC_ASSERT(r.ok);
}

RC_GTEST_PROP(Checks2d, FlippingAnyEdgeOfTheDelaunayTriangulationIsCaught, ()) {
  const std::vector<Vec2> p = small_lattice_set();
  Tris t = brute_force_delaunay(p);
  // An interior edge whose quadrilateral is strictly convex flips into another triangulation;
  // the perturbed Delaunay triangulation being unique, that one must fail the empty circle.
  struct Flip {
    std::size_t i, j;
    int k, l;  // edge k of t[i] is edge l of t[j], reversed
  };
  std::vector<Flip> flippable;
  for (std::size_t i = 0; i < t.size(); ++i) {
    for (std::size_t j = i + 1; j < t.size(); ++j) {
      for (int k = 0; k < 3; ++k) {
        for (int l = 0; l < 3; ++l) {
          if (t[i][k] != t[j][(l + 1) % 3] || t[i][(k + 1) % 3] != t[j][l]) continue;
          const Vec2 a = p[t[i][k]], b = p[t[i][(k + 1) % 3]], c = p[t[i][(k + 2) % 3]], d = p[t[j][(l + 2) % 3]];
          // The quadrilateral a d b c is strictly convex iff both new triangles are ccw.
          if (orient2d(c, a, d) == Sign::Positive && orient2d(d, b, c) == Sign::Positive) {
            flippable.push_back({i, j, k, l});
          }
        }
      }
    }
  }
  RC_PRE(!flippable.empty());
  const Flip f = flippable[*rc::gen::inRange<std::size_t>(0, flippable.size())];
  // t[i] = (a, b, c) and t[j] = (b, a, d) become (c, a, d) and (d, b, c).
  const std::uint32_t a = t[f.i][f.k], b = t[f.i][(f.k + 1) % 3], c = t[f.i][(f.k + 2) % 3];
  const std::uint32_t d = t[f.j][(f.l + 2) % 3];
  t[f.i] = {c, a, d};
  t[f.j] = {d, b, c};
  RC_ASSERT(check_topology2(p, t).ok);
  RC_ASSERT(check_orientation2(p, t).ok);
  RC_ASSERT(check_hull_coverage2(p, t).ok);
  RC_ASSERT(!check_empty_circle2(p, t).ok);
}

TEST(Checks2d, BruteForceOnGeneratedDegenerateSets) {
  for (const char* name : {"grid", "exact_circle", "collinear", "uniform"}) {
    const std::vector<Vec2> p = generate_points2d(name, 25, 7);
    const CheckReport2 r = verify_delaunay2d(p, brute_force_delaunay(p));
    EXPECT_TRUE(r.ok) << name << ": " << to_text(r);
  }
}

}  // namespace
}  // namespace dtlab
