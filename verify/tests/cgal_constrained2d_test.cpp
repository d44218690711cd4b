// dtlab's "cdt" method against CGAL's Constrained_Delaunay_triangulation_2
// (verify/cgal_constrained2d). On input in general position (random double coordinates: no four
// cocircular points, no point on a segment, no crossings) the constrained Delaunay triangulation
// is unique, so dtlab's triangles and constrained edges must be exactly CGAL's: random points with
// random non-crossing segments, and random polygons with holes.
//
// The observation, measured here: with crossing segments that nearly meet in one point,
// CGAL (exact constructions, Exact_intersections_tag) builds a valid triangulation of the EXACT
// intersection points, but written in doubles (each coordinate correctly rounded) some of its
// triangles fold or flatten. dtlab treats the rounded point as the truth and must stay valid in
// doubles: asserted for dtlab, reported for CGAL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "algorithms/constrained2d/constrained2d.hpp"
#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/element_sets2.hpp"
#include "verify/cgal_constrained2d.hpp"
#include "verify/checks2d.hpp"
#include "verify/checks_constrained2d.hpp"

namespace dtlab {
namespace {

using Segment = std::array<std::uint32_t, 2>;

struct Input {
  std::vector<Vec2> points;
  std::vector<Segment> segments;
  std::vector<Vec2> holes;
};

std::vector<Segment> sorted_edges(const std::vector<ConstrainedEdge2>& edges) {
  std::vector<Segment> out;
  for (const ConstrainedEdge2& e : edges) out.push_back({e.a, e.b});
  std::sort(out.begin(), out.end());
  return out;
}

// dtlab's cdt and CGAL's (Epick) on the same input: same triangles of the hull, same
// constrained edges; dtlab's result passes the exact checks.
void expect_same_as_cgal(const Input& in, const std::string& what) {
  const ConstrainedInput2 ci{.points = in.points, .segments = in.segments, .segment_markers = {}, .holes = in.holes,
                             .regions = {}};
  const Constrained2dResult mine = constrained2d(ci, {.method = "cdt"});
  const ConstrainedCheckReport2 report = verify_constrained2d(ci, mine, {.method = "cdt"});
  ASSERT_TRUE(report.ok) << what << ": " << to_text(report);
  ASSERT_EQ(mine.crossing_steiner_points, 0u) << what;
  const CgalConstrained2d cgal = cgal_constrained2d(in.points, in.segments);
  ASSERT_EQ(cgal.created_points, 0u) << what;
  const std::vector<TriangleIds> ours = canonical_triangle_set(mine.triangulation.finite_triangles());
  EXPECT_EQ(ours.size(), cgal.triangles.size()) << what;
  EXPECT_TRUE(ours == canonical_triangle_set(cgal.triangles)) << what << ": triangles differ from CGAL's";
  EXPECT_TRUE(sorted_edges(mine.constrained_edges) == cgal.constrained_edges) << what << ": constrained edges differ";
  std::printf("[ figures  ] %s: %zu triangles, dtlab cdt %.4f s, CGAL CDT %.4f s\n", what.c_str(), ours.size(),
              mine.seconds, cgal.seconds);
}

TEST(CgalConstrained2d, RandomPointsWithNonCrossingSegmentsSameAsCgal) {
  // Segments: a random half of the Delaunay edges of a fifth of the points (they do not cross
  // each other, and cross many edges of the triangulation of all the points).
  for (const std::size_t n : {1'000, 30'000}) {
    std::mt19937_64 rng(n);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Input in;
    for (std::size_t i = 0; i < n; ++i) in.points.push_back({u(rng), u(rng)});
    const std::vector<Vec2> sub(in.points.begin(), in.points.begin() + static_cast<std::ptrdiff_t>(n / 5));
    for (const auto& e : edges(delaunay2d(sub).triangulation))
      if (rng() % 2 == 0) in.segments.push_back({e[0], e[1]});
    expect_same_as_cgal(in, "uniform n=" + std::to_string(n) + ", " + std::to_string(in.segments.size()) + " segments");
  }
}

TEST(CgalConstrained2d, PolygonsWithHolesSameAsCgal) {
  // A star-shaped polygon of k vertices at random radii around the origin, with smaller
  // star-shaped holes around points of a circle inside it, and random points inside.
  for (const std::uint32_t seed : {1u, 2u, 3u, 4u, 5u}) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Input in;
    const auto ring = [&](Vec2 centre, double r0, double r1, int k) {
      const auto base = static_cast<std::uint32_t>(in.points.size());
      for (int i = 0; i < k; ++i) {
        const double angle = (i + 0.2 + 0.6 * u(rng)) * 6.283185307179586 / k;
        const double r = r0 + (r1 - r0) * u(rng);
        in.points.push_back({centre.x + r * std::cos(angle), centre.y + r * std::sin(angle)});
        in.segments.push_back({base + static_cast<std::uint32_t>(i), base + static_cast<std::uint32_t>((i + 1) % k)});
      }
    };
    ring({0, 0}, 80, 100, 200 * static_cast<int>(seed));
    const int holes = 6;
    for (int h = 0; h < holes; ++h) {
      const Vec2 c = {45 * std::cos(h * 6.283185307179586 / holes), 45 * std::sin(h * 6.283185307179586 / holes)};
      ring(c, 8, 15, 12 + h);
      in.holes.push_back(c);
    }
    for (int i = 0; i < 500; ++i) in.points.push_back({-50 + 100 * u(rng), -50 + 100 * u(rng)});
    expect_same_as_cgal(in, "star polygon seed " + std::to_string(seed) + " with " + std::to_string(holes) + " holes");
  }
}

TEST(CgalConstrained2d, WrapperRefusesCrossingsInEpick) {
  const std::vector<Vec2> P = {{0, 0}, {1, 1}, {0, 1}, {1, 0.25}};
  const std::vector<Segment> S = {{0, 1}, {2, 3}};
  EXPECT_THROW(cgal_constrained2d(P, S, CgalCdtKernel::Epick), InputError);
  const CgalConstrained2d exact = cgal_constrained2d(P, S, CgalCdtKernel::EpeckExactIntersections);
  EXPECT_EQ(exact.created_points, 1u);
  EXPECT_EQ(exact.triangles.size(), 4u);
}

// Three or more segments through nearly one point: the lines pass through a random point p, but
// their endpoints are rounded, so their exact pairwise intersections are distinct points a few
// ulps apart, which rounding to double moves, merges or reorders.
Input nearly_concurrent(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Input in;
  in.points = {{-1, -1}, {2, -1}, {2, 2}, {-1, 2}};
  const Vec2 p = {u(rng), u(rng)};
  const int lines = 3 + static_cast<int>(rng() % 3);
  for (int k = 0; k < lines; ++k) {
    const double angle = 3.141592653589793 * (k + 0.8 * u(rng)) / lines;
    const double r = 0.3 + 0.6 * u(rng), s = 0.3 + 0.6 * u(rng);
    const auto base = static_cast<std::uint32_t>(in.points.size());
    in.points.push_back({p.x - r * std::cos(angle), p.y - r * std::sin(angle)});
    in.points.push_back({p.x + s * std::cos(angle), p.y + s * std::sin(angle)});
    in.segments.push_back({base, base + 1});
  }
  return in;
}

TEST(CgalConstrained2d, NearlyConcurrentCrossingsCgalFoldsInDoublesDtlabDoesNot) {
  std::mt19937_64 rng(2024);
  const int trials = 400;
  std::size_t cgal_folded = 0, cgal_flat = 0, cgal_inputs_bad = 0, cgal_merged = 0, cgal_triangles = 0;
  std::size_t ours_steiner = 0, ours_valid = 0, ours_refused = 0, ours_not_converged = 0, ours_chains_flagged = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const Input in = nearly_concurrent(rng);
    const ConstrainedInput2 ci{.points = in.points, .segments = in.segments, .segment_markers = {}, .holes = {},
                               .regions = {}};
    for (const char* method : {"cdt", "swap", "conforming"}) {
      // Whatever dtlab returns is valid in doubles. It may refuse (conforming: a piece with no
      // double point between its ends); InternalError (resolution not converging, which
      // clusters caused before crossings were snap rounded) is counted and must not happen.
      Constrained2dResult mine;
      try {
        mine = constrained2d(ci, {.method = method, .keep_exterior = true});
      } catch (const InputError&) {
        ++ours_refused;
        continue;
      } catch (const InternalError&) {
        ++ours_not_converged;
        continue;
      }
      // Valid in doubles, always, and every check passes ("conforming" refuses, with
      // InputError, to split a piece whose ends are adjacent doubles: counted as refused).
      const ConstrainedCheckOptions2 check{.method = method, .keep_exterior = true};
      const ConstrainedCheckReport2 report = check_constrained_validity2(ci, mine, check);
      ASSERT_TRUE(report.ok) << "trial " << trial << " " << method << ": " << to_text(report);
      const ConstrainedCheckReport2 full = verify_constrained2d(ci, mine, check);
      ours_chains_flagged += !full.ok;
      EXPECT_TRUE(full.ok) << "trial " << trial << " " << method << ": " << to_text(full);
      ++ours_valid;
      if (std::string(method) == "cdt") ours_steiner += mine.crossing_steiner_points;
    }

    const CgalConstrained2d cgal = cgal_constrained2d(in.points, in.segments, CgalCdtKernel::EpeckExactIntersections);
    cgal_triangles += cgal.triangles.size();
    std::size_t folded = 0, flat = 0;
    for (const TriangleIds& t : cgal.triangles) {
      const Sign s = orient2d(cgal.points[t[0]], cgal.points[t[1]], cgal.points[t[2]]);
      folded += s == Sign::Negative;
      flat += s == Sign::Zero;
    }
    std::vector<Vec2> sorted = cgal.points;
    std::sort(sorted.begin(), sorted.end(), [](const Vec2& a, const Vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    cgal_merged += static_cast<std::size_t>(sorted.end() - std::unique(sorted.begin(), sorted.end()));
    cgal_folded += folded;
    cgal_flat += flat;
    cgal_inputs_bad += (folded + flat) > 0;
  }
  std::printf("[ figures  ] %d inputs of 3-5 nearly concurrent segments: dtlab (cdt, swap, conforming) valid in "
              "doubles on all %zu results returned (%zu crossing Steiner points in cdt; %zu with chains bent past one "
              "rounding bound in a cluster), %zu refused (InputError), %zu not converged (InternalError); CGAL EPECK + Exact_intersections_tag, rounded to double: %zu inputs "
              "with folded or flat triangles, %zu folded and %zu flat of %zu triangles, %zu vertices merged by "
              "rounding\n",
              trials, ours_valid, ours_steiner, ours_chains_flagged, ours_refused, ours_not_converged, cgal_inputs_bad, cgal_folded,
              cgal_flat, cgal_triangles, cgal_merged);
  EXPECT_GT(ours_valid, std::size_t{trials});
  EXPECT_EQ(ours_not_converged, 0u);
  RecordProperty("cgal_inputs_with_folds", static_cast<int>(cgal_inputs_bad));
}

// A minimal case of the above that dtlab did not resolve before crossings were snap rounded
// (crossings.hpp): five segments through nearly one point; the crossings of segments 0, 1 and 2
// round to three points within an ulp of each other, in an order that contradicts the exact one,
// and the chains, each bent at its own crossings, kept re-crossing there ("segment resolution:
// more crossings than segments allow"). Routed through every hot point they meet, they do not.
TEST(CgalConstrained2d, NearlyConcurrentSegmentsResolve) {
  const std::vector<Vec2> P = {{-1, -1},
                               {2, -1},
                               {2, 2},
                               {-1, 2},
                               {0.0074210969066436649, -0.12127542196877807},
                               {0.82618098262579065, 0.18687106635075096},
                               {0.082478619515461982, -0.36600258228072774},
                               {0.55069532313867098, 0.31503904197952914},
                               {0.23536121073134797, -0.56705284532276012},
                               {0.47446030812751927, 0.79012520894497684},
                               {0.67626669119446792, -0.41632733387681309},
                               {-0.061503945320706466, 0.49034943685344989},
                               {1.1318272700229319, -0.0988691860180822},
                               {-0.37009215130567419, 0.091903349182931957}};
  const std::vector<Segment> S = {{4, 5}, {6, 7}, {8, 9}, {10, 11}, {12, 13}};
  const ConstrainedInput2 ci{.points = P, .segments = S, .segment_markers = {}, .holes = {}, .regions = {}};
  for (const char* method : {"cdt", "swap"}) {
    const Constrained2dResult mine = constrained2d(ci, {.method = method, .keep_exterior = true});
    EXPECT_TRUE(verify_constrained2d(ci, mine, {.method = method, .keep_exterior = true}).ok) << method;
  }
  // "conforming" would have to split a piece between crossings one ulp apart: it says so.
  try {
    const Constrained2dResult mine = constrained2d(ci, {.method = "conforming", .keep_exterior = true});
    EXPECT_TRUE(verify_constrained2d(ci, mine, {.method = "conforming", .keep_exterior = true}).ok);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be split further"), std::string::npos) << e.what();
    EXPECT_FALSE(e.items().empty());
  }
}

}  // namespace
}  // namespace dtlab
