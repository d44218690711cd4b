// Triangle's .poly reader and writer: round trips keep every bit, the vertices may sit in a
// separate .node file, and every kind of malformed input is a ParseError at the right line.
#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "mesh/io/poly_format.hpp"
#include "mesh/io/triangle_format.hpp"

namespace dtlab {
namespace {

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
bool same_bits(const Vec2& a, const Vec2& b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y); }

// operator== would take -0.0 for 0.0; this does not.
void expect_same_poly(const PolyData2& a, const PolyData2& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) EXPECT_TRUE(same_bits(a.points[i], b.points[i])) << i;
  ASSERT_EQ(a.attributes.size(), b.attributes.size());
  for (std::size_t i = 0; i < a.attributes.size(); ++i) EXPECT_TRUE(same_bits(a.attributes[i], b.attributes[i])) << i;
  ASSERT_EQ(a.holes.size(), b.holes.size());
  for (std::size_t i = 0; i < a.holes.size(); ++i) EXPECT_TRUE(same_bits(a.holes[i], b.holes[i])) << i;
  ASSERT_EQ(a.regions.size(), b.regions.size());
  for (std::size_t i = 0; i < a.regions.size(); ++i) {
    EXPECT_TRUE(same_bits(a.regions[i].point, b.regions[i].point) &&
                same_bits(a.regions[i].attribute, b.regions[i].attribute) &&
                same_bits(a.regions[i].max_area, b.regions[i].max_area))
        << i;
  }
  EXPECT_EQ(a, b);
}

// A square with a square hole, markers, attributes and two regions.
PolyData2 sample_poly(int first_index) {
  PolyData2 p;
  p.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75},
              {-0.0, 1.0 / 3.0}, {kMinCoordinateMagnitude, -kMaxCoordinateMagnitude}};
  p.attribute_count = 2;
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    p.attributes.push_back(0.1 * static_cast<double>(i));
    p.attributes.push_back(-1e300 / (1.0 + static_cast<double>(i)));
  }
  p.has_point_markers = true;
  for (std::size_t i = 0; i < p.points.size(); ++i) p.point_markers.push_back(static_cast<int>(i % 3) - 1);
  p.first_index = first_index;
  p.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  p.has_segment_markers = true;
  p.segment_markers = {1, 1, 1, 1, 2, 2, 2, std::numeric_limits<int>::min()};
  p.holes = {{0.5, 0.5}};
  p.regions = {{{0.1, 0.1}, 7.0, 0.01}, {{0.9, 0.9}, -0.5, -1.0}};
  return p;
}

std::filesystem::path temp_path(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "dtlab_poly_format_test";
  std::filesystem::create_directories(dir);
  return dir / name;
}

void expect_parse_error(const std::string& text, const std::function<void(std::istream&)>& read, std::uint64_t line,
                        const std::string& what) {
  std::istringstream in(text);
  try {
    read(in);
    ADD_FAILURE() << "no ParseError for:\n" << text;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), line) << e.what() << "\nfor:\n" << text;
    EXPECT_EQ(e.file(), "input.txt");
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos)
        << "message '" << e.what() << "' lacks '" << what << "'";
  }
}

const auto kRead = [](std::istream& in) { read_triangle_poly(in, "input.txt"); };

// Lines 1-4: three vertices numbered from 1, no attributes or markers.
const std::string kThree = "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n";

TEST(PolyFormat, RoundTripKeepsEveryBit) {
  for (int first : {0, 1}) {
    const PolyData2 p = sample_poly(first);
    std::stringstream s;
    write_triangle_poly(s, p);
    expect_same_poly(read_triangle_poly(s, "memory"), p);
  }
}

TEST(PolyFormat, RoundTripThroughFileWithoutOptionalParts) {
  PolyData2 p;
  p.points = {{0, 0}, {1, 0}, {0, 1}};
  p.segments = {{0, 1}, {1, 2}, {2, 0}};
  const std::string path = temp_path("plain.poly").string();
  write_triangle_poly(path, p);
  expect_same_poly(read_triangle_poly(path), p);
}

TEST(PolyFormat, ReadsTriangleExampleLayout) {
  // Header defaults, 0-based numbering, comments, no region section.
  const std::string text =
      "# a triangle with a dangling segment\n"
      "4\n"
      "0 0 0\n1 2 0   # comment\n2 0 2\n\n3 0.5 0.5\n"
      "4\n0 0 1\n1 1 2\n2 2 0\n3 0 3\n"
      "0\n";
  std::istringstream in(text);
  const PolyData2 p = read_triangle_poly(in, "input.txt");
  EXPECT_EQ(p.first_index, 0);
  EXPECT_EQ(p.points.size(), 4u);
  EXPECT_EQ(p.segments, (std::vector<std::array<std::uint32_t, 2>>{{0, 1}, {1, 2}, {2, 0}, {0, 3}}));
  EXPECT_FALSE(p.has_segment_markers);
  EXPECT_TRUE(p.segment_markers.empty());
  EXPECT_TRUE(p.holes.empty());
  EXPECT_TRUE(p.regions.empty());
}

TEST(PolyFormat, VerticesFromASeparateNodeFile) {
  const PolyData2 full = sample_poly(0);
  TriangleNodes nodes;
  nodes.points = full.points;
  nodes.attribute_count = full.attribute_count;
  nodes.attributes = full.attributes;
  nodes.has_markers = true;
  nodes.markers = full.point_markers;
  nodes.first_index = 0;
  const std::string base = temp_path("separate").string();
  write_triangle_node(base + ".node", nodes);

  // The .poly Triangle writes: 0 vertices, then the rest numbered like the .node.
  std::stringstream rest;
  PolyData2 no_points = full;
  no_points.points.clear();
  no_points.attributes.clear();
  no_points.point_markers.clear();
  no_points.segments.clear();
  no_points.segment_markers.clear();
  write_triangle_poly(rest, no_points);
  std::string text = rest.str();
  std::string segments = "8 1\n";
  for (std::size_t i = 0; i < full.segments.size(); ++i) {
    segments += std::to_string(i) + " " + std::to_string(full.segments[i][0]) + " " +
                std::to_string(full.segments[i][1]) + " " + std::to_string(full.segment_markers[i]) + "\n";
  }
  text.replace(text.find("0 1\n"), 4, segments);  // the empty segment section
  {
    std::ofstream(base + ".poly") << text;
  }
  expect_same_poly(read_triangle_poly(base + ".poly"), full);

  std::istringstream in(text);
  expect_same_poly(read_triangle_poly(in, "memory", &nodes), full);
  expect_parse_error(text, kRead, 3, "vertex number 0, but there are no vertices");

  std::filesystem::remove(base + ".node");
  EXPECT_THROW(read_triangle_poly(base + ".poly"), ParseError);
}

TEST(PolyFormat, WriterRefusesBadData) {
  std::stringstream s;
  PolyData2 p = sample_poly(1);
  p.segments.push_back({0, 10});
  p.segment_markers.push_back(0);
  EXPECT_THROW(write_triangle_poly(s, p), InputError);
  p = sample_poly(1);
  p.segment_markers.pop_back();
  EXPECT_THROW(write_triangle_poly(s, p), InputError);
  p = sample_poly(1);
  p.attributes.pop_back();
  EXPECT_THROW(write_triangle_poly(s, p), InputError);
  p = sample_poly(2);
  EXPECT_THROW(write_triangle_poly(s, p), InputError);
}

RC_GTEST_PROP(PolyFormat, RandomPolysRoundTrip, ()) {
  PolyData2 p;
  const auto n = *rc::gen::inRange<std::size_t>(0, 30);
  auto coordinate = [] {
    const auto mantissa = *rc::gen::arbitrary<std::uint64_t>() & ((std::uint64_t{1} << 52) - 1);
    const int exponent = *rc::gen::inRange(kMinCoordinateExponent, kMaxCoordinateExponent);
    const double v = std::ldexp(1.0 + std::ldexp(static_cast<double>(mantissa), -52), exponent);
    return *rc::gen::arbitrary<bool>() ? -v : v;
  };
  for (std::size_t i = 0; i < n; ++i) p.points.push_back({coordinate(), coordinate()});
  // With no vertices the file does not say where numbering starts: the reader keeps 1.
  p.first_index = n == 0 ? 1 : *rc::gen::inRange(0, 2);
  p.has_segment_markers = *rc::gen::arbitrary<bool>();
  if (n > 0) {
    const auto m = *rc::gen::inRange<std::size_t>(0, 30);
    for (std::size_t i = 0; i < m; ++i) {
      p.segments.push_back({*rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(n)),
                            *rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(n))});
      if (p.has_segment_markers) p.segment_markers.push_back(*rc::gen::arbitrary<int>());
    }
  }
  const auto h = *rc::gen::inRange<std::size_t>(0, 4);
  for (std::size_t i = 0; i < h; ++i) p.holes.push_back({coordinate(), coordinate()});
  const auto r = *rc::gen::inRange<std::size_t>(0, 4);
  for (std::size_t i = 0; i < r; ++i) p.regions.push_back({{coordinate(), coordinate()}, coordinate(), coordinate()});
  std::stringstream s;
  write_triangle_poly(s, p);
  const PolyData2 back = read_triangle_poly(s, "memory");
  RC_ASSERT(back == p);
  for (std::size_t i = 0; i < n; ++i) RC_ASSERT(same_bits(back.points[i], p.points[i]));
}

// --- malformed input -------------------------------------------------------------------------------

TEST(PolyMalformed, VertexSection) {
  expect_parse_error("", kRead, 1, "missing the header");
  expect_parse_error("3 3 0 0\n", kRead, 1, "must be 2D");
  expect_parse_error("3 2 0 2\n", kRead, 1, "not 0 or 1");
  expect_parse_error("3 2 0 0 0\n", kRead, 1, "trailing");
  expect_parse_error("3 2 0 0\n1 0 0\n2 1 0\n", kRead, 3, "file ends after 2 of 3 vertices");
  expect_parse_error("3 2 0 0\n2 0 0\n", kRead, 2, "first one must be 0 or 1");
  expect_parse_error("3 2 0 0\n1 0 0\n3 1 0\n", kRead, 3, "expected 2");
  expect_parse_error("3 2 1 0\n1 0 0\n", kRead, 2, "expected 4 fields, found 3");
  expect_parse_error("3 2 0 1\n1 0 0 1.5\n", kRead, 2, "not an integer");
  expect_parse_error("3 2 0 0\n1 0 1e999\n", kRead, 2, "out of the range of a double");
  expect_parse_error("3 2 0 0\n1 0 1e-300\n", kRead, 2, "vertex 1 of 3 y is too small");
  expect_parse_error("3 2 1 0\n1 0 0 nan\n", kRead, 2, "attribute 1 is not finite");
}

TEST(PolyMalformed, SegmentSection) {
  expect_parse_error(kThree, kRead, 4, "file ends before the segment header");
  expect_parse_error(kThree + "4 0 0\n", kRead, 5, "more vertices than the count says?");
  expect_parse_error(kThree + "1 2\n", kRead, 5, "segment boundary marker count is 2");
  expect_parse_error(kThree + "2 0\n1 1 2\n", kRead, 6, "file ends after 1 of 2 segments");
  expect_parse_error(kThree + "1 0\n1 1 4\n0\n", kRead, 6, "segment 1 of 1: vertex number 4 out of range 1..3");
  expect_parse_error(kThree + "1 0\n1 0 1\n0\n", kRead, 6, "vertex number 0 out of range 1..3");
  expect_parse_error(kThree + "1 1\n1 1 2\n0\n", kRead, 6, "expected 4 fields, found 3");
  expect_parse_error(kThree + "1 0\n1 1 2 7\n0\n", kRead, 6, "trailing text '7'");
  expect_parse_error(kThree + "2 0\n1 1 2\n1 2 3\n0\n", kRead, 7, "expected 2");
  expect_parse_error(kThree + "1 1\n1 1 2 x\n0\n", kRead, 6, "not an integer");
}

TEST(PolyMalformed, HoleAndRegionSections) {
  const std::string segs = kThree + "1 0\n1 1 2\n";  // lines 5-6
  expect_parse_error(segs, kRead, 6, "file ends before the hole count");
  expect_parse_error(segs + "2 1 3\n", kRead, 7, "more segments than the count says?");
  expect_parse_error(segs + "1\n", kRead, 7, "file ends after 0 of 1 holes");
  expect_parse_error(segs + "1\n1 0.2\n", kRead, 8, "expected 3 fields, found 2");
  expect_parse_error(segs + "1\n1 0.2 inf\n", kRead, 8, "not finite");
  expect_parse_error(segs + "1\n1 0.2 1e200\n", kRead, 8, "hole 1 of 1 y is too large");
  expect_parse_error(segs + "1\n1 0.2 0.2\n2 0.3 0.3\n", kRead, 9, "more holes than the count says?");
  expect_parse_error(segs + "0\n1\n1 0.2 0.2 1\n", kRead, 9, "expected 5 fields, found 4");
  expect_parse_error(segs + "0\n1\n1 0.2 0.2 1 0.5\n2 0 0 1 1\n", kRead, 10, "more regions than the count says?");
  expect_parse_error(segs + "0\n2\n1 0.2 0.2 1 0.5\n", kRead, 9, "file ends after 1 of 2 regions");
  expect_parse_error(segs + "0\n1\n1 0.2 0.2 1 -nan\n", kRead, 9, "maximum area is not finite");
  expect_parse_error(segs + "0\n1\n0 0.2 0.2 1e400 1\n", kRead, 9, "attribute '1e400' is out of the range");
  expect_parse_error(segs + "0\n-1\n", kRead, 8, "negative");
}

TEST(PolyMalformed, MissingFileIsAParseError) {
  EXPECT_THROW(read_triangle_poly(temp_path("does_not_exist.poly").string()), ParseError);
}

}  // namespace
}  // namespace dtlab
