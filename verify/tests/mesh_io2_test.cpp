// The 2D file formats: write/read round trips keep every bit, and every kind of malformed input
// is a ParseError naming the file and the right line.
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit.hpp"
#include "mesh/io/point_file.hpp"
#include "mesh/io/triangle_format.hpp"

namespace dtlab {
namespace {

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

template <class P>
void expect_same_points(const std::vector<P>& a, const std::vector<P>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(same_bits(a[i].x, b[i].x)) << "point " << i;
    EXPECT_TRUE(same_bits(a[i].y, b[i].y)) << "point " << i;
    if constexpr (requires { a[i].z; }) {
      EXPECT_TRUE(same_bits(a[i].z, b[i].z)) << "point " << i;
    }
  }
}

void expect_same_mesh(const MeshData2& a, const MeshData2& b) {
  expect_same_points(a.vertices, b.vertices);
  EXPECT_EQ(a.vertex_refs, b.vertex_refs);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.edge_refs, b.edge_refs);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.triangle_refs, b.triangle_refs);
}

// Doubles that a careless writer would not bring back.
std::vector<double> awkward_doubles() {
  return {0.1,
          -0.0,
          0.0,
          1.0 / 3.0,
          -2.0 / 3.0,
          std::nextafter(1.0, 2.0),
          std::nextafter(1.0, 0.0),
          1e9 + 0.123456789,
          kMinCoordinateMagnitude,
          -kMaxCoordinateMagnitude,
          std::nextafter(kMinCoordinateMagnitude, 1.0),
          123456789012345678.0,
          2.2250738585072014e-18};
}

MeshData2 sample_mesh() {
  MeshData2 m;
  const std::vector<double> v = awkward_doubles();
  for (std::size_t i = 0; i + 1 < v.size(); ++i) m.vertices.push_back({v[i], v[i + 1]});
  for (std::size_t i = 0; i < m.vertices.size(); ++i) m.vertex_refs.push_back(static_cast<int>(i) * 7 - 20);
  m.edges = {{0, 1}, {1, 2}, {11, 0}};
  m.edge_refs = {1, -1, std::numeric_limits<int>::max()};
  m.triangles = {{0, 1, 2}, {2, 3, 4}, {9, 10, 11}};
  m.triangle_refs = {std::numeric_limits<int>::min(), 0, 42};
  return m;
}

std::filesystem::path temp_path(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "dtlab_mesh_io2_test";
  std::filesystem::create_directories(dir);
  return dir / name;
}

// Runs `read` on `text` and expects a ParseError at `line` whose message contains `what`.
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

const auto kReadMedit = [](std::istream& in) { read_medit2(in, "input.txt"); };
const auto kReadNode = [](std::istream& in) { read_triangle_node(in, "input.txt"); };
const auto kReadPoints2 = [](std::istream& in) { read_point_file2(in, "input.txt"); };
const auto kReadPoints3 = [](std::istream& in) { read_point_file3(in, "input.txt"); };
const auto kDimension = [](std::istream& in) { point_file_dimension(in, "input.txt"); };

// A .ele reader against three 1-based vertices.
void read_ele_of_three(std::istream& in) {
  std::istringstream node("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n");
  read_triangle_ele(in, "input.txt", read_triangle_node(node, "nodes"));
}

const std::string kHeader = "MeshVersionFormatted 2\nDimension 2\n";

// --- round trips --------------------------------------------------------------------------------

TEST(Medit, RoundTripKeepsEveryBit) {
  const MeshData2 m = sample_mesh();
  std::stringstream s;
  write_medit2(s, m);
  expect_same_mesh(read_medit2(s, "memory"), m);
}

TEST(Medit, RoundTripThroughFile) {
  const MeshData2 m = sample_mesh();
  const std::string path = temp_path("round.mesh").string();
  write_medit2(path, m);
  expect_same_mesh(read_medit2(path), m);
}

TEST(Medit, WriterFillsEmptyReferencesWithZero) {
  MeshData2 m;
  m.vertices = {{0, 0}, {1, 0}, {0, 1}};
  m.triangles = {{0, 1, 2}};
  std::stringstream s;
  write_medit2(s, m);
  const MeshData2 back = read_medit2(s, "memory");
  EXPECT_EQ(back.vertex_refs, (std::vector<int>{0, 0, 0}));
  EXPECT_EQ(back.triangle_refs, (std::vector<int>{0}));
  EXPECT_TRUE(back.edges.empty());
}

TEST(Medit, WriterRefusesBadData) {
  MeshData2 m;
  m.vertices = {{0, 0}, {1, 0}, {0, 1}};
  m.triangles = {{0, 1, 3}};
  std::stringstream s;
  EXPECT_THROW(write_medit2(s, m), InputError);
  m.triangles = {{0, 1, 2}};
  m.triangle_refs = {1, 2};
  EXPECT_THROW(write_medit2(s, m), InputError);
}

TEST(Medit, ReadsTheFreeLayoutMeditAllows) {
  const std::string text =
      "# written by hand\r\n"
      "MeshVersionFormatted\n1\n\n"
      "Dimension\n 2\n"
      "Vertices 3\n"
      "+0.5 -1e-3 7   # a comment after data\n"
      "1 0 0\r\n"
      "\n"
      "0 1 0\n"
      "Edges\n1\n1 2 5\n"
      "Triangles\n1\n1 2 3 -4\n"
      "End\n# trailing comment\n\n";
  std::istringstream in(text);
  const MeshData2 m = read_medit2(in, "input.txt");
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.vertices[0], (Vec2{0.5, -1e-3}));
  EXPECT_EQ(m.vertex_refs, (std::vector<int>{7, 0, 0}));
  EXPECT_EQ(m.edges, (std::vector<std::array<std::uint32_t, 2>>{{0, 1}}));
  EXPECT_EQ(m.edge_refs, (std::vector<int>{5}));
  EXPECT_EQ(m.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}}));
  EXPECT_EQ(m.triangle_refs, (std::vector<int>{-4}));
}

RC_GTEST_PROP(Medit, RandomMeshesRoundTripBitForBit, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(0, 40);
  MeshData2 m;
  for (std::size_t i = 0; i < n; ++i) {
    double c[2];
    for (double& v : c) {
      // Any double in the supported range: random sign, exponent and 52-bit mantissa.
      const auto mantissa = *rc::gen::arbitrary<std::uint64_t>() & ((std::uint64_t{1} << 52) - 1);
      // (1 + m) * 2^e < 2^142 for every mantissa m: the exponent stops one short of the top.
      const int exponent = *rc::gen::inRange(kMinCoordinateExponent, kMaxCoordinateExponent);
      v = std::ldexp(1.0 + std::ldexp(static_cast<double>(mantissa), -52), exponent);
      if (*rc::gen::arbitrary<bool>()) v = -v;
      RC_ASSERT(coordinate_in_range(v));
    }
    m.vertices.push_back({c[0], c[1]});
    m.vertex_refs.push_back(*rc::gen::arbitrary<int>());
  }
  if (n >= 3) {
    const auto t = *rc::gen::inRange<std::size_t>(0, 20);
    for (std::size_t i = 0; i < t; ++i) {
      m.triangles.push_back({*rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(n)),
                             *rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(n)),
                             *rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(n))});
      m.triangle_refs.push_back(*rc::gen::arbitrary<int>());
    }
  }
  std::stringstream s;
  write_medit2(s, m);
  const MeshData2 back = read_medit2(s, "memory");
  RC_ASSERT(back.vertices.size() == m.vertices.size());
  for (std::size_t i = 0; i < n; ++i) {
    RC_ASSERT(same_bits(back.vertices[i].x, m.vertices[i].x));
    RC_ASSERT(same_bits(back.vertices[i].y, m.vertices[i].y));
  }
  RC_ASSERT(back.vertex_refs == m.vertex_refs);
  RC_ASSERT(back.triangles == m.triangles);
  RC_ASSERT(back.triangle_refs == m.triangle_refs);
}

TEST(TriangleFormat, NodeRoundTripWithAttributesAndMarkers) {
  for (int first : {0, 1}) {
    TriangleNodes nodes;
    const std::vector<double> v = awkward_doubles();
    for (std::size_t i = 0; i + 1 < v.size(); ++i) nodes.points.push_back({v[i], v[i + 1]});
    nodes.attribute_count = 2;
    for (std::size_t i = 0; i < 2 * nodes.points.size(); ++i) nodes.attributes.push_back(1.0 / (1.0 + i));
    nodes.has_markers = true;
    for (std::size_t i = 0; i < nodes.points.size(); ++i) nodes.markers.push_back(static_cast<int>(i % 3) - 1);
    nodes.first_index = first;
    std::stringstream s;
    write_triangle_node(s, nodes);
    const TriangleNodes back = read_triangle_node(s, "memory");
    expect_same_points(back.points, nodes.points);
    EXPECT_EQ(back.attribute_count, 2u);
    ASSERT_EQ(back.attributes.size(), nodes.attributes.size());
    for (std::size_t i = 0; i < back.attributes.size(); ++i) EXPECT_TRUE(same_bits(back.attributes[i], nodes.attributes[i]));
    EXPECT_TRUE(back.has_markers);
    EXPECT_EQ(back.markers, nodes.markers);
    EXPECT_EQ(back.first_index, first);
  }
}

TEST(TriangleFormat, EleRoundTripThreeAndSixNodes) {
  TriangleNodes nodes;
  for (int i = 0; i < 7; ++i) nodes.points.push_back({static_cast<double>(i), static_cast<double>(i * i)});
  for (int first : {0, 1}) {
    nodes.first_index = first;
    TriangleElements e;
    e.triangles = {{0, 1, 2}, {2, 1, 6}};
    e.attribute_count = 1;
    e.attributes = {3.5, -1.0};
    e.first_index = 1 - first;
    e.vertex_first_index = first;
    for (bool six : {false, true}) {
      e.midside.clear();
      if (six) e.midside = {{3, 4, 5}, {5, 4, 3}};
      std::stringstream s;
      write_triangle_ele(s, e, nodes.points.size());
      const TriangleElements back = read_triangle_ele(s, "memory", nodes);
      EXPECT_EQ(back.triangles, e.triangles);
      EXPECT_EQ(back.midside, e.midside);
      EXPECT_EQ(back.attributes, e.attributes);
      EXPECT_EQ(back.first_index, e.first_index);
      EXPECT_EQ(back.vertex_first_index, first);
    }
  }
}

TEST(TriangleFormat, MeshRoundTripThroughFiles) {
  MeshData2 m = sample_mesh();
  m.edges.clear();  // .node/.ele carry no edges
  m.edge_refs.clear();
  const std::string base = temp_path("round").string();
  write_triangle_mesh(base, m);
  expect_same_mesh(read_triangle_mesh(base), m);
}

TEST(TriangleFormat, HeaderDefaultsAndZeroBasedNumbering) {
  std::istringstream node("# Triangle's defaults: 2D, no attributes, no markers\n3\n0 0 0\n1 1 0\n2 0 1\n");
  const TriangleNodes nodes = read_triangle_node(node, "input.txt");
  EXPECT_EQ(nodes.first_index, 0);
  EXPECT_EQ(nodes.points.size(), 3u);
  EXPECT_FALSE(nodes.has_markers);
  std::istringstream ele("1\n0 0 1 2\n");
  const TriangleElements e = read_triangle_ele(ele, "input.txt", nodes);
  EXPECT_EQ(e.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}}));
  const MeshData2 m = to_mesh_data(nodes, e);
  EXPECT_EQ(m.vertex_refs, (std::vector<int>{0, 0, 0}));
  EXPECT_EQ(m.triangle_refs, (std::vector<int>{0}));
}

TEST(TriangleFormat, NonIntegralAttributesAreNotReferences) {
  std::istringstream node("3 2 0 1\n1 0 0 5\n2 1 0 6\n3 0 1 7\n");
  const TriangleNodes nodes = read_triangle_node(node, "input.txt");
  std::istringstream ele("1 3 1\n1 1 2 3 0.5\n");
  const MeshData2 m = to_mesh_data(nodes, read_triangle_ele(ele, "input.txt", nodes));
  EXPECT_EQ(m.vertex_refs, (std::vector<int>{5, 6, 7}));
  EXPECT_EQ(m.triangle_refs, (std::vector<int>{0}));
}

TEST(PointFile, RoundTrip2dAnd3d) {
  std::vector<Vec2> p2;
  std::vector<Vec3> p3;
  const std::vector<double> v = awkward_doubles();
  for (std::size_t i = 0; i + 2 < v.size(); ++i) {
    p2.push_back({v[i], v[i + 1]});
    p3.push_back({v[i], v[i + 1], v[i + 2]});
  }
  std::stringstream s2, s3;
  write_point_file(s2, p2);
  write_point_file(s3, p3);
  EXPECT_EQ(point_file_dimension(s2, "a"), 2);
  EXPECT_EQ(point_file_dimension(s3, "b"), 3);
  s2.clear();
  s2.seekg(0);
  s3.clear();
  s3.seekg(0);
  expect_same_points(read_point_file2(s2, "a"), p2);
  expect_same_points(read_point_file3(s3, "b"), p3);

  const std::string path = temp_path("points.xy").string();
  write_point_file(path, std::span<const Vec2>(p2));
  EXPECT_EQ(point_file_dimension(path), 2);
  expect_same_points(read_point_file2(path), p2);
}

TEST(PointFile, CommentsAndBlankLines) {
  std::istringstream in("# header\n\n  1 2  \n\t3 4 # trailing comment\n#5 6\n");
  const std::vector<Vec2> p = read_point_file2(in, "input.txt");
  EXPECT_EQ(p, (std::vector<Vec2>{{1, 2}, {3, 4}}));
}

TEST(Readers, MissingFileIsAParseError) {
  const std::string missing = temp_path("does_not_exist.mesh").string();
  EXPECT_THROW(read_medit2(missing), ParseError);
  EXPECT_THROW(read_triangle_mesh(missing), ParseError);
  EXPECT_THROW(read_point_file2(missing), ParseError);
}

// --- malformed input: Medit -----------------------------------------------------------------------

TEST(MeditMalformed, CountsAndTruncation) {
  expect_parse_error(kHeader + "Vertices\nEnd\n", kReadMedit, 3, "missing count after Vertices");
  expect_parse_error(kHeader + "Vertices\n", kReadMedit, 3, "missing count");
  expect_parse_error(kHeader + "Vertices -1\nEnd\n", kReadMedit, 3, "negative");
  expect_parse_error(kHeader + "Vertices 99999999999\nEnd\n", kReadMedit, 3, "32-bit");
  expect_parse_error(kHeader + "Vertices 3\n0 0 0\n1 0 0\nEnd\n", kReadMedit, 6, "count is 3 but only 2");
  expect_parse_error(kHeader + "Vertices 1\n0 0 0\n1 0 0\nEnd\n", kReadMedit, 5, "more entries than");
  expect_parse_error(kHeader + "Vertices 3\n0 0 0\n1 0 0\n", kReadMedit, 5, "truncated");
  expect_parse_error(kHeader + "Vertices 1\n0 0 0\n", kReadMedit, 4, "ends before End");
  expect_parse_error("", kReadMedit, 1, "ends before End");
  expect_parse_error(kHeader + "Vertices 1 2\nEnd\n", kReadMedit, 3, "trailing");
}

TEST(MeditMalformed, BadNumbers) {
  expect_parse_error(kHeader + "Vertices 1\n0 abc 0\nEnd\n", kReadMedit, 4, "not a number: 'abc'");
  expect_parse_error(kHeader + "Vertices 1\n0 nan 0\nEnd\n", kReadMedit, 4, "not finite");
  expect_parse_error(kHeader + "Vertices 1\n-inf 0 0\nEnd\n", kReadMedit, 4, "not finite");
  expect_parse_error(kHeader + "Vertices 1\n1e999 0 0\nEnd\n", kReadMedit, 4, "out of the range of a double");
  expect_parse_error(kHeader + "Vertices 1\n0x10 0 0\nEnd\n", kReadMedit, 4, "not a number");
  expect_parse_error(kHeader + "Vertices 1\n1.5.2 0 0\nEnd\n", kReadMedit, 4, "not a number");
  expect_parse_error(kHeader + "Vertices 1\n0 0 1.5\nEnd\n", kReadMedit, 4, "not an integer");
  expect_parse_error(kHeader + "Vertices 1\n1e300 0 0\nEnd\n", kReadMedit, 4, "too large");
  expect_parse_error(kHeader + "Vertices 1\n0 1e-300 0\nEnd\n", kReadMedit, 4, "too small");
  expect_parse_error(kHeader + "Vertices 1\n0 0 99999999999\nEnd\n", kReadMedit, 4, "does not fit an int");
}

TEST(MeditMalformed, FieldCounts) {
  expect_parse_error(kHeader + "Vertices 1\n0 0\nEnd\n", kReadMedit, 4, "expected 3 fields, found 2");
  expect_parse_error(kHeader + "Vertices 1\n0 0 1 7\nEnd\n", kReadMedit, 4, "trailing text '7'");
  expect_parse_error(kHeader + "Vertices 3\n0 0 0\n1 0 0\n0 1 0\nTriangles 1\n1 2 3\nEnd\n", kReadMedit, 8,
                     "expected 4 fields, found 3");
}

TEST(MeditMalformed, IndicesOutOfRange) {
  const std::string v = kHeader + "Vertices 3\n0 0 0\n1 0 0\n0 1 0\n";
  expect_parse_error(v + "Triangles 1\n1 2 4 0\nEnd\n", kReadMedit, 8, "vertex number 4 out of range 1..3");
  expect_parse_error(v + "Triangles 1\n0 1 2 0\nEnd\n", kReadMedit, 8, "vertex number 0 out of range");
  expect_parse_error(v + "Edges 1\n1 -2 0\nEnd\n", kReadMedit, 8, "out of range");
}

TEST(MeditMalformed, Keywords) {
  expect_parse_error("Dimension 2\nMeshVersionFormatted 2\nEnd\n", kReadMedit, 1, "MeshVersionFormatted first");
  expect_parse_error("MeshVersionFormatted 7\nEnd\n", kReadMedit, 1, "not 1, 2, 3 or 4");
  expect_parse_error("MeshVersionFormatted 2\nDimension 3\nEnd\n", kReadMedit, 2, "3D mesh");
  expect_parse_error("MeshVersionFormatted 2\nDimension\n3\nEnd\n", kReadMedit, 3, "3D mesh");
  expect_parse_error("MeshVersionFormatted 2\nVertices 0\nEnd\n", kReadMedit, 2, "Vertices before Dimension");
  expect_parse_error(kHeader + "Triangles 0\nEnd\n", kReadMedit, 3, "Triangles before Vertices");
  expect_parse_error(kHeader + "Vertices 0\nVertices 0\nEnd\n", kReadMedit, 4, "second Vertices");
  expect_parse_error(kHeader + "Foo 3\nEnd\n", kReadMedit, 3, "unknown keyword 'Foo'");
  expect_parse_error(kHeader + "vertices 3\nEnd\n", kReadMedit, 3, "case-sensitive");
  expect_parse_error(kHeader + "Quadrilaterals 0\nEnd\n", kReadMedit, 3, "not supported by the 2D reader");
  expect_parse_error(kHeader + "End\nVertices 0\n", kReadMedit, 4, "text after End");
  expect_parse_error(kHeader + "End extra\n", kReadMedit, 3, "trailing");
  expect_parse_error(std::string("MeshVersionFormatted 2\nDim\x01\xff\n"), kReadMedit, 2, "\\x01\\xff");
}

// --- Medit 2D: feature and attribute sections, read, checked and skipped with a note -------------

// Lines 1-6: three vertices of a triangle.
const std::string kTriVertices = kHeader + "Vertices 3\n0 0 1\n1 0 2\n0 1 3\n";
const std::string kSkippedBare2 = kTriVertices + "Edges 2\n1 2 4\n2 3 5\nTriangles 1\n1 2 3 6\nEnd\n";
const std::string kSkippedFull2 = kTriVertices +  // lines 1-6
                                  "Corners 3\n1\n2\n3\n"
                                  "Edges 2\n1 2 4\n2 3 5\n"
                                  "Triangles 1\n1 2 3 6\n"
                                  "RequiredVertices 1\n2\n"
                                  "Ridges 1\n2\n"
                                  "RequiredEdges 2\n1\n2\n"
                                  "RequiredTriangles 1\n1\n"
                                  "Normals 1\n0 1\n"
                                  "NormalAtVertices 1\n3 1\n"
                                  "Tangents 2\n1 0\n0.6 0.8\n"
                                  "TangentAtVertices 2\n1 2\n2 1\n"
                                  "Identifier \"triangle\"\n"
                                  "Geometry\n\"triangle.mesh\"\n"
                                  "End\n";

TEST(MeditSkipped, EverySectionReadCheckedAndNamedInANote) {
  std::istringstream full(kSkippedFull2), bare(kSkippedBare2);
  std::vector<std::string> notes, bare_notes;
  expect_same_mesh(read_medit2(full, "input.txt", &notes), read_medit2(bare, "input.txt", &bare_notes));
  EXPECT_TRUE(bare_notes.empty());
  const std::vector<std::string> expected = {
      "section Corners skipped (3 entries from line 7: corner vertices)",
      "section RequiredVertices skipped (1 entry from line 16: required vertices)",
      "section Ridges skipped (1 entry from line 18: ridge edges)",
      "section RequiredEdges skipped (2 entries from line 20: required edges)",
      "section RequiredTriangles skipped (1 entry from line 23: required triangles)",
      "section Normals skipped (1 entry from line 25: normal vectors)",
      "section NormalAtVertices skipped (1 entry from line 27: vertex normals)",
      "section Tangents skipped (2 entries from line 29: tangent vectors)",
      "section TangentAtVertices skipped (2 entries from line 32: vertex tangents)",
      "section Identifier skipped (line 35: the mesh's name)",
      "section Geometry skipped (line 36: the geometry file's name)"};
  EXPECT_EQ(notes, expected);
}

TEST(MeditSkipped, MalformedCountsAndNumbersNameTheLine) {
  // kTriVertices is lines 1-6.
  expect_parse_error(kTriVertices + "Corners 2\n1\nEnd\n", kReadMedit, 9, "Corners count is 2 but only 1 entries");
  expect_parse_error(kTriVertices + "Corners 1\n1\n3\nEnd\n", kReadMedit, 9, "more entries than the section's count");
  expect_parse_error(kTriVertices + "Corners 2\n4\n1\nEnd\n", kReadMedit, 8,
                     "Corners entry 1: vertex number 4 out of range 1..3");
  expect_parse_error(kTriVertices + "Corners 1\n-1\nEnd\n", kReadMedit, 8, "not positive");
  expect_parse_error(kTriVertices + "Corners 1\n1.5\nEnd\n", kReadMedit, 8, "Corners entry 1: vertex number");
  expect_parse_error(kTriVertices + "RequiredEdges 1\n1\nEnd\n", kReadMedit, 8, "edge number 1 out of range 1..0");
  expect_parse_error(kTriVertices + "Triangles 1\n1 2 3 0\nRequiredTriangles 1\n2\nEnd\n", kReadMedit, 10,
                     "RequiredTriangles entry 1: triangle number 2 out of range 1..1");
  expect_parse_error(kTriVertices + "Tangents 1\n1 0\nTangentAtVertices 1\n1 2\nEnd\n", kReadMedit, 10,
                     "tangent number 2 out of range 1..1");
  expect_parse_error(kTriVertices + "Normals 1\n0 0 1\nEnd\n", kReadMedit, 8, "trailing");
  expect_parse_error(kTriVertices + "NormalAtVertices 1\n1\nEnd\n", kReadMedit, 8, "expected 2 fields, found 1");
  expect_parse_error(kTriVertices + "Ridges 1\n1\nRidges 1\n1\nEnd\n", kReadMedit, 9, "second Ridges section");
  expect_parse_error(kTriVertices + "Identifier\nEnd\n", kReadMedit, 7, "missing string after Identifier");
}

TEST(MeditSkipped, ElementsTheMeshCannotHoldStayRefused) {
  for (const char* kw : {"Quadrilaterals", "Tetrahedra", "Hexahedra", "EdgesP2", "TrianglesP2"}) {
    expect_parse_error(kTriVertices + kw + " 0\nEnd\n", kReadMedit, 7,
                       std::string("'").append(kw).append("' is not supported by the 2D reader"));
  }
}

// --- malformed input: Triangle --------------------------------------------------------------------

TEST(TriangleMalformed, NodeHeader) {
  expect_parse_error("", kReadNode, 1, "missing the header");
  expect_parse_error("# only a comment\n\n", kReadNode, 1, "missing the header");
  expect_parse_error("3 3 0 0\n", kReadNode, 1, "must be 2D");
  expect_parse_error("3 2 0 2\n", kReadNode, 1, "not 0 or 1");
  expect_parse_error("3 2 -1 0\n", kReadNode, 1, "negative");
  expect_parse_error("3 2 0 0 9\n", kReadNode, 1, "trailing");
  expect_parse_error("three 2 0 0\n", kReadNode, 1, "not an integer");
}

TEST(TriangleMalformed, NodeEntries) {
  expect_parse_error("2 2 0 0\n2 0 0\n3 1 1\n", kReadNode, 2, "first one must be 0 or 1");
  expect_parse_error("2 2 0 0\n1 0 0\n3 1 1\n", kReadNode, 3, "expected 2");
  expect_parse_error("2 2 0 0\n1 0 0\n2 1\n", kReadNode, 3, "expected 3 fields, found 2");
  expect_parse_error("2 2 1 0\n1 0 0 0.5\n2 1 1\n", kReadNode, 3, "expected 4 fields, found 3");
  expect_parse_error("2 2 0 1\n1 0 0 1\n2 1 1 1 1\n", kReadNode, 3, "trailing");
  expect_parse_error("2 2 0 1\n1 0 0 1\n2 1 1 1.5\n", kReadNode, 3, "not an integer");
  expect_parse_error("2 2 0 0\n1 0 0\n\n# comment\n", kReadNode, 2, "truncated");
  expect_parse_error("1 2 0 0\n1 0 0\n2 1 1\n", kReadNode, 3, "more lines than");
  expect_parse_error("1 2 0 0\n1 NaN 0\n", kReadNode, 2, "not finite");
  expect_parse_error("1 2 1 0\n1 0 0 inf\n", kReadNode, 2, "not finite");
  expect_parse_error("1 2 0 0\n1 0 1e200\n", kReadNode, 2, "too large");
}

TEST(TriangleMalformed, EleEntries) {
  expect_parse_error("", read_ele_of_three, 1, "missing the header");
  expect_parse_error("1 4 0\n", read_ele_of_three, 1, "not 3 or 6");
  expect_parse_error("1 3 0 5\n", read_ele_of_three, 1, "trailing");
  expect_parse_error("1 3 0\n1 1 2 4\n", read_ele_of_three, 2, "node 4 out of range 1..3");
  expect_parse_error("1 3 0\n1 0 1 2\n", read_ele_of_three, 2, "node 0 out of range 1..3");
  expect_parse_error("1 3 0\n1 1 2\n", read_ele_of_three, 2, "expected 4 fields, found 3");
  expect_parse_error("1 3 1\n1 1 2 3\n", read_ele_of_three, 2, "expected 5 fields, found 4");
  expect_parse_error("2 3 0\n1 1 2 3\n", read_ele_of_three, 2, "truncated");
  expect_parse_error("2 3 0\n1 1 2 3\n3 1 2 3\n", read_ele_of_three, 3, "expected 2");
  expect_parse_error("1 3 0\n1 1 2 3\n2 1 2 3\n", read_ele_of_three, 3, "more lines than");
  expect_parse_error("1 3 0\n1 1 2 x\n", read_ele_of_three, 2, "not an integer");
}

// --- malformed input: point files ------------------------------------------------------------------

TEST(PointFileMalformed, Lines) {
  expect_parse_error("0 0\n1 2 3\n", kReadPoints2, 2, "a 3D point file?");
  expect_parse_error("0 0 0\n1 2\n", kReadPoints3, 2, "a 2D point file?");
  expect_parse_error("0 0\n1\n", kReadPoints2, 2, "expected 2 coordinates, found 1");
  expect_parse_error("# c\n0 0\n1 two\n", kReadPoints2, 3, "not a number: 'two'");
  expect_parse_error("0 0\n\n\n1 -Infinity\n", kReadPoints2, 4, "not finite");
  expect_parse_error("0 0\n1 1e-310\n", kReadPoints2, 2, "too small");
  expect_parse_error("0 0\n1 1,5\n", kReadPoints2, 2, "not a number");
  expect_parse_error("", kDimension, 1, "no point");
  expect_parse_error("# nothing\n\n", kDimension, 2, "no point");
  expect_parse_error("1 2 3 4\n", kDimension, 1, "2 or 3 per line");
  expect_parse_error("1 x\n", kDimension, 1, "not a number");
}

}  // namespace
}  // namespace dtlab
