// mesh/mesh_quality.hpp on meshes with known answers: the equilateral and right isoceles
// triangles, the regular tetrahedron, one triangle per quality bin, unit edges in a metric,
// inverted and flat elements, refused input, the JSON key set and its values read back; and
// properties: Q_K and the angles do not change under translation, rotation and scaling, the bins
// count every element once and their shares sum to 1, the report is the same bytes on every run.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "kernel/error.hpp"
#include "kernel/quality.hpp"
#include "mesh/mesh_quality.hpp"

namespace dtlab {
namespace {

using Tri = std::array<std::uint32_t, 3>;
using Tet = std::array<std::uint32_t, 4>;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

::testing::AssertionResult close(double got, double want, double rel) {
  if (std::fabs(got - want) <= rel * std::fabs(want)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << got << " differs from " << want << " by more than " << rel << " relative";
}

// A flat JSON object of numbers, null, true and false, parsed into (key, text of the value)
// pairs in order; fails the test on anything else.
std::vector<std::pair<std::string, std::string>> parse_flat_json(const std::string& s) {
  std::vector<std::pair<std::string, std::string>> fields;
  std::size_t i = 0;
  auto fail = [&](const char* what) {
    ADD_FAILURE() << what << " at offset " << i << " of " << s;
    return std::vector<std::pair<std::string, std::string>>{};
  };
  if (s.empty() || s[i++] != '{') return fail("no '{'");
  while (i < s.size()) {
    if (s[i++] != '"') return fail("no key");
    const std::size_t end = s.find('"', i);
    if (end == std::string::npos || end + 1 >= s.size() || s[end + 1] != ':') return fail("bad key");
    std::string key = s.substr(i, end - i);
    i = end + 2;
    const std::size_t stop = s.find_first_of(",}", i);
    if (stop == std::string::npos) return fail("no end of value");
    std::string value = s.substr(i, stop - i);
    if (value != "null" && value != "true" && value != "false") {
      char* parsed_end = nullptr;
      std::strtod(value.c_str(), &parsed_end);
      if (value.empty() || *parsed_end != '\0') return fail("value is not a number");
    }
    fields.emplace_back(std::move(key), std::move(value));
    i = stop + 1;
    if (s[stop] == '}') return i == s.size() ? fields : fail("text after '}'");
  }
  return fail("no '}'");
}

std::vector<std::string> keys_of(const std::vector<std::pair<std::string, std::string>>& fields) {
  std::vector<std::string> keys;
  for (const auto& f : fields) keys.push_back(f.first);
  return keys;
}

std::string value_of(const std::vector<std::pair<std::string, std::string>>& fields, const std::string& key) {
  for (const auto& f : fields)
    if (f.first == key) return f.second;
  ADD_FAILURE() << "no key " << key;
  return "";
}

const std::vector<Vec2> kEquilateral = {{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}};
const std::vector<Tri> kOne = {{0, 1, 2}};
// The regular tetrahedron with edge 2 sqrt(2), positively oriented.
const std::vector<Vec3> kRegular = {{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}};
const std::vector<Tet> kOneTet = {{0, 1, 2, 3}};

TEST(MeshQuality2d, EquilateralTriangle) {
  const QualityReport r = measure_quality(kEquilateral, kOne);
  EXPECT_EQ(r.dimension, 2);
  EXPECT_FALSE(r.has_metric);
  EXPECT_EQ(r.points, 3u);
  EXPECT_EQ(r.vertices, 3u);
  EXPECT_EQ(r.elements, 1u);
  EXPECT_TRUE(close(r.quality_worst, 1.0, 1e-14));
  EXPECT_EQ(r.quality_mean, r.quality_worst);
  EXPECT_EQ(r.quality_bins, (std::array<std::uint64_t, 4>{1, 0, 0, 0}));
  EXPECT_EQ(r.quality_shares, (std::array<double, 4>{1, 0, 0, 0}));
  EXPECT_TRUE(close(r.angle_min, 60.0, 1e-13));
  EXPECT_TRUE(close(r.angle_max, 60.0, 1e-13));
  EXPECT_EQ(r.edges, 3u);
  EXPECT_TRUE(close(r.edge_length_min, 1.0, 1e-15));
  EXPECT_TRUE(close(r.edge_length_max, 1.0, 1e-15));
  EXPECT_TRUE(close(r.mean_ratio_worst, 1.0, 1e-14));
  EXPECT_TRUE(close(r.measure, std::sqrt(3.0) / 4, 1e-15));
  EXPECT_EQ(r.inverted, 0u);
  EXPECT_EQ(r.flat, 0u);
  // Metric figures are undefined without a metric.
  EXPECT_TRUE(std::isnan(r.metric_length_min));
  EXPECT_TRUE(std::isnan(r.unit_edge_share));
}

TEST(MeshQuality2d, RightIsocelesTriangle) {
  const std::vector<Vec2> p = {{0, 0}, {1, 0}, {0, 1}};
  const QualityReport r = measure_quality(p, kOne);
  // alpha h_max (perimeter) / (2 area) = sqrt(3)/6 sqrt(2) (2 + sqrt(2)) = (sqrt 6 + sqrt 3) / 3.
  const double q = (std::sqrt(6.0) + std::sqrt(3.0)) / 3;
  EXPECT_TRUE(close(r.quality_worst, q, 1e-14));
  EXPECT_TRUE(close(r.angle_min, 45.0, 1e-14));
  EXPECT_TRUE(close(r.angle_max, 90.0, 1e-14));
  EXPECT_EQ(r.edge_length_min, 1.0);
  EXPECT_TRUE(close(r.edge_length_max, std::sqrt(2.0), 1e-15));
  EXPECT_TRUE(close(r.edge_length_mean, (2 + std::sqrt(2.0)) / 3, 1e-15));
  // Mean ratio 4 sqrt(3) area / (1 + 1 + 2).
  EXPECT_TRUE(close(r.mean_ratio_mean, std::sqrt(3.0) / 2, 1e-14));
  EXPECT_EQ(r.measure, 0.5);
}

TEST(MeshQuality3d, RegularTetrahedron) {
  const QualityReport r = measure_quality(kRegular, kOneTet);
  EXPECT_EQ(r.dimension, 3);
  EXPECT_EQ(r.vertices, 4u);
  EXPECT_EQ(r.elements, 1u);
  EXPECT_TRUE(close(r.quality_worst, 1.0, 1e-14));
  EXPECT_EQ(r.quality_bins, (std::array<std::uint64_t, 4>{1, 0, 0, 0}));
  const double dihedral = std::acos(1.0 / 3.0) * 180.0 / std::acos(-1.0);  // 70.528779...
  EXPECT_TRUE(close(r.angle_min, dihedral, 1e-13));
  EXPECT_TRUE(close(r.angle_max, dihedral, 1e-13));
  EXPECT_NEAR(r.angle_min, 70.53, 0.005);
  EXPECT_EQ(r.edges, 6u);
  EXPECT_TRUE(close(r.edge_length_mean, 2 * std::sqrt(2.0), 1e-15));
  EXPECT_TRUE(close(r.measure, 8.0 / 3.0, 1e-15));
  EXPECT_TRUE(close(r.mean_ratio_mean, 1.0, 1e-14));
  EXPECT_EQ(r.inverted, 0u);
}

TEST(MeshQuality3d, CornerTetrahedronDihedralsAndUnitMetric) {
  // The corner tetrahedron: dihedral angles 90 (three edges at the corner) and acos(1/sqrt 3).
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const QualityReport r = measure_quality(p, kOneTet);
  EXPECT_TRUE(close(r.angle_max, 90.0, 1e-14));
  EXPECT_TRUE(close(r.angle_min, std::acos(1.0 / std::sqrt(3.0)) * 180.0 / std::acos(-1.0), 1e-13));
  EXPECT_TRUE(close(r.measure, 1.0 / 6.0, 1e-15));
  // In the metric I/8, the regular tetrahedron of edge 2 sqrt(2) has unit edges.
  const std::vector<Metric3> m(4, Metric3{{0.125, 0, 0.125, 0, 0, 0.125}});
  const QualityReport u = measure_quality(kRegular, kOneTet, m);
  EXPECT_TRUE(u.has_metric);
  EXPECT_EQ(u.unit_edges, 6u);
  EXPECT_EQ(u.unit_edge_share, 1.0);
  EXPECT_TRUE(close(u.metric_length_mean, 1.0, 1e-15));
  EXPECT_TRUE(close(u.quality_worst, 1.0, 1e-13));
  EXPECT_TRUE(close(u.mean_ratio_worst, 1.0, 1e-13));
}

// Isoceles triangles of base 1 and apex height h: Q = alpha (1 + 2 s) / h for s = sqrt(1/4 + h^2)
// below 1, so h = 0.2, 0.1, 0.01 give Q = 2.37, 4.44, 43.3: one per bin after the equilateral.
TEST(MeshQuality2d, BinsAndSharedEdges) {
  std::vector<Vec2> p;
  std::vector<Tri> t;
  for (const double h : {std::sqrt(3.0) / 2, 0.2, 0.1, 0.01, 0.0}) {
    const auto base = static_cast<std::uint32_t>(p.size());
    const double x = 2.0 * base;
    p.insert(p.end(), {{x, 0}, {x + 1, 0}, {x + 0.5, h}});
    t.push_back({base, base + 1, base + 2});
  }
  p.push_back({100, 100});  // used by no element
  const QualityReport r = measure_quality(p, t);
  EXPECT_EQ(r.points, 16u);
  EXPECT_EQ(r.vertices, 15u);
  EXPECT_EQ(r.elements, 5u);
  // The flat one (h = 0) has Q = infinity: in the last bin, in Q_M, not in the mean.
  EXPECT_EQ(r.quality_bins, (std::array<std::uint64_t, 4>{1, 1, 1, 2}));
  EXPECT_EQ(r.quality_shares, (std::array<double, 4>{0.2, 0.2, 0.2, 0.4}));
  EXPECT_EQ(r.quality_worst, kInf);
  EXPECT_EQ(r.flat, 1u);
  EXPECT_EQ(r.inverted, 0u);
  double sum = 0;
  for (std::uint32_t i = 0; i < 4; ++i) sum += shape_quality(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
  EXPECT_TRUE(close(r.quality_mean, sum / 4, 1e-15));
  EXPECT_EQ(r.angle_min, 0.0);
  EXPECT_EQ(r.angle_max, 180.0);
  EXPECT_EQ(r.mean_ratio_worst, 0.0);

  // A unit square in two triangles: 4 vertices, 5 unique edges.
  const std::vector<Vec2> sq = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Tri> two = {{0, 1, 2}, {0, 2, 3}};
  const QualityReport s = measure_quality(sq, two);
  EXPECT_EQ(s.edges, 5u);
  EXPECT_EQ(s.vertices, 4u);
  EXPECT_TRUE(close(s.edge_length_mean, (4 + std::sqrt(2.0)) / 5, 1e-15));
  EXPECT_EQ(s.measure, 1.0);
}

TEST(MeshQuality2d, UnitEdgesInAMetric) {
  // The unit square in two triangles, in the metric diag(1, 4) (size 1 along x, 1/2 along y):
  // the x edges have length 1, the y edges 2, the diagonal sqrt(5): 2 unit edges of 5.
  const std::vector<Vec2> sq = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Tri> two = {{0, 1, 2}, {0, 2, 3}};
  const std::vector<Metric2> m(4, Metric2{{1.0, 0.0, 4.0}});
  const QualityReport r = measure_quality(sq, two, m);
  EXPECT_TRUE(r.has_metric);
  EXPECT_EQ(r.edges, 5u);
  EXPECT_EQ(r.unit_edges, 2u);
  EXPECT_EQ(r.unit_edge_share, 0.4);
  EXPECT_TRUE(close(r.metric_length_min, 1.0, 1e-15));
  EXPECT_TRUE(close(r.metric_length_max, std::sqrt(5.0), 1e-15));
  EXPECT_TRUE(close(r.metric_length_mean, (6 + std::sqrt(5.0)) / 5, 1e-15));
  // In the unit space both triangles are right triangles with legs 1 and 2.
  const double alpha = kQualityAlpha2d;
  EXPECT_TRUE(close(r.quality_worst, alpha * std::sqrt(5.0) * (3 + std::sqrt(5.0)) / 2, 1e-14));
  EXPECT_TRUE(close(r.mean_ratio_worst, 4 * std::sqrt(3.0) * 1.0 / 10.0, 1e-14));
  // The Euclidean figures are kept beside the metric ones.
  EXPECT_TRUE(close(r.edge_length_max, std::sqrt(2.0), 1e-15));
  EXPECT_EQ(r.angle_max, 90.0);

  // Mean ratio in the vertex metric of largest determinant: with 16 I at vertex 1 (det 256
  // against 4) it is the Euclidean mean ratio of the right isoceles triangle, sqrt(3)/2.
  std::vector<Metric2> strict = m;
  strict[1] = Metric2{{16.0, 0.0, 16.0}};
  const QualityReport s = measure_quality(sq, std::vector<Tri>{{0, 1, 2}}, strict);
  EXPECT_TRUE(close(s.mean_ratio_worst, std::sqrt(3.0) / 2, 1e-14));
}

TEST(MeshQuality, InvertedElementsAreMeasuredAndCounted) {
  const std::vector<Tri> cw = {{0, 2, 1}};
  const QualityReport r = measure_quality(kEquilateral, cw);
  EXPECT_EQ(r.inverted, 1u);
  EXPECT_EQ(r.flat, 0u);
  EXPECT_TRUE(close(r.quality_worst, 1.0, 1e-14));
  EXPECT_TRUE(close(r.measure, -std::sqrt(3.0) / 4, 1e-15));
  EXPECT_LT(r.mean_ratio_worst, 0.0);

  const std::vector<Tet> negative = {{1, 0, 2, 3}, {0, 1, 2, 3}};
  const QualityReport t = measure_quality(kRegular, negative);
  EXPECT_EQ(t.inverted, 1u);
  EXPECT_EQ(t.elements, 2u);
  EXPECT_LT(std::fabs(t.measure), 1e-14);  // -8/3 + 8/3
  EXPECT_EQ(t.quality_bins[0], 2u);

  const std::vector<Vec3> flat = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const QualityReport f = measure_quality(flat, kOneTet);
  EXPECT_EQ(f.flat, 1u);
  EXPECT_EQ(f.quality_worst, kInf);
  EXPECT_TRUE(std::isnan(f.quality_mean));
  EXPECT_EQ(f.quality_bins[3], 1u);
}

TEST(MeshQuality, RefusesBadInput) {
  const std::vector<Tri> out_of_range = {{0, 1, 3}};
  EXPECT_THROW(measure_quality(kEquilateral, out_of_range), InputError);
  try {
    measure_quality(kEquilateral, out_of_range);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("triangle 0: vertex 3 out of range"), std::string::npos) << e.what();
    EXPECT_EQ(e.items(), std::vector<std::uint64_t>{0});
  }
  EXPECT_THROW(measure_quality(kEquilateral, kOne, std::vector<Metric2>(2)), InputError);
  std::vector<Metric2> bad(3);
  bad[2] = Metric2{{1.0, 2.0, 1.0}};  // det < 0
  try {
    measure_quality(kEquilateral, kOne, bad);
    ADD_FAILURE() << "a metric that is not positive definite was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 2"), std::string::npos) << e.what();
  }
  // A NaN coordinate is refused at a used vertex, ignored at an unused one.
  std::vector<Vec2> p = kEquilateral;
  p.push_back({kNaN, 0});
  EXPECT_NO_THROW(measure_quality(p, kOne));
  EXPECT_THROW(measure_quality(p, std::vector<Tri>{{0, 1, 3}}), InputError);
  const std::vector<Tet> tet_out = {{0, 1, 2, 4}};
  EXPECT_THROW(measure_quality(kRegular, tet_out), InputError);
}

TEST(MeshQuality, EmptyMesh) {
  const QualityReport r = measure_quality(kEquilateral, std::vector<Tri>{});
  EXPECT_EQ(r.elements, 0u);
  EXPECT_EQ(r.vertices, 0u);
  EXPECT_EQ(r.edges, 0u);
  EXPECT_TRUE(std::isnan(r.quality_worst));
  EXPECT_EQ(r.quality_shares, (std::array<double, 4>{0, 0, 0, 0}));
  const auto fields = parse_flat_json(quality_json(r));
  EXPECT_EQ(value_of(fields, "quality_worst"), "null");
  EXPECT_EQ(value_of(fields, "share_1_2"), "0");
}

TEST(MeshQualityJson, KeySetAndValues) {
  const std::vector<std::string> keys2 = {
      "dimension",        "metric",           "points",          "vertices",         "elements",
      "quality_worst",    "quality_mean",     "quality_1_2",     "quality_2_3",      "quality_3_10",
      "quality_over_10",  "share_1_2",        "share_2_3",       "share_3_10",       "share_over_10",
      "min_angle_deg",    "max_angle_deg",    "edges",           "edge_length_min",  "edge_length_max",
      "edge_length_mean", "metric_length_min", "metric_length_max", "metric_length_mean", "unit_edges",
      "unit_edge_share",  "mean_ratio_worst", "mean_ratio_mean", "area",             "inverted",
      "flat"};
  const std::vector<Vec2> sq = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Tri> two = {{0, 1, 2}, {0, 2, 3}};
  const QualityReport plain = measure_quality(sq, two);
  const auto fields = parse_flat_json(quality_json(plain));
  EXPECT_EQ(keys_of(fields), keys2);
  EXPECT_EQ(value_of(fields, "metric"), "false");
  EXPECT_EQ(value_of(fields, "unit_edges"), "null");
  EXPECT_EQ(value_of(fields, "metric_length_mean"), "null");
  EXPECT_EQ(value_of(fields, "elements"), "2");
  EXPECT_EQ(value_of(fields, "area"), "1");
  // Doubles read back to the same value.
  EXPECT_EQ(std::strtod(value_of(fields, "quality_worst").c_str(), nullptr), plain.quality_worst);
  EXPECT_EQ(std::strtod(value_of(fields, "edge_length_mean").c_str(), nullptr), plain.edge_length_mean);

  const std::vector<Metric2> m(4, Metric2{{1.0, 0.0, 4.0}});
  const auto with_metric = parse_flat_json(quality_json(measure_quality(sq, two, m)));
  EXPECT_EQ(keys_of(with_metric), keys2);
  EXPECT_EQ(value_of(with_metric, "metric"), "true");
  EXPECT_EQ(value_of(with_metric, "unit_edges"), "2");
  EXPECT_EQ(value_of(with_metric, "unit_edge_share"), "0.4");

  // 3D: the dihedral angle and volume keys in the same places; Q_M of a flat element is null.
  std::vector<std::string> keys3 = keys2;
  keys3[15] = "min_dihedral_deg";
  keys3[16] = "max_dihedral_deg";
  keys3[28] = "volume";
  const std::vector<Vec3> flat = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const auto fields3 = parse_flat_json(quality_json(measure_quality(flat, kOneTet)));
  EXPECT_EQ(keys_of(fields3), keys3);
  EXPECT_EQ(value_of(fields3, "quality_worst"), "null");
  EXPECT_EQ(value_of(fields3, "flat"), "1");
}

TEST(MeshQualityTable, ListsTheBookFigures) {
  const std::vector<Metric2> m(3, Metric2{{1.0, 0.0, 1.0}});
  const std::string table = quality_table(measure_quality(kEquilateral, kOne, m));
  for (const char* label : {"vertices (np)", "elements (ne)", "Q_M (worst Q_K)", "Q in [1,2]", "Q in ]2,3]",
                            "Q in ]3,10]", "Q > 10", "angles (deg)", "unit edges", "mean ratio", "area",
                            "inverted / flat"})
    EXPECT_NE(table.find(label), std::string::npos) << label << " missing from\n" << table;
  EXPECT_NE(table.find("3 (100.00%) with length"), std::string::npos) << table;
  EXPECT_EQ(table.back(), '\n');
  const std::string table3 = quality_table(measure_quality(kRegular, kOneTet));
  EXPECT_NE(table3.find("dihedral angles (deg)"), std::string::npos) << table3;
  EXPECT_EQ(table3.find("unit edges"), std::string::npos) << table3;
}

rc::Gen<double> gen_coordinate() {
  return rc::gen::map(rc::gen::inRange(-1000000, 1000001), [](int i) { return i * 1e-6; });
}

Vec2 rotate(const Vec2& p, double c, double s) { return {c * p.x - s * p.y, s * p.x + c * p.y}; }

RC_GTEST_PROP(MeshQuality2d, InvariantUnderTranslationRotationScaling, ()) {
  const std::vector<Vec2> p = {{*gen_coordinate(), *gen_coordinate()},
                               {*gen_coordinate(), *gen_coordinate()},
                               {*gen_coordinate(), *gen_coordinate()}};
  const QualityReport r = measure_quality(p, kOne);
  // Away from flat, and not tiny beside its coordinates, where rounding the moved points dominates.
  RC_PRE(r.quality_worst < 100.0 && r.edge_length_max > 1e-2);
  const double turn = *rc::gen::inRange(0, 6283) * 1e-3;
  const double scale = std::ldexp(1.0 + *rc::gen::inRange(0, 1000) * 1e-3, *rc::gen::inRange(-20, 21));
  const Vec2 shift{*gen_coordinate() * 100 * scale, *gen_coordinate() * 100 * scale};
  std::vector<Vec2> q;
  for (const Vec2& v : p) q.push_back(shift + scale * rotate(v, std::cos(turn), std::sin(turn)));
  const QualityReport s = measure_quality(q, kOne);
  RC_ASSERT(close(s.quality_worst, r.quality_worst, 1e-7));
  RC_ASSERT(std::fabs(s.angle_min - r.angle_min) < 1e-6);
  RC_ASSERT(std::fabs(s.angle_max - r.angle_max) < 1e-6);
  RC_ASSERT(close(std::fabs(s.measure), std::fabs(r.measure) * scale * scale, 1e-7));
  // Scaling by a power of two alone is exact: the same Q to the last bit.
  std::vector<Vec2> exact;
  for (const Vec2& v : p) exact.push_back(std::ldexp(1.0, 7) * v);
  RC_ASSERT(measure_quality(exact, kOne).quality_worst == r.quality_worst);
}

RC_GTEST_PROP(MeshQuality, BinsCountEveryElementOnceAndSharesSumToOne, ()) {
  const int n = *rc::gen::inRange(3, 40);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) p.push_back({*gen_coordinate(), *gen_coordinate(), *gen_coordinate()});
  const auto index = rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(n));
  std::vector<Tet> tets(*rc::gen::inRange(1, 60));
  for (Tet& t : tets) t = {*index, *index, *index, *index};
  const QualityReport r = measure_quality(p, tets);
  std::uint64_t count = 0;
  double share = 0;
  for (std::size_t b = 0; b < 4; ++b) {
    count += r.quality_bins[b];
    share += r.quality_shares[b];
  }
  RC_ASSERT(count == tets.size());
  RC_ASSERT(std::fabs(share - 1.0) < 1e-14);
  RC_ASSERT(r.inverted + r.flat <= tets.size());
  RC_ASSERT(r.vertices <= static_cast<std::uint64_t>(n));
  RC_ASSERT(r.edges <= 6 * tets.size());
  // The same input gives the same bytes.
  RC_ASSERT(quality_json(measure_quality(p, tets)) == quality_json(r));
  RC_ASSERT(quality_table(measure_quality(p, tets)) == quality_table(r));
}

// The angle range measures by atan2 only the angles whose cosine can make them extreme, and the
// edges are counted by buckets instead of a global sort: the same figures as measuring every
// dihedral angle and sorting every edge key, to the last bit.
RC_GTEST_PROP(MeshQuality3d, AnglesAndEdgesAsTheDirectScan, ()) {
  std::vector<Vec3> p;
  std::vector<Tet> tets;
  if (*rc::gen::arbitrary<bool>()) {
    // Random tetrahedra over a few points, repeated vertices (flat) included.
    const int n = *rc::gen::inRange(4, 30);
    for (int i = 0; i < n; ++i) p.push_back({*gen_coordinate(), *gen_coordinate(), *gen_coordinate()});
    const auto index = rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(n));
    tets.resize(*rc::gen::inRange(1, 80));
    for (Tet& t : tets) t = {*index, *index, *index, *index};
  } else {
    // Near copies of one tetrahedron: extreme angles a hair apart, in any order.
    std::array<Vec3, 4> base;
    for (Vec3& b : base) b = {*gen_coordinate(), *gen_coordinate(), *gen_coordinate()};
    const int copies = *rc::gen::inRange(1, 40);
    for (int k = 0; k < copies; ++k) {
      const auto first = static_cast<std::uint32_t>(p.size());
      for (const Vec3& b : base)
        p.push_back(b + 1e-4 * Vec3{*gen_coordinate(), *gen_coordinate(), *gen_coordinate()});
      tets.push_back({first, first + 1, first + 2, first + 3});
    }
  }
  double lo = kInf, hi = -kInf;
  std::vector<std::uint64_t> keys;
  static constexpr int kEdge[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  for (const Tet& t : tets) {
    for (const auto& q : kEdge) {
      const Vec3 e = p[t[q[1]]] - p[t[q[0]]];
      const Vec3 u = cross(e, p[t[q[2]]] - p[t[q[0]]]), v = cross(e, p[t[q[3]]] - p[t[q[0]]]);
      const double angle = std::atan2(norm(cross(u, v)), dot(u, v));
      lo = std::min(lo, angle);
      hi = std::max(hi, angle);
      const std::uint64_t a = std::min(t[q[0]], t[q[1]]), b = std::max(t[q[0]], t[q[1]]);
      keys.push_back(a << 32 | b);  // a loop (a == b) too, as the report counts it
    }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  const QualityReport r = measure_quality(p, tets);
  constexpr double kDegrees = 57.295779513082320876798;
  RC_ASSERT(r.angle_min == lo * kDegrees);
  RC_ASSERT(r.angle_max == hi * kDegrees);
  RC_ASSERT(r.edges == keys.size());
  double longest = 0.0;
  for (const std::uint64_t k : keys) longest = std::max(longest, norm(p[k & 0xffffffffu] - p[k >> 32]));
  RC_ASSERT(r.edge_length_max == longest);
}

}  // namespace
}  // namespace dtlab
