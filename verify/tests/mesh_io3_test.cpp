// The 3D file formats (Medit 3D, TetGen .node/.ele/.face): write/read round trips keep every
// bit, tetrahedra come out positive whatever the file's orientation, and every kind of
// malformed input is a ParseError naming the file and the right line.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/io/medit.hpp"
#include "mesh/io/medit3.hpp"
#include "mesh/io/tetgen_format.hpp"

namespace dtlab {
namespace {

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

void expect_same_points(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(same_bits(a[i].x, b[i].x) && same_bits(a[i].y, b[i].y) && same_bits(a[i].z, b[i].z))
        << "point " << i;
  }
}

void expect_same_mesh(const MeshData3& a, const MeshData3& b) {
  expect_same_points(a.vertices, b.vertices);
  EXPECT_EQ(a.vertex_refs, b.vertex_refs);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.edge_refs, b.edge_refs);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.triangle_refs, b.triangle_refs);
  EXPECT_EQ(a.tetrahedra, b.tetrahedra);
  EXPECT_EQ(a.tetrahedron_refs, b.tetrahedron_refs);
}

// Doubles that a careless writer would not bring back.
std::vector<double> awkward_doubles() {
  return {0.1,
          -0.0,
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

bool positive(const MeshData3& m, const std::array<std::uint32_t, 4>& t) {
  return orient3d(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], m.vertices[t[3]]) == Sign::Positive;
}

// Awkward coordinates on the vertices that no tetrahedron uses; a cube split into five positive
// tetrahedra (the first eight vertices) for the ones that do.
MeshData3 sample_mesh() {
  MeshData3 m;
  for (int i = 0; i < 8; ++i) m.vertices.push_back({0.1 * (i & 1), 0.1 * ((i >> 1) & 1), 0.1 * (i >> 2)});
  const std::vector<double> v = awkward_doubles();
  for (std::size_t i = 0; i + 2 < v.size(); ++i) m.vertices.push_back({v[i], v[i + 1], v[i + 2]});
  for (std::size_t i = 0; i < m.vertices.size(); ++i) m.vertex_refs.push_back(static_cast<int>(i) * 7 - 20);
  m.edges = {{0, 1}, {1, 2}, {17, 0}};
  m.edge_refs = {1, -1, std::numeric_limits<int>::max()};
  m.triangles = {{0, 1, 2}, {2, 3, 4}, {15, 16, 17}};
  m.triangle_refs = {std::numeric_limits<int>::min(), 0, 42};
  // Corner 0 and its three neighbours, the other three corners with 7, and the middle one.
  m.tetrahedra = {{0, 1, 2, 4}, {3, 2, 1, 7}, {5, 4, 7, 1}, {6, 7, 4, 2}, {1, 2, 4, 7}};
  for (auto& t : m.tetrahedra) {
    if (!positive(m, t)) std::swap(t[2], t[3]);
  }
  m.tetrahedron_refs = {1, 2, 3, -4, 0};
  return m;
}

std::filesystem::path temp_path(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "dtlab_mesh_io3_test";
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

const auto kReadMedit3 = [](std::istream& in) { read_medit3(in, "input.txt"); };
const std::string kHeader = "MeshVersionFormatted 2\nDimension 3\n";
// Lines 3-7: four vertices of a positive tetrahedron (1 2 3 4).
const std::string kTetVertices = kHeader + "Vertices 4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";

// --- Medit 3D ------------------------------------------------------------------------------------

TEST(Medit3, SampleTetrahedraArePositive) {
  const MeshData3 m = sample_mesh();
  for (const auto& t : m.tetrahedra) EXPECT_TRUE(positive(m, t));
}

TEST(Medit3, RoundTripKeepsEveryBit) {
  const MeshData3 m = sample_mesh();
  std::stringstream s;
  write_medit3(s, m);
  const MeshData3 back = read_medit3(s, "memory");
  expect_same_mesh(back, m);
}

TEST(Medit3, RoundTripThroughFile) {
  const MeshData3 m = sample_mesh();
  const std::string path = temp_path("round.mesh").string();
  write_medit3(path, m);
  expect_same_mesh(read_medit3(path), m);
}

TEST(Medit3, WriterFillsEmptyReferencesAndRefusesBadData) {
  MeshData3 m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.tetrahedra = {{0, 1, 2, 3}};
  std::stringstream s;
  write_medit3(s, m);
  const MeshData3 back = read_medit3(s, "memory");
  EXPECT_EQ(back.vertex_refs, (std::vector<int>{0, 0, 0, 0}));
  EXPECT_EQ(back.tetrahedron_refs, (std::vector<int>{0}));
  EXPECT_TRUE(back.triangles.empty());

  m.tetrahedra = {{0, 1, 2, 4}};
  EXPECT_THROW(write_medit3(s, m), InputError);
  m.tetrahedra = {{0, 1, 2, 3}};
  m.tetrahedron_refs = {1, 2};
  EXPECT_THROW(write_medit3(s, m), InputError);
  m.tetrahedron_refs.clear();
  m.vertex_refs = {1};
  EXPECT_THROW(write_medit3(s, m), InputError);
}

TEST(Medit3, ReadsTheFreeLayoutMeditAllows) {
  const std::string text =
      "# written by hand\r\n"
      "MeshVersionFormatted\n1\n\n"
      "Dimension\n 3\n"
      "Vertices 4\n"
      "+0.5 -1e-3 0 7   # a comment after data\n"
      "1 0 0 0\r\n"
      "\n"
      "0 1 0 0\n"
      "0 0 1 0\n"
      "Tetrahedra\n1\n1 2 3 4 9\n"
      "Edges\n1\n1 2 5\n"
      "Triangles\n1\n1 2 3 -4\n"
      "End\n# trailing comment\n\n";
  std::istringstream in(text);
  const MeshData3 m = read_medit3(in, "input.txt");
  ASSERT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.vertices[0], (Vec3{0.5, -1e-3, 0}));
  EXPECT_EQ(m.vertex_refs, (std::vector<int>{7, 0, 0, 0}));
  EXPECT_EQ(m.edges, (std::vector<std::array<std::uint32_t, 2>>{{0, 1}}));
  EXPECT_EQ(m.triangle_refs, (std::vector<int>{-4}));
  EXPECT_EQ(m.tetrahedra, (std::vector<std::array<std::uint32_t, 4>>{{0, 1, 2, 3}}));
  EXPECT_EQ(m.tetrahedron_refs, (std::vector<int>{9}));
}

RC_GTEST_PROP(Medit3, RandomMeshesRoundTripBitForBit, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(0, 40);
  MeshData3 m;
  for (std::size_t i = 0; i < n; ++i) {
    double c[3];
    for (double& v : c) {
      // Any double in the supported range: random sign, exponent and 52-bit mantissa, the
      // exponent one short of the top so that (1 + m) * 2^e < 2^142.
      const auto mantissa = *rc::gen::arbitrary<std::uint64_t>() & ((std::uint64_t{1} << 52) - 1);
      const int exponent = *rc::gen::inRange(kMinCoordinateExponent, kMaxCoordinateExponent);
      v = std::ldexp(1.0 + std::ldexp(static_cast<double>(mantissa), -52), exponent);
      if (*rc::gen::arbitrary<bool>()) v = -v;
      RC_ASSERT(coordinate_in_range(v));
    }
    m.vertices.push_back({c[0], c[1], c[2]});
    m.vertex_refs.push_back(*rc::gen::arbitrary<int>());
  }
  if (n >= 4) {
    const auto t = *rc::gen::inRange<std::size_t>(0, 20);
    for (std::size_t i = 0; i < t; ++i) {
      std::array<std::uint32_t, 4> tet{};
      for (auto& v : tet) v = *rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(n));
      const Sign s = orient3d(m.vertices[tet[0]], m.vertices[tet[1]], m.vertices[tet[2]], m.vertices[tet[3]]);
      if (s == Sign::Zero) continue;  // a flat tetrahedron is not a valid MeshData3
      if (s == Sign::Negative) std::swap(tet[0], tet[1]);
      m.tetrahedra.push_back(tet);
      m.tetrahedron_refs.push_back(*rc::gen::arbitrary<int>());
      m.triangles.push_back({tet[0], tet[1], tet[2]});
      m.triangle_refs.push_back(*rc::gen::arbitrary<int>());
    }
  }
  std::stringstream s;
  write_medit3(s, m);
  const MeshData3 back = read_medit3(s, "memory");
  RC_ASSERT(back.vertices.size() == m.vertices.size());
  for (std::size_t i = 0; i < n; ++i) {
    RC_ASSERT(same_bits(back.vertices[i].x, m.vertices[i].x));
    RC_ASSERT(same_bits(back.vertices[i].y, m.vertices[i].y));
    RC_ASSERT(same_bits(back.vertices[i].z, m.vertices[i].z));
  }
  RC_ASSERT(back.vertex_refs == m.vertex_refs);
  RC_ASSERT(back.triangles == m.triangles);
  RC_ASSERT(back.triangle_refs == m.triangle_refs);
  RC_ASSERT(back.tetrahedra == m.tetrahedra);
  RC_ASSERT(back.tetrahedron_refs == m.tetrahedron_refs);
}

TEST(Medit3, TwoDimensionalFilesAreRefusedEachWay) {
  // A 2D file to the 3D reader and a 3D file to the 2D reader: each names the other reader's job.
  std::stringstream s2;
  write_medit2(s2, MeshData2{{{0, 0}, {1, 0}, {0, 1}}, {}, {}, {}, {{0, 1, 2}}, {}});
  expect_parse_error(s2.str(), kReadMedit3, 3, "2D mesh");
  std::stringstream s3;
  write_medit3(s3, sample_mesh());
  expect_parse_error(s3.str(), [](std::istream& in) { read_medit2(in, "input.txt"); }, 3, "3D mesh");
}

TEST(Medit3Malformed, CountsAndTruncation) {
  expect_parse_error(kHeader + "Vertices\nEnd\n", kReadMedit3, 3, "missing count after Vertices");
  expect_parse_error(kHeader + "Vertices -1\nEnd\n", kReadMedit3, 3, "negative");
  expect_parse_error(kHeader + "Vertices 3\n0 0 0 0\n1 0 0 0\nEnd\n", kReadMedit3, 6, "count is 3 but only 2");
  expect_parse_error(kHeader + "Vertices 1\n0 0 0 0\n1 0 0 0\nEnd\n", kReadMedit3, 5, "more entries than");
  expect_parse_error(kHeader + "Vertices 3\n0 0 0 0\n1 0 0 0\n", kReadMedit3, 5, "truncated");
  expect_parse_error(kTetVertices, kReadMedit3, 7, "ends before End");
  expect_parse_error(kTetVertices + "Tetrahedra 2\n1 2 3 4 0\nEnd\n", kReadMedit3, 10, "count is 2 but only 1");
  expect_parse_error("", kReadMedit3, 1, "ends before End");
}

TEST(Medit3Malformed, Fields) {
  expect_parse_error(kHeader + "Vertices 1\n0 0 0\nEnd\n", kReadMedit3, 4, "expected 4 fields, found 3");
  expect_parse_error(kHeader + "Vertices 1\n0 0 0 1 7\nEnd\n", kReadMedit3, 4, "trailing text '7'");
  expect_parse_error(kHeader + "Vertices 1\n0 0 z 1\nEnd\n", kReadMedit3, 4, "vertex 1 z is not a number");
  expect_parse_error(kHeader + "Vertices 1\n0 0 nan 1\nEnd\n", kReadMedit3, 4, "not finite");
  expect_parse_error(kHeader + "Vertices 1\n0 0 1e300 1\nEnd\n", kReadMedit3, 4, "vertex 1 z is too large");
  expect_parse_error(kHeader + "Vertices 1\n0 0 0 1.5\nEnd\n", kReadMedit3, 4, "not an integer");
  expect_parse_error(kHeader + "Vertices 1\n0 0 0 3000000000\nEnd\n", kReadMedit3, 4, "does not fit an int");
  expect_parse_error(kTetVertices + "Tetrahedra 1\n1 2 3 4\nEnd\n", kReadMedit3, 9, "expected 5 fields, found 4");
  expect_parse_error(kTetVertices + "Tetrahedra 1\n1 2 3 4 0 0\nEnd\n", kReadMedit3, 9, "trailing");
}

TEST(Medit3Malformed, IndicesOutOfRange) {
  expect_parse_error(kTetVertices + "Tetrahedra 1\n1 2 3 5 0\nEnd\n", kReadMedit3, 9,
                     "tetrahedron 1: vertex number 5 out of range 1..4");
  expect_parse_error(kTetVertices + "Tetrahedra 1\n0 2 3 4 0\nEnd\n", kReadMedit3, 9, "vertex number 0 out of range");
  expect_parse_error(kTetVertices + "Triangles 1\n1 2 -3 0\nEnd\n", kReadMedit3, 9, "out of range");
  expect_parse_error(kTetVertices + "Edges 1\n1 9 0\nEnd\n", kReadMedit3, 9, "edge 1: vertex number 9");
  expect_parse_error(kHeader + "Vertices 0\nEdges 1\n1 1 0\nEnd\n", kReadMedit3, 5, "there are no vertices");
}

TEST(Medit3Malformed, TetrahedraMustBePositive) {
  expect_parse_error(kTetVertices + "Tetrahedra 1\n1 2 4 3 0\nEnd\n", kReadMedit3, 9, "negatively oriented");
  expect_parse_error(kTetVertices + "Tetrahedra 2\n1 2 3 4 0\n2 1 3 4 0\nEnd\n", kReadMedit3, 10,
                     "tetrahedron 2 is negatively oriented");
  expect_parse_error(kTetVertices + "Tetrahedra 1\n1 2 3 3 0\nEnd\n", kReadMedit3, 9, "flat");
  // Coplanar but distinct: decided exactly, not with a tolerance.
  const std::string coplanar = kHeader + "Vertices 4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0.5 0.5 0 0\n";
  expect_parse_error(coplanar + "Tetrahedra 1\n1 2 3 4 0\nEnd\n", kReadMedit3, 9, "flat");
  // The smallest lift off that plane is positive.
  const std::string lifted =
      kHeader + "Vertices 4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0.5 0.5 1.793662034335766e-43 0\nTetrahedra 1\n1 2 3 4 0\nEnd\n";
  std::istringstream in(lifted);
  EXPECT_EQ(read_medit3(in, "input.txt").tetrahedra.size(), 1u);
}

TEST(Medit3Malformed, Keywords) {
  expect_parse_error("Dimension 3\nMeshVersionFormatted 2\nEnd\n", kReadMedit3, 1, "MeshVersionFormatted first");
  expect_parse_error("MeshVersionFormatted 2\nDimension 4\nEnd\n", kReadMedit3, 2, "Dimension 4 is not 3");
  expect_parse_error("MeshVersionFormatted 2\nDimension\n2\nEnd\n", kReadMedit3, 3, "2D mesh");
  expect_parse_error("MeshVersionFormatted 2\nVertices 0\nEnd\n", kReadMedit3, 2, "Vertices before Dimension");
  expect_parse_error(kHeader + "Tetrahedra 0\nEnd\n", kReadMedit3, 3, "Tetrahedra before Vertices");
  expect_parse_error(kTetVertices + "Tetrahedra 0\nTetrahedra 0\nEnd\n", kReadMedit3, 9, "second Tetrahedra");
  expect_parse_error(kHeader + "Hexahedra 0\nEnd\n", kReadMedit3, 3,
                     "'Hexahedra' is not supported by the 3D reader (it keeps Vertices, Edges, Triangles and Tetrahedra)");
  expect_parse_error(kHeader + "tetrahedra 0\nEnd\n", kReadMedit3, 3, "case-sensitive: Tetrahedra");
  expect_parse_error(kHeader + "Foo 3\nEnd\n", kReadMedit3, 3, "unknown keyword 'Foo'");
  expect_parse_error(kHeader + "End\nVertices 0\n", kReadMedit3, 4, "text after End");
}

// --- Medit 3D: feature and attribute sections, read, checked and skipped with a note -------------

// Every skipped section, Ridges before the Edges it numbers; the same mesh as kSkippedBare.
const std::string kSkippedFull = kTetVertices +  // lines 1-7
                                 "Ridges 1\n2\n"
                                 "Edges 2\n1 2 5\n2 3 6\n"
                                 "Triangles 1\n1 2 3 7\n"
                                 "Tetrahedra 1\n1 2 3 4 8\n"
                                 "Corners\n2\n1\n4\n"
                                 "RequiredVertices 1\n3\n"
                                 "RequiredEdges 2\n1\n2\n"
                                 "RequiredTriangles 1\n1\n"
                                 "RequiredQuadrilaterals 0\n"
                                 "Normals 2\n0 0 1\n0.5 -0.5 0.7071\n"
                                 "NormalAtVertices 2\n1 2\n4 1\n"
                                 "Tangents 1\n1 0 0\n"
                                 "TangentAtVertices 1\n2 1\n"
                                 "Identifier\n\"a cube, corner\"\n"
                                 "Geometry \"cube.mesh\"\n"
                                 "End\n";
const std::string kSkippedBare = kTetVertices + "Edges 2\n1 2 5\n2 3 6\nTriangles 1\n1 2 3 7\nTetrahedra 1\n1 2 3 4 8\nEnd\n";

bool has_note(const std::vector<std::string>& notes, const std::string& text) {
  return std::any_of(notes.begin(), notes.end(), [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

TEST(Medit3Skipped, EverySectionReadCheckedAndNamedInANote) {
  std::istringstream full(kSkippedFull), bare(kSkippedBare);
  std::vector<std::string> notes, bare_notes;
  const MeshData3 m = read_medit3(full, "input.txt", &notes);
  expect_same_mesh(m, read_medit3(bare, "input.txt", &bare_notes));
  EXPECT_TRUE(bare_notes.empty());
  ASSERT_EQ(notes.size(), 12u);
  EXPECT_EQ(notes[0], "section Ridges skipped (1 entry from line 8: ridge edges)");
  for (const char* text : {"section Corners skipped (2 entries from line 17", "section RequiredVertices skipped (1 entry",
                           "section RequiredEdges skipped (2 entries", "section RequiredTriangles skipped (1 entry",
                           "section RequiredQuadrilaterals skipped (0 entries", "section Normals skipped (2 entries",
                           "section NormalAtVertices skipped (2 entries", "section Tangents skipped (1 entry",
                           "section TangentAtVertices skipped (1 entry", "section Identifier skipped",
                           "section Geometry skipped"}) {
    EXPECT_TRUE(has_note(notes, text)) << text;
  }
}

TEST(Medit3Skipped, WithoutASinkTheNotesAreWarningsOnStderr) {
  std::istringstream full(kSkippedFull);
  std::ostringstream err;
  std::streambuf* old = std::cerr.rdbuf(err.rdbuf());
  read_medit3(full, "input.txt");
  std::cerr.rdbuf(old);
  EXPECT_NE(err.str().find("warning: input.txt: section Corners skipped (2 entries"), std::string::npos) << err.str();
}

TEST(Medit3Skipped, SurfaceReaderSkipsThemToo) {
  std::istringstream in(kHeader + "Vertices 4\n0 0 0 0\n1 0 0 0\n1 1 0 0\n0 1 0 0\nQuadrilaterals 1\n1 2 3 4 1\n"
                                  "RequiredQuadrilaterals 1\n1\nCorners 1\n4\nEnd\n");
  std::vector<std::string> notes;
  const Plc3 plc = read_medit3_surface(in, "input.txt", &notes);
  EXPECT_EQ(plc.facets.size(), 1u);
  EXPECT_EQ(notes.size(), 2u);
}

TEST(Medit3Skipped, MalformedCountsAndNumbersNameTheLine) {
  // kTetVertices is lines 1-7.
  expect_parse_error(kTetVertices + "Corners 3\n1\n2\nEnd\n", kReadMedit3, 11, "Corners count is 3 but only 2 entries");
  expect_parse_error(kTetVertices + "Corners 1\n1\n2\nEnd\n", kReadMedit3, 10, "more entries than the section's count");
  expect_parse_error(kTetVertices + "Corners 2\n1\n5\nEnd\n", kReadMedit3, 10,
                     "Corners entry 2: vertex number 5 out of range 1..4");
  expect_parse_error(kTetVertices + "RequiredVertices 1\n0\nEnd\n", kReadMedit3, 9, "not positive");
  expect_parse_error(kTetVertices + "Corners\nEnd\n", kReadMedit3, 8, "missing count after Corners");
  expect_parse_error(kTetVertices + "Corners -1\nEnd\n", kReadMedit3, 8, "Corners count");
  expect_parse_error(kTetVertices + "Corners 1\n1 2\nEnd\n", kReadMedit3, 9, "trailing");
  expect_parse_error(kTetVertices + "Corners 1\n1\nCorners 0\nEnd\n", kReadMedit3, 10, "second Corners section");
  // Numbers into Edges and Triangles are checked at End, at the line of the largest.
  expect_parse_error(kTetVertices + "Ridges 2\n1\n3\nEdges 2\n1 2 0\n2 3 0\nEnd\n", kReadMedit3, 10,
                     "Ridges entry 2: edge number 3 out of range 1..2");
  expect_parse_error(kTetVertices + "RequiredTriangles 1\n1\nEnd\n", kReadMedit3, 9, "triangle number 1 out of range");
  expect_parse_error(kTetVertices + "Normals 1\n0 0 1\nNormalAtVertices 1\n4 2\nEnd\n", kReadMedit3, 11,
                     "NormalAtVertices entry 1: normal number 2 out of range 1..1");
  expect_parse_error(kTetVertices + "TangentAtVertices 1\n9 1\nTangents 1\n1 0 0\nEnd\n", kReadMedit3, 9,
                     "vertex number 9 out of range 1..4");
  expect_parse_error(kTetVertices + "Normals 1\n0 1\nEnd\n", kReadMedit3, 9, "expected 3 fields, found 2");
  expect_parse_error(kTetVertices + "Tangents 1\n0 nan 1\nEnd\n", kReadMedit3, 9, "not finite");
  expect_parse_error(kTetVertices + "Identifier cube\nEnd\n", kReadMedit3, 8, "quoted string");
  expect_parse_error(kTetVertices + "Geometry\nEnd\n", kReadMedit3, 8, "missing string after Geometry");
}

TEST(Medit3Skipped, ElementsTheMeshCannotHoldStayRefused) {
  for (const char* kw : {"Hexahedra", "Prisms", "Pyramids", "Quadrilaterals", "TetrahedraP2", "EdgesP2"}) {
    expect_parse_error(kTetVertices + kw + " 0\nEnd\n", kReadMedit3, 8,
                       std::string("'").append(kw).append("' is not supported by the 3D reader"));
  }
}

// TetGen's own Medit output (-g) carries Corners and Edges besides its tetrahedra.
TEST(Medit3Skipped, ReadsTetGensOutputLikeItsNodeAndEle) {
  if (std::system("command -v tetgen > /dev/null 2>&1") != 0) GTEST_SKIP() << "tetgen is not installed";
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("dtlab_medit3_tetgen_" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(std::string(DTLAB_SOURCE_DIR) + "/data/quad_cube.off", dir / "quad_cube.off",
                             std::filesystem::copy_options::overwrite_existing);
  const std::string command = "cd '" + dir.string() + "' && tetgen -pq1.414 -g quad_cube.off > tetgen.log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::vector<std::string> notes;
  const MeshData3 medit = read_medit3((dir / "quad_cube.1.mesh").string(), &notes);
  const MeshData3 tetgen = read_tetgen_mesh((dir / "quad_cube.1").string());
  EXPECT_EQ(medit.vertices.size(), tetgen.vertices.size());
  EXPECT_EQ(medit.tetrahedra.size(), tetgen.tetrahedra.size());
  // The .mesh lists every face, boundary ones with their marker and interior ones with 0; the
  // .face only the boundary.
  EXPECT_EQ(static_cast<std::size_t>(std::count_if(medit.triangle_refs.begin(), medit.triangle_refs.end(),
                                                   [](int r) { return r != 0; })),
            tetgen.triangles.size());
  EXPECT_GT(medit.tetrahedra.size(), 0u);
  auto sorted = [](std::vector<std::array<std::uint32_t, 4>> tets) {
    for (auto& t : tets) std::sort(t.begin(), t.end());
    std::sort(tets.begin(), tets.end());
    return tets;
  };
  EXPECT_EQ(sorted(medit.tetrahedra), sorted(tetgen.tetrahedra));
  EXPECT_TRUE(has_note(notes, "section Corners skipped (")) << (notes.empty() ? "no notes" : notes[0]);
  std::filesystem::remove_all(dir);
}

// --- TetGen .node / .ele / .face ---------------------------------------------------------------

const auto kReadNode = [](std::istream& in) { read_tetgen_node(in, "input.txt"); };

// Four points numbered from 1 (a positive tetrahedron 1 2 3 4) and a fifth above the others.
TetGenNodes five_nodes(int first_index = 1) {
  std::istringstream in("5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n");
  TetGenNodes nodes = read_tetgen_node(in, "nodes");
  nodes.first_index = first_index;
  return nodes;
}

void read_ele_of_five(std::istream& in) { read_tetgen_ele(in, "input.txt", five_nodes()); }
void read_face_of_five(std::istream& in) { read_tetgen_face(in, "input.txt", five_nodes()); }

TEST(TetGenFormat, NodeRoundTripWithAttributesAndMarkers) {
  for (int first : {0, 1}) {
    TetGenNodes nodes = to_tetgen_nodes(sample_mesh());
    nodes.attribute_count = 2;
    for (std::size_t i = 0; i < 2 * nodes.points.size(); ++i) nodes.attributes.push_back(1.0 / (3.0 + i));
    nodes.first_index = first;
    std::stringstream s;
    write_tetgen_node(s, nodes);
    const TetGenNodes back = read_tetgen_node(s, "memory");
    expect_same_points(back.points, nodes.points);
    EXPECT_EQ(back.attributes, nodes.attributes);
    EXPECT_TRUE(back.has_markers);
    EXPECT_EQ(back.markers, nodes.markers);
    EXPECT_EQ(back.first_index, first);
  }
}

TEST(TetGenFormat, EleAndFaceRoundTripFourAndTenNodes) {
  TetGenNodes nodes = five_nodes();
  for (int first : {0, 1}) {
    nodes.first_index = first;
    TetGenElements e;
    e.tetrahedra = {{0, 1, 2, 3}, {1, 2, 3, 4}};
    ASSERT_EQ(orient3d(nodes.points[1], nodes.points[2], nodes.points[3], nodes.points[4]), Sign::Positive);
    e.attribute_count = 1;
    e.attributes = {3.5, -1.0};
    e.first_index = 1 - first;
    e.vertex_first_index = first;
    for (bool ten : {false, true}) {
      e.midside.clear();
      if (ten) e.midside = {{4, 4, 4, 4, 4, 4}, {0, 1, 2, 3, 0, 1}};
      std::stringstream s;
      write_tetgen_ele(s, e, nodes.points.size());
      const TetGenElements back = read_tetgen_ele(s, "memory", nodes);
      EXPECT_EQ(back.tetrahedra, e.tetrahedra);
      EXPECT_EQ(back.midside, e.midside);
      EXPECT_EQ(back.attributes, e.attributes);
      EXPECT_EQ(back.orientation, Sign::Positive);
      EXPECT_EQ(back.first_index, e.first_index);
      EXPECT_EQ(back.vertex_first_index, first);
      if (ten) {
        EXPECT_THROW(to_mesh_data3(nodes, back), InputError);
      }
    }
    TetGenFaces f;
    f.triangles = {{0, 1, 2}, {4, 3, 2}};
    f.has_markers = true;
    f.markers = {-7, 8};
    f.vertex_first_index = first;
    std::stringstream s;
    write_tetgen_face(s, f, nodes.points.size());
    const TetGenFaces back = read_tetgen_face(s, "memory", nodes);
    EXPECT_EQ(back.triangles, f.triangles);
    EXPECT_EQ(back.markers, f.markers);
  }
}

TEST(TetGenFormat, MeshRoundTripThroughFiles) {
  MeshData3 m = sample_mesh();
  m.edges.clear();  // .node/.ele/.face carry no edges
  m.edge_refs.clear();
  const std::string base = temp_path("round").string();
  write_tetgen_mesh(base, m);
  expect_same_mesh(read_tetgen_mesh(base), m);

  // Without a .face file there are no triangles.
  std::filesystem::remove(base + ".face");
  const MeshData3 no_faces = read_tetgen_mesh(base);
  EXPECT_TRUE(no_faces.triangles.empty());
  EXPECT_EQ(no_faces.tetrahedra, m.tetrahedra);
}

TEST(TetGenFormat, NegativelyOrientedFilesComeOutPositive) {
  // The same mesh written with every tetrahedron reversed (TetGen's -R): n3 and n4 swapped back.
  const MeshData3 m = sample_mesh();
  TetGenNodes nodes = to_tetgen_nodes(m);
  TetGenElements reversed = to_tetgen_elements(m);
  for (auto& t : reversed.tetrahedra) std::swap(t[0], t[1]);
  std::stringstream s;
  write_tetgen_ele(s, reversed, nodes.points.size());
  const TetGenElements back = read_tetgen_ele(s, "memory", nodes);
  EXPECT_EQ(back.orientation, Sign::Negative);
  EXPECT_EQ(back.tetrahedra, reversed.tetrahedra);  // the raw record keeps the file's order
  const MeshData3 converted = to_mesh_data3(nodes, back);
  ASSERT_EQ(converted.tetrahedra.size(), m.tetrahedra.size());
  for (std::size_t i = 0; i < m.tetrahedra.size(); ++i) {
    const auto& t = converted.tetrahedra[i];
    EXPECT_TRUE(positive(converted, t)) << i;
    EXPECT_EQ((std::array<std::uint32_t, 4>{m.tetrahedra[i][1], m.tetrahedra[i][0], m.tetrahedra[i][3],
                                            m.tetrahedra[i][2]}),
              t);
  }
  EXPECT_EQ(converted.tetrahedron_refs, m.tetrahedron_refs);
}

TEST(TetGenFormat, HeaderDefaultsZeroBasedAndNonIntegralAttributes) {
  std::istringstream node("# TetGen's defaults: 3D, no attributes, no markers\n4\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
  const TetGenNodes nodes = read_tetgen_node(node, "input.txt");
  EXPECT_EQ(nodes.first_index, 0);
  EXPECT_FALSE(nodes.has_markers);
  std::istringstream ele("1\n0 0 1 2 3\n");
  const TetGenElements e = read_tetgen_ele(ele, "input.txt", nodes);
  EXPECT_EQ(e.tetrahedra, (std::vector<std::array<std::uint32_t, 4>>{{0, 1, 2, 3}}));
  std::istringstream face("1\n0 0 1 2\n");
  const TetGenFaces f = read_tetgen_face(face, "input.txt", nodes);
  const MeshData3 m = to_mesh_data3(nodes, e, &f);
  EXPECT_EQ(m.vertex_refs, (std::vector<int>{0, 0, 0, 0}));
  EXPECT_EQ(m.tetrahedron_refs, (std::vector<int>{0}));
  EXPECT_EQ(m.triangle_refs, (std::vector<int>{0}));

  std::istringstream attr("1 4 1\n0 0 1 2 3 0.5\n");
  EXPECT_EQ(to_mesh_data3(nodes, read_tetgen_ele(attr, "input.txt", nodes)).tetrahedron_refs, (std::vector<int>{0}));
  std::istringstream region("1 4 2\n0 0 1 2 3 -12 0.5\n");
  EXPECT_EQ(to_mesh_data3(nodes, read_tetgen_ele(region, "input.txt", nodes)).tetrahedron_refs,
            (std::vector<int>{-12}));
}

TEST(TetGenFormat, WritersRefuseBadData) {
  std::stringstream s;
  TetGenElements e;
  e.tetrahedra = {{0, 1, 2, 5}};
  EXPECT_THROW(write_tetgen_ele(s, e, 5), InputError);
  e.tetrahedra = {{0, 1, 2, 3}};
  e.attribute_count = 1;
  EXPECT_THROW(write_tetgen_ele(s, e, 5), InputError);
  TetGenFaces f;
  f.triangles = {{0, 1, 9}};
  EXPECT_THROW(write_tetgen_face(s, f, 5), InputError);
  f.triangles = {{0, 1, 2}};
  f.has_markers = true;
  EXPECT_THROW(write_tetgen_face(s, f, 5), InputError);
  TetGenNodes n = five_nodes();
  n.first_index = 2;
  EXPECT_THROW(write_tetgen_node(s, n), InputError);
}

TEST(TetGenMalformed, NodeFile) {
  expect_parse_error("", kReadNode, 1, "missing the header");
  expect_parse_error("3 2 0 0\n", kReadNode, 1, "must be 3D");
  expect_parse_error("3 3 0 2\n", kReadNode, 1, "not 0 or 1");
  expect_parse_error("3 3 0 0 1\n", kReadNode, 1, "trailing");
  expect_parse_error("2 3 0 0\n1 0 0 0\n", kReadNode, 2, "file ends after 1 of 2 points");
  expect_parse_error("2 3 0 0\n1 0 0 0\n1 1 1 1\n", kReadNode, 3, "expected 2");
  expect_parse_error("1 3 0 0\n2 0 0 0\n", kReadNode, 2, "first one must be 0 or 1");
  expect_parse_error("1 3 0 0\n1 0 0\n", kReadNode, 2, "expected 4 fields, found 3");
  expect_parse_error("1 3 1 1\n1 0 0 0 0.5\n", kReadNode, 2, "expected 6 fields, found 5");
  expect_parse_error("1 3 0 1\n1 0 0 0 x\n", kReadNode, 2, "not an integer");
  expect_parse_error("1 3 0 0\n1 0 0 1e-320\n", kReadNode, 2, "point 1 of 1 z is too small");
  expect_parse_error("1 3 0 0\n1 0 0 0\n2 0 0 0\n", kReadNode, 3, "more lines than");
}

TEST(TetGenMalformed, EleFile) {
  expect_parse_error("", read_ele_of_five, 1, "missing the header");
  expect_parse_error("1 6 0\n", read_ele_of_five, 1, "not 4 or 10");
  expect_parse_error("1 4 0 0\n", read_ele_of_five, 1, "trailing");
  expect_parse_error("1 4 0\n1 1 2 3 6\n", read_ele_of_five, 2, "vertex number 6 out of range 1..5");
  expect_parse_error("1 4 0\n1 0 2 3 4\n", read_ele_of_five, 2, "vertex number 0 out of range 1..5");
  expect_parse_error("1 4 0\n1 1 2 3\n", read_ele_of_five, 2, "expected 5 fields, found 4");
  expect_parse_error("1 4 1\n1 1 2 3 4\n", read_ele_of_five, 2, "expected 6 fields, found 5");
  expect_parse_error("1 10 0\n1 1 2 3 4 5 5 5 5 5\n", read_ele_of_five, 2, "expected 11 fields, found 10");
  expect_parse_error("2 4 0\n1 1 2 3 4\n", read_ele_of_five, 2, "file ends after 1 of 2 tetrahedra");
  expect_parse_error("1 4 0\n1 1 2 3 4\n2 1 2 3 4\n", read_ele_of_five, 3, "more lines than");
  expect_parse_error("1 4 1\n1 1 2 3 4 nan\n", read_ele_of_five, 2, "attribute 1 is not finite");
}

TEST(TetGenMalformed, EleOrientation) {
  expect_parse_error("1 4 0\n1 1 2 3 3\n", read_ele_of_five, 2, "flat");
  expect_parse_error("2 4 0\n1 1 2 3 4\n2 1 2 4 3\n", read_ele_of_five, 3,
                     "tetrahedron 2 of 2 is negatively oriented, but the first tetrahedron is positively oriented");
  expect_parse_error("2 4 0\n1 1 2 4 3\n2 2 3 4 5\n", read_ele_of_five, 3, "positively oriented, but the first");
  expect_parse_error("2 4 0\n1 1 2 3 4\n2 2 3 4 2\n", read_ele_of_five, 3, "flat");
}

TEST(TetGenMalformed, FaceFile) {
  expect_parse_error("", read_face_of_five, 1, "missing the header");
  expect_parse_error("1 2\n", read_face_of_five, 1, "not 0 or 1");
  expect_parse_error("1 0 0\n", read_face_of_five, 1, "trailing");
  expect_parse_error("1 1\n1 1 2 3\n", read_face_of_five, 2, "expected 5 fields, found 4");
  expect_parse_error("1 1\n1 1 2 3 1 7 8\n", read_face_of_five, 2, "trailing text '7'");
  expect_parse_error("1 0\n1 1 2 6\n", read_face_of_five, 2, "face 1 of 1: vertex number 6 out of range 1..5");
  expect_parse_error("2 0\n1 1 2 3\n", read_face_of_five, 2, "file ends after 1 of 2 faces");
  expect_parse_error("1 0\n1 1 2 3\n# end\n2 1 2 3\n", read_face_of_five, 4, "more lines than");
}

TEST(TetGenMalformed, MissingFilesAreParseErrors) {
  const std::string base = temp_path("missing_parts").string();
  std::filesystem::remove(base + ".node");
  EXPECT_THROW(read_tetgen_mesh(base), ParseError);
  {
    std::ofstream(base + ".node") << "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  }
  std::filesystem::remove(base + ".ele");
  try {
    read_tetgen_mesh(base);
    ADD_FAILURE() << "no ParseError without a .ele";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), base + ".ele");
  }
}

}  // namespace
}  // namespace dtlab
