// The surface readers (OFF, STL ASCII and binary, TetGen .poly/.smesh, Medit, read_surface):
// round trips keep every bit, STL encoding is told by the size rule, STL vertices merge only when
// bitwise identical, mesh/io's own fan split of polygons (triangulate_plc_facets) takes planar
// strictly convex ones only (decided exactly), read_surface carries OFF polygons and Medit
// Quadrilaterals as polygon facets named as their files number them, every malformed input is a
// ParseError at the right line (or byte offset), and real OFF and STL surfaces from Debian's CGAL
// data read as closed or open surfaces (or polygon facets) as they should.
#include <bit>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit3.hpp"
#include "mesh/io/obj_format.hpp"
#include "mesh/io/off_format.hpp"
#include "mesh/io/stl_format.hpp"
#include "mesh/io/surface_input.hpp"
#include "mesh/io/tetgen_poly.hpp"

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

std::filesystem::path temp_dir() {
  const auto dir = std::filesystem::temp_directory_path() / "dtlab_surface_io_test";
  std::filesystem::create_directories(dir);
  return dir;
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
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

template <class F>
void expect_input_error(F&& f, const std::string& what, std::vector<std::uint64_t> items = {}) {
  try {
    f();
    ADD_FAILURE() << "no InputError (expected '" << what << "')";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << "message '" << e.what() << "' lacks '" << what << "'";
    if (!items.empty()) {
      EXPECT_EQ(e.items(), items) << e.what();
    }
  }
}

// A tetrahedron's surface with coordinates that a careless writer would not bring back.
MeshData3 awkward_tetrahedron() {
  MeshData3 m;
  m.vertices = {{0.1, -0.0, 1.0 / 3.0},
                {std::nextafter(1.0, 2.0), 1e9 + 0.123456789, -2.0 / 3.0},
                {kMinCoordinateMagnitude, -kMaxCoordinateMagnitude, 123456789012345678.0},
                {2.2250738585072014e-18, std::nextafter(kMinCoordinateMagnitude, 1.0), 7.0}};
  m.vertex_refs = {0, 0, 0, 0};
  m.triangles = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  m.triangle_refs = {0, 0, 0, 0};
  return m;
}

// Every undirected edge and how many triangles use it.
std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_uses(const MeshData3& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const auto& t : m.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  }
  return uses;
}

bool is_closed(const MeshData3& m) {
  for (const auto& [edge, n] : edge_uses(m)) {
    if (n != 2) return false;
  }
  return !m.triangles.empty();
}

// --- OFF -------------------------------------------------------------------------------------------

const auto kReadOff = [](std::istream& in) { read_off(in, "input.txt"); };

TEST(Off, RoundTripKeepsEveryBit) {
  const MeshData3 m = awkward_tetrahedron();
  std::stringstream text;
  write_off(text, m);
  const MeshData3 back = read_off(text, "rewritten.off");
  expect_same_points(back.vertices, m.vertices);
  EXPECT_EQ(back, m);
}

TEST(Off, ReadsPrefixedHeadersColoursCommentsAndCountsOnTheHeaderLine) {
  const std::string text =
      "# comment\nCOFF 4 2 0\n"
      "0 0 0 0.9 0 0\n1 0 0 0 0 0.9 1\n0 1 0 1 1 1\n"
      "0 0 1 0 0 0 # colour with 3 numbers\n"
      "3 0 1 2 0.9 0 0\n3 0 3 1 7\n";
  std::istringstream in(text);
  const MeshData3 m = read_off(in, "input.txt");
  ASSERT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.vertices[3], (Vec3{0, 0, 1}));
  EXPECT_EQ(m.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {0, 3, 1}}));
  EXPECT_EQ(m.triangle_refs, (std::vector<int>{0, 0}));

  std::istringstream noff("STCNOFF\n1 0 0\n1 2 3  0 0 1  0.5 0.5 0.5  0.25 0.75\n");
  EXPECT_EQ(read_off(noff, "input.txt").vertices, (std::vector<Vec3>{{1, 2, 3}}));
}

TEST(Off, PolygonIsRefusedByName) {
  expect_parse_error("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n", kReadOff, 7, "face 1 of 1 has 4 vertices: a polygon");
  expect_parse_error("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n", kReadOff, 7, "read_off_surface");
}

TEST(Off, MalformedInputIsAParseErrorAtItsLine) {
  const std::string v3 = "0 0 0\n1 0 0\n0 1 0\n";  // lines 3-5 after "OFF\n3 1 0\n"
  struct Case {
    std::string text;
    std::uint64_t line;
    std::string what;
  };
  const std::vector<Case> cases = {
      {"", 1, "empty file"},
      {"\n# only a comment\n", 1, "empty file"},
      {"3 1 0\n" + v3, 1, "found the number '3'"},
      {"PLY\n", 1, "expected the OFF header"},
      {"4OFF\n", 1, "4D"},
      {"nOFF\n", 1, "nOFF"},
      {"XOFF\n", 1, "unknown OFF variant"},
      {"OFF BINARY\n", 1, "binary OFF"},
      {"OFF\n", 1, "file ends before the counts"},
      {"OFF\n3 1\n", 2, "expected 3 fields"},
      {"OFF\n-3 1 0\n", 2, "vertex count is negative"},
      {"OFF\n3 1 x\n", 2, "edge count is not an integer"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n", 4, "file ends after 2 of 3 vertices"},
      {"OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", 4, "vertex 2 of 3: expected 3 fields"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0 5\n0 1 0\n3 0 1 2\n", 4, "trailing text '5'"},
      {"OFF\n3 1 0\n0 0 nan\n1 0 0\n0 1 0\n3 0 1 2\n", 3, "vertex 1 of 3 z is not finite"},
      {"OFF\n3 1 0\n0 0 1e300\n1 0 0\n0 1 0\n3 0 1 2\n", 3, "vertex 1 of 3 z is too large"},
      {"OFF\n3 1 0\n0 0 1e-300\n1 0 0\n0 1 0\n3 0 1 2\n", 3, "too small"},
      {"OFF\n3 1 0\n" + v3, 5, "file ends after 0 of 1 faces"},
      {"OFF\n3 1 0\n" + v3 + "2 0 1\n", 6, "face 1 of 1 has 2 vertices"},
      {"OFF\n3 1 0\n" + v3 + "3 0 1\n", 6, "expected 3 vertex numbers, found 2"},
      {"OFF\n3 1 0\n" + v3 + "3 0 1 3\n", 6, "face 1 of 1: vertex number 3 out of range 0..2"},
      {"OFF\n3 1 0\n" + v3 + "3 0 1 -1\n", 6, "vertex number -1 out of range"},
      {"OFF\n3 1 0\n" + v3 + "3 0 1 2 0.5 0.5\n", 6, "2 numbers after the vertex numbers"},
      {"OFF\n3 1 0\n" + v3 + "3 0 1 2 red\n", 6, "colour is not a number"},
      {"OFF\n3 1 0\n" + v3 + "3 0 1 2\n3 0 1 2\n", 7, "more lines than the header's 1 faces"},
      {"COFF\n3 1 0\n0 0 0 1 1\n1 0 0\n0 1 0\n3 0 1 2\n", 3, "expected 6 fields, found 5"},
  };
  for (const Case& c : cases) expect_parse_error(c.text, kReadOff, c.line, c.what);
}

// Issue 42, item 7: the OFF reader said "vertex 0" and "face 0" beside 1-based line numbers. It
// counts vertices and faces from 1 now, "vertex 3 of 3", as the Medit, poly and TetGen readers
// do; a vertex number inside a face is quoted as the file writes it, from 0, with its range.
TEST(Off, MessagesNumberVerticesAndFacesFromOne) {
  const std::string head = "OFF\n3 2 0\n0 0 0\n1 0 0\n";
  expect_parse_error(head + "0 1 inf\n3 0 1 2\n3 0 2 1\n", kReadOff, 5, "vertex 3 of 3 z is not finite");
  expect_parse_error(head + "0 1 0\n3 0 1 2\n3 0 2\n", kReadOff, 7, "face 2 of 2: expected 3 vertex numbers");
  expect_parse_error(head + "0 1 0\n3 0 1 2\n3 0 2 3\n", kReadOff, 7, "face 2 of 2: vertex number 3 out of range 0..2");
}

TEST(Off, WriterRefusesWhatOffCannotHold) {
  MeshData3 m = awkward_tetrahedron();
  m.edges = {{0, 1}};
  std::ostringstream out;
  expect_input_error([&] { write_off(out, m); }, "OFF holds vertices and triangles only");
  m.edges.clear();
  m.triangles.push_back({0, 1, 9});
  expect_input_error([&] { write_off(out, m); }, "triangle 4: vertex 9 out of range", {4});
}

// --- STL -------------------------------------------------------------------------------------------

const auto kReadStl = [](std::istream& in) { read_stl(in, "input.txt"); };

std::string ascii_facet(const std::string& a, const std::string& b, const std::string& c,
                        const std::string& normal = "0 0 1") {
  return " facet normal " + normal + "\n  outer loop\n   vertex " + a + "\n   vertex " + b + "\n   vertex " + c +
         "\n  endloop\n endfacet\n";
}

// A binary STL: `header` padded to 80 bytes, then the facets' float32 coordinates.
std::string binary_stl(const std::string& header, const std::vector<std::array<float, 9>>& facets) {
  std::string bytes = header;
  bytes.resize(80, ' ');
  auto u32 = [&](std::uint32_t v) {
    for (int k = 0; k < 4; ++k) bytes += static_cast<char>((v >> (8 * k)) & 0xff);
  };
  u32(static_cast<std::uint32_t>(facets.size()));
  for (const auto& f : facets) {
    for (int k = 0; k < 3; ++k) u32(0);
    for (float c : f) u32(std::bit_cast<std::uint32_t>(c));
    bytes += std::string(2, '\0');
  }
  return bytes;
}

TEST(Stl, AsciiRoundTripKeepsEveryBit) {
  const MeshData3 m = awkward_tetrahedron();
  std::stringstream text;
  write_stl(text, m, StlEncoding::Ascii);
  EXPECT_EQ(detect_stl_encoding(text.str()), StlEncoding::Ascii);
  const MeshData3 back = read_stl(text, "rewritten.stl");
  expect_same_points(back.vertices, m.vertices);
  EXPECT_EQ(back, m);
}

TEST(Stl, BinaryRoundTripKeepsEveryBitAndRefusesNonFloats) {
  MeshData3 m;
  m.vertices = {{0.1f, -0.0f, 1e-30f}, {3.0e38f, 1.0f, 2.5f}, {-7.0f, 0.0f, std::nextafter(1.0f, 2.0f)}, {1, 1, 1}};
  m.vertex_refs = {0, 0, 0, 0};
  m.triangles = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  m.triangle_refs = {0, 0, 0, 0};
  std::stringstream bytes;
  write_stl(bytes, m, StlEncoding::Binary);
  EXPECT_EQ(bytes.str().size(), 84u + 50u * 4u);
  EXPECT_EQ(detect_stl_encoding(bytes.str()), StlEncoding::Binary);
  const MeshData3 back = read_stl(bytes, "rewritten.stl");
  expect_same_points(back.vertices, m.vertices);
  EXPECT_EQ(back, m);

  m.vertices[3].y = 0.1;  // not a float
  std::ostringstream out;
  expect_input_error([&] { write_stl(out, m, StlEncoding::Binary); }, "vertex 3: coordinate 0.1 is not exactly a float32",
                     {3});
  m.vertices[3].y = 1e300;
  expect_input_error([&] { write_stl(out, m, StlEncoding::Binary); }, "not exactly a float32", {3});
}

TEST(Stl, EncodingIsToldBySizeNotBySolidPrefix) {
  const std::array<float, 9> tri = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  // A binary file whose header begins with "solid", as many writers do.
  std::string bytes = binary_stl("solid made by a CAD tool", {tri, tri});
  EXPECT_EQ(detect_stl_encoding(bytes), StlEncoding::Binary);
  std::istringstream in(bytes);
  const MeshData3 m = read_stl(in, "input.txt");
  EXPECT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.triangles.size(), 2u);
  // One byte more or less: no longer binary; it begins with "solid", but holds NUL bytes.
  expect_parse_error(bytes + " ", kReadStl, 1, "as a binary STL its size would be 84 + 50 x 2 = 184 bytes");
  expect_parse_error(bytes.substr(0, bytes.size() - 1), kReadStl, 1, "a NUL byte at byte 81");
  // Neither rule: not "solid", wrong size; short files too.
  expect_parse_error(binary_stl("binary", {tri}) + "xx", kReadStl, 80, "does not begin with 'solid'");
  expect_parse_error("hello", kReadStl, 1, "too short for a binary STL (5 bytes");
  expect_parse_error("", kReadStl, 1, "empty file");
  // An empty binary file (84 bytes, 0 facets) is a valid empty surface.
  std::istringstream empty(binary_stl("", {}));
  EXPECT_TRUE(read_stl(empty, "input.txt").triangles.empty());
}

TEST(Stl, VerticesMergeOnlyWhenBitwiseIdentical) {
  const std::string text = "solid s\n" + ascii_facet("0 0 0", "1 0 0", "0 1 0") +
                           ascii_facet("1.0 0 0", "0 1.000 0", "+0 0 1") +  // same doubles: merged
                           ascii_facet("-0 0 0", "1 0 0", "0 1 0") +        // -0 is not 0
                           ascii_facet("1 0 0", "1.0000000000000002 0 0", "0 1 0") +  // next double, degenerate
                           "endsolid s\n";
  std::istringstream in(text);
  const MeshData3 m = read_stl(in, "input.txt");
  ASSERT_EQ(m.vertices.size(), 6u);
  EXPECT_EQ(m.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {1, 2, 3}, {4, 1, 2}, {1, 5, 2}}));
  EXPECT_TRUE(std::signbit(m.vertices[4].x));
  EXPECT_EQ(m.vertices[5].x, std::nextafter(1.0, 2.0));

  // Binary: the same rule on float32 values; a degenerate facet is kept.
  const std::string bytes = binary_stl("", {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 0, 0, -0.0f, 0, 0}});
  std::istringstream bin(bytes);
  const MeshData3 b = read_stl(bin, "input.txt");
  EXPECT_EQ(b.vertices.size(), 4u);
  EXPECT_EQ(b.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {0, 0, 3}}));
}

TEST(Stl, AsciiAcceptsSeveralSolidsAnyCaseAndUnparsedNormals) {
  const std::string text = "SOLID one\n" + ascii_facet("0 0 0", "1 0 0", "0 1 0", "nan nan nan") +
                           "ENDSOLID one\nsolid\n  FACET NORMAL 0 0 0\n OUTER LOOP\nVERTEX 0 0 1\nVertex 1 0 0\n"
                           "vertex 0 1 0\n EndLoop\nendfacet\nendsolid\n\n";
  std::istringstream in(text);
  const MeshData3 m = read_stl(in, "input.txt");
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.triangle_refs, (std::vector<int>{0, 1}));
}

TEST(Stl, MalformedAsciiIsAParseErrorAtItsLine) {
  const std::string f = ascii_facet("0 0 0", "1 0 0", "0 1 0");  // lines 2-8 after "solid\n"
  struct Case {
    std::string text;
    std::uint64_t line;
    std::string what;
  };
  const std::vector<Case> cases = {
      {"solid\n", 1, "file ends in solid 0 before its endsolid"},
      {"solid\n" + f, 8, "file ends in solid 0"},
      {"solid\nfacet 0 0 1\n", 2, "expected 'facet normal nx ny nz'"},
      {"solid\nfacet normal 0 0\n", 2, "expected 5 fields"},
      {"solid\nvertex 0 0 0\n", 2, "expected 'facet normal' or 'endsolid'"},
      {"solid\nfacet normal 0 0 1\nouter\n", 3, "expected 2 fields"},
      {"solid\nfacet normal 0 0 1\ninner loop\n", 3, "expected 'outer'"},
      {"solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n", 6,
       "facet 0 has 2 vertices; an STL facet has 3"},
      {"solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\n", 7,
       "facet 0 has more than 3 vertices"},
      {"solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0\n", 5, "facet 0 vertex 2 (vertex x y z)"},
      {"solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 inf\n", 5, "facet 0 vertex 2 z is not finite"},
      {"solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 1e-200\n", 5, "too small"},
      {"solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop x\n", 7,
       "trailing text"},
      {"solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendloop\n", 8,
       "expected 'endfacet'"},
      {"solid\n" + f + "endsolid\nfacet normal 0 0 1\n", 10, "expected 'solid' (the start of solid 1)"},
      {"solid\n" + f + f + "endsolid\nsolid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nendloop\n", 21,
       "facet 2 has 1 vertices"},
  };
  for (const Case& c : cases) expect_parse_error(c.text, kReadStl, c.line, c.what);
}

TEST(Stl, MalformedBinaryIsAParseErrorAtItsByteOffset) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float subnormal = std::numeric_limits<float>::denorm_min();  // 2^-149, below the supported range
  const std::array<float, 9> ok = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  // Facet 1, vertex 3, y: 84 + 50 + 12 + 24 + 4.
  expect_parse_error(binary_stl("", {ok, {0, 0, 0, 1, 0, 0, 0, nan, 0}}), kReadStl, 84 + 50 + 12 + 24 + 4,
                     "at byte 174: facet 1 vertex 3 y is NaN");
  expect_parse_error(binary_stl("", {{0, 0, subnormal, 1, 0, 0, 0, 1, 0}}), kReadStl, 84 + 12 + 8, "z is too small");
  expect_parse_error(binary_stl("", {{0, 0, 0, 1, 0, 0, 0, 1, std::numeric_limits<float>::infinity()}}), kReadStl,
                     84 + 12 + 32, "is infinite");
}

// --- TetGen .poly / .smesh ---------------------------------------------------------------------

const auto kReadPoly = [](std::istream& in) { read_tetgen_poly(in, "input.txt"); };
const auto kReadSmesh = [](std::istream& in) { read_tetgen_smesh(in, "input.txt"); };

// A unit cube as six quadrilateral facets with markers 1..6, plus one facet with an isolated
// vertex, a segment and a triangle, and a facet hole (not triangulable, but a valid PLC file).
Plc3 sample_plc() {
  Plc3 plc;
  for (int i = 0; i < 8; ++i) plc.vertices.push_back({0.1 * (i & 1), 0.1 * ((i >> 1) & 1), 0.1 * (i >> 2)});
  plc.vertices.push_back({1.0 / 3.0, -0.0, 1e-40});
  plc.vertex_markers = {1, 2, 3, 4, 5, 6, 7, 8, -9};
  // Corners of each side in cyclic order (x = 0, x = 1, y = 0, y = 1, z = 0, z = 1).
  const std::vector<std::vector<std::uint32_t>> sides = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                                         {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
  for (std::size_t s = 0; s < sides.size(); ++s) plc.facets.push_back({{sides[s]}, {}, static_cast<int>(s) + 1});
  plc.facets.push_back({{{8}, {0, 8}, {0, 1, 8}}, {{0.5, 0.25, -1e9}}, std::numeric_limits<int>::min()});
  plc.holes = {{0.05, 0.05, 0.05}};
  plc.regions = {{{0.01, 0.02, 0.03}, 7.0, 0.5}, {{-1, -1, -1}, -2.5, -1.0}};
  return plc;
}

TEST(TetGenPoly, RoundTripKeepsEveryBit) {
  const Plc3 plc = sample_plc();
  std::stringstream text;
  write_tetgen_poly(text, plc);
  const Plc3 back = read_tetgen_poly(text, "rewritten.poly");
  expect_same_points(back.vertices, plc.vertices);
  EXPECT_EQ(back, plc);
}

TEST(TetGenPoly, SmeshRoundTripAndRefusals) {
  Plc3 plc = sample_plc();
  std::ostringstream refused;
  expect_input_error([&] { write_tetgen_smesh(refused, plc); }, "facet 6 has 3 polygons and 1 holes", {6});
  plc.facets.pop_back();
  std::stringstream text;
  write_tetgen_smesh(text, plc);
  const Plc3 back = read_tetgen_smesh(text, "rewritten.smesh");
  expect_same_points(back.vertices, plc.vertices);
  EXPECT_EQ(back, plc);
}

TEST(TetGenPoly, ReadsTetGenLayouts) {
  // Numbered from 0, no markers, a corner list over two lines, a region without maximum volume,
  // no region part in the second file.
  const std::string smesh =
      "4 3\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n"
      "4 0\n3 0 1 2\n3 0 3\n 1\n3 1 3 2\n3 2 3 0\n"
      "1\n0 0.1 0.1 0.1\n1\n0 0.2 0.2 0.2 5\n";
  std::istringstream in(smesh);
  const Plc3 plc = read_tetgen_smesh(in, "input.txt");
  ASSERT_EQ(plc.facets.size(), 4u);
  EXPECT_EQ(plc.facets[1].polygons, (std::vector<std::vector<std::uint32_t>>{{0, 3, 1}}));
  EXPECT_EQ(plc.vertex_markers, (std::vector<int>{0, 0, 0, 0}));
  ASSERT_EQ(plc.regions.size(), 1u);
  EXPECT_EQ(plc.regions[0].attribute, 5.0);
  EXPECT_EQ(plc.regions[0].max_volume, -1.0);

  const std::string poly =
      "3 3 0 1\n1 0 0 0 4\n2 1 0 0 5\n3 0 1 0 6\n"
      "1 1\n2 1 -3\n3 1 2 3\n2 1 2\n1 0.5 0.5 0\n"
      "0\n";
  std::istringstream p(poly);
  const Plc3 q = read_tetgen_poly(p, "input.txt");
  ASSERT_EQ(q.facets.size(), 1u);
  EXPECT_EQ(q.facets[0].marker, -3);
  EXPECT_EQ(q.facets[0].polygons, (std::vector<std::vector<std::uint32_t>>{{0, 1, 2}, {0, 1}}));
  EXPECT_EQ(q.facets[0].holes, (std::vector<Vec3>{{0.5, 0.5, 0}}));
  EXPECT_EQ(q.vertex_markers, (std::vector<int>{4, 5, 6}));
  EXPECT_TRUE(q.regions.empty());
}

TEST(TetGenPoly, SeparateNodeFile) {
  const auto dir = temp_dir();
  write_text(dir / "separate.node", "4 3 0 1\n1 0 0 0 1\n2 1 0 0 1\n3 0 1 0 2\n4 0 0 1 2\n");
  write_text(dir / "separate.smesh", "0 3 0 0\n4 1\n3 1 2 3 10\n3 1 4 2 11\n3 2 4 3 12\n3 3 4 1 13\n0\n");
  const Plc3 plc = read_tetgen_smesh((dir / "separate.smesh").string());
  EXPECT_EQ(plc.vertices.size(), 4u);
  EXPECT_EQ(plc.vertex_markers, (std::vector<int>{1, 1, 2, 2}));
  EXPECT_EQ(plc.facets[3].polygons[0], (std::vector<std::uint32_t>{2, 3, 0}));
  EXPECT_EQ(plc.facets[3].marker, 13);
  // Without the .node file: the .node reader's error, naming that file.
  write_text(dir / "orphan.poly", "0 3 0 0\n0 0\n0\n");
  try {
    read_tetgen_poly((dir / "orphan.poly").string());
    ADD_FAILURE() << "no ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), (dir / "orphan.node").string());
  }
}

TEST(TetGenPoly, MalformedInputIsAParseErrorAtItsLine) {
  const std::string nodes = "3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n";  // lines 1-4
  struct Case {
    std::string text;
    std::uint64_t line;
    std::string what;
    bool smesh = false;
  };
  const std::vector<Case> cases = {
      {"", 1, "empty file"},
      {"3 2 0 0\n", 1, "a TetGen PLC must be 3D"},
      {"3 3 0 2\n", 1, "boundary marker count is 2"},
      {"3 3 0 0 0\n", 1, "trailing text '0' after 4 fields"},
      {"3 3 0 0\n1 0 0 0\n3 1 0 0\n", 3, "numbered 3, expected 2"},
      {"3 3 0 0\n1 0 0 0\n2 1 0 1e999\n", 3, "out of the range of a double"},
      {"3 3 1 0\n1 0 0 0\n", 2, "expected 5 fields"},
      {nodes, 4, "file ends before the facet list header"},
      {nodes + "1 0 0\n", 5, "more points than the count says?"},
      {nodes + "1 0\n", 5, "file ends after 0 of 1 facets"},
      {nodes + "1 0\n0\n", 6, "facet 1 of 1 has no polygon"},
      {nodes + "1 0\n1 0 5\n", 6, "the facet list header says there are no boundary markers"},
      {nodes + "1 1\n1 0\n", 6, "expected 3 fields"},
      {nodes + "1 0\n1\n", 6, "file ends after 0 of 1 polygons of facet 1 of 1"},
      {nodes + "1 0\n1\n0\n", 7, "polygon 1 of facet 1 of 1 has no corner"},
      {nodes + "1 0\n1\n3 1 2 4\n", 7, "vertex number 4 out of range 1..3"},
      {nodes + "1 0\n1\n3 1 2\n", 7, "file ends in polygon 1 of facet 1 of 1"},
      {nodes + "1 0\n1\n2 1 2 3\n", 7, "trailing text '3'"},
      {nodes + "1 0\n1 1\n3 1 2 3\n", 7, "file ends after 0 of 1 holes of facet 1 of 1"},
      {nodes + "1 0\n1 1\n3 1 2 3\n1 0 0\n", 8, "hole 1 of facet 1 of 1 (<hole #> <x> <y> <z>)"},
      {nodes + "1 0\n1\n3 1 2 3\n", 7, "file ends before the volume hole count"},
      {nodes + "1 0\n1\n3 1 2 3\n3 1 2 3\n", 8, "more facets than the count says?"},
      {nodes + "1 0\n1\n3 1 2 3\n1\n2 0 0 0\n", 9, "numbered 2; the first one must be 0 or 1"},
      {nodes + "1 0\n1\n3 1 2 3\n0\n1\n1 0 0 0\n", 10, "expected 6 fields"},
      {nodes + "1 0\n1\n3 1 2 3\n0\n1\n1 0 0 0 1 2 3\n", 10, "trailing text '3'"},
      {nodes + "1 0\n1\n3 1 2 3\n0\n1\n1 0 0 0 1 2\n2 0 0 0 1 2\n", 11, "text after the last region"},
      {nodes + "1 0\n1\n3 1 2 3\n0\n0 0\n", 9, "alone on its line"},
      {nodes + "1 1\n3 1 2 3\n0\n", 6, "facet 1 of 1: missing boundary marker", true},
      {nodes + "1 0\n3 1 2 3 7\n0\n", 6, "facet 1 of 1: trailing text '7'", true},
      {nodes + "1 1\n3 1 2 3 x\n0\n", 6, "boundary marker is not an integer", true},
  };
  for (const Case& c : cases) expect_parse_error(c.text, c.smesh ? kReadSmesh : kReadPoly, c.line, c.what);
}

// --- Facets to triangles -----------------------------------------------------------------------

TEST(TriangulatePlcFacets, ConvexPlanarPolygonsBecomeFansWithTheirMarkers) {
  Plc3 plc = sample_plc();
  plc.facets.pop_back();
  plc.facets.push_back({{{8}, {0, 8}, {0, 1, 8}}, {}, 42});
  const MeshData3 m = triangulate_plc_facets(plc);
  EXPECT_EQ(m.vertices, plc.vertices);
  EXPECT_EQ(m.vertex_refs, plc.vertex_markers);
  ASSERT_EQ(m.triangles.size(), 13u);
  for (std::size_t f = 0; f < 6; ++f) {
    const auto& q = plc.facets[f].polygons[0];
    EXPECT_EQ(m.triangles[2 * f], (std::array<std::uint32_t, 3>{q[0], q[1], q[2]}));
    EXPECT_EQ(m.triangles[2 * f + 1], (std::array<std::uint32_t, 3>{q[0], q[2], q[3]}));
    EXPECT_EQ(m.triangle_refs[2 * f], static_cast<int>(f) + 1);
  }
  EXPECT_EQ(m.triangles[12], (std::array<std::uint32_t, 3>{0, 1, 8}));
  EXPECT_EQ(m.triangle_refs[12], 42);
  EXPECT_EQ(m.edges, (std::vector<std::array<std::uint32_t, 2>>{{0, 8}}));
  EXPECT_EQ(m.edge_refs, (std::vector<int>{42}));
  EXPECT_TRUE(is_closed(MeshData3{m.vertices, {}, {}, {}, {m.triangles.begin(), m.triangles.begin() + 12}, {}, {}, {}}));
}

TEST(TriangulatePlcFacets, RefusesWhatItCannotSplitExactly) {
  Plc3 plc;
  plc.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}, {2, 0, 0}, {1, 1, 1e-30}, {0.25, 0.75, 0}};
  auto one = [&](std::vector<std::uint32_t> polygon, std::vector<Vec3> holes = {}) {
    Plc3 p = plc;
    p.facets = {PlcFacet3{{{0, 1, 2}}, {}, 0}};
    p.facets.push_back({{std::move(polygon)}, std::move(holes), 9});
    return p;
  };
  expect_input_error([&] { triangulate_plc_facets(one({0, 1, 6, 3})); },
                     "facet 1, polygon 0 (4 corners): corner 3 (vertex 3) is not in the plane", {1});
  expect_input_error([&] { triangulate_plc_facets(one({0, 1, 2, 7, 3})); }, "is not convex (it turns the other way at corner 3)", {1});
  expect_input_error([&] { triangulate_plc_facets(one({0, 1, 5, 2})); }, "corners 0, 1, 2 are collinear", {1});
  expect_input_error([&] { triangulate_plc_facets(one({0, 4, 2, 3})); }, "are collinear", {1});
  expect_input_error([&] { triangulate_plc_facets(one({0, 1, 2, 3}, {{0.5, 0.5, 0}})); },
                     "facet 1 has 1 holes: facet holes are not supported yet", {1});
  expect_input_error([&] { triangulate_plc_facets(one({0, 1, 2, 8})); }, "vertex 8 out of range", {1});
  // A pentagram: every turn has the same sign, but it winds twice.
  Plc3 star;
  for (int k = 0; k < 5; ++k) {
    const double a = 2 * 3.141592653589793 * (2 * k) / 5;
    star.vertices.push_back({std::cos(a), std::sin(a), 1.0});
  }
  star.facets = {{{{0, 1, 2, 3, 4}}, {}, 0}};
  expect_input_error([&] { triangulate_plc_facets(star); }, "winds around more than once", {0});
  // The same points in convex order are split.
  star.facets = {{{{0, 3, 1, 4, 2}}, {}, 0}};
  EXPECT_EQ(triangulate_plc_facets(star).triangles.size(), 3u);
}

// --- Polygon facets: OFF and Medit Quadrilaterals ----------------------------------------------------

TEST(OffSurface, ReadsPolygonsAsFacetsWithTheirColoursSkipped) {
  std::istringstream in("OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 2 0\n5 0 1 4 2 3 0.5 0.5 0.5\n3 0 3 1\n");
  const Plc3 plc = read_off_surface(in, "input.txt");
  ASSERT_EQ(plc.facets.size(), 2u);
  EXPECT_EQ(plc.facets[0].polygons, (std::vector<std::vector<std::uint32_t>>{{0, 1, 4, 2, 3}}));
  EXPECT_EQ(plc.facets[1].polygons, (std::vector<std::vector<std::uint32_t>>{{0, 3, 1}}));
  EXPECT_EQ(plc.facets[0].marker, 0);
  EXPECT_EQ(plc.vertex_markers, std::vector<int>(5, 0));
  const auto read = [](std::istream& s) { read_off_surface(s, "input.txt"); };
  expect_parse_error("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2\n", read, 7, "face 1 of 1: expected 4 vertex numbers, found 3");
  expect_parse_error("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 4\n", read, 7, "vertex number 4 out of range");
  expect_parse_error("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 1 2\n", read, 7, "2 numbers after the vertex numbers");
  expect_parse_error("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 1\n", read, 7, "face 1 of 1 has 2 vertices; a face needs 3");
}

TEST(ObjSurface, ReadsFacesOfEveryCornerFormAndNegativeNumbers) {
  std::istringstream in(
      "# a square and a triangle\nmtllib a.mtl\no square\nv 0 0 0\nv 1 0 0\nv 1 1 0 1\nv 0 1 0 0.5 0.5 0.5\n"
      "vt 0 0\nvn 0 0 1\ns off\nusemtl red\nf 1/1/1 2//1 3/1 4\ng tip\nf -4 -1 5\nv 0.5 0.5 1\nl 1 3 5\np 2\n");
  const Plc3 plc = read_obj_surface(in, "input.txt");
  ASSERT_EQ(plc.vertices.size(), 5u);
  EXPECT_EQ(plc.vertices[4], (Vec3{0.5, 0.5, 1}));
  EXPECT_EQ(plc.vertex_markers, std::vector<int>(5, 0));
  ASSERT_EQ(plc.facets.size(), 4u);
  EXPECT_EQ(plc.facets[0].polygons, (std::vector<std::vector<std::uint32_t>>{{0, 1, 2, 3}}));
  EXPECT_EQ(plc.facets[1].polygons, (std::vector<std::vector<std::uint32_t>>{{0, 3, 4}}));  // 5: given later
  EXPECT_EQ(plc.facets[2].polygons, (std::vector<std::vector<std::uint32_t>>{{0, 2}}));
  EXPECT_EQ(plc.facets[3].polygons, (std::vector<std::vector<std::uint32_t>>{{2, 4}}));
  const auto read = [](std::istream& s) { read_obj_surface(s, "input.txt"); };
  const std::string v3 = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_parse_error(v3 + "f 1 2\n", read, 4, "face 1 has 2 corners; a face needs 3");
  expect_parse_error(v3 + "f 1 2 0\n", read, 4, "face 1: vertex number 0");
  expect_parse_error(v3 + "f 1 2 -4\n", read, 4, "reaches back past the first vertex (3 read so far)");
  expect_parse_error(v3 + "f 1 2 4\nf 1 2 3\n", read, 4, "vertex number 4 out of range 1..3");
  expect_parse_error(v3 + "f 1 2 3/x\n", read, 4, "is not v, v/vt, v//vn or v/vt/vn");
  expect_parse_error(v3 + "f 1 2 3/1/1/1\n", read, 4, "is not v, v/vt, v//vn or v/vt/vn");
  expect_parse_error(v3 + "f 1 2 \\\n3\n", read, 4, "continued with");
  expect_parse_error(v3 + "curv 0 1 1 2\n", read, 4, "free-form geometry ('curv')");
  expect_parse_error(v3 + "vx 1\n", read, 4, "unknown OBJ keyword 'vx'");
  expect_parse_error("v 0 0 0 2\n", read, 1, "w = 2; rational vertices");
  expect_parse_error("v 0 0\n", read, 1, "expected x y z [w] or x y z r g b, found 2 numbers");
  expect_parse_error("v 0 0 nan\n", read, 1, "vertex z");
}

TEST(MeditSurface, ReadsQuadrilateralsAfterTrianglesAndEdgesLast) {
  const std::string text =
      "MeshVersionFormatted 2\nDimension 3\nVertices 5\n0 0 0 1\n1 0 0 2\n1 1 0 3\n0 1 0 4\n0 0 1 5\n"
      "Quadrilaterals 1\n1 2 3 4 9\nTriangles 1\n1 2 5 8\nEdges 1\n1 5 6\nEnd\n";
  std::istringstream in(text);
  const Plc3 plc = read_medit3_surface(in, "input.txt");
  EXPECT_EQ(plc.vertex_markers, (std::vector<int>{1, 2, 3, 4, 5}));
  ASSERT_EQ(plc.facets.size(), 3u);
  EXPECT_EQ(plc.facets[0], (PlcFacet3{{{0, 1, 4}}, {}, 8}));
  EXPECT_EQ(plc.facets[1], (PlcFacet3{{{0, 1, 2, 3}}, {}, 9}));
  EXPECT_EQ(plc.facets[2], (PlcFacet3{{{0, 4}}, {}, 6}));
  // read_medit3 (MeshData3 has no quadrilaterals) still refuses the section by name.
  std::istringstream again(text);
  try {
    read_medit3(again, "input.txt");
    ADD_FAILURE() << "Quadrilaterals accepted by read_medit3";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 9u);
    EXPECT_NE(std::string(e.what()).find("'Quadrilaterals' is not supported by the 3D reader"), std::string::npos)
        << e.what();
  }
  const auto read = [](std::istream& s) { read_medit3_surface(s, "input.txt"); };
  expect_parse_error("MeshVersionFormatted 2\nDimension 3\nVertices 1\n0 0 0 0\nQuadrilaterals 1\n1 1 1 2 0\nEnd\n",
                     read, 6, "vertex number 2 out of range");
  expect_parse_error("MeshVersionFormatted 2\nDimension 3\nVertices 1\n0 0 0 0\nHexahedra 0\nEnd\n", read, 5,
                     "not supported by the 3D surface reader (it keeps Vertices, Edges, Triangles, Quadrilaterals and Tetrahedra)");
}

// --- read_surface ----------------------------------------------------------------------------------

TEST(ReadSurface, ChoosesTheReaderByExtension) {
  const auto dir = temp_dir();
  const MeshData3 tet = awkward_tetrahedron();
  write_off((dir / "tet.off").string(), tet);
  write_stl((dir / "tet.STL").string(), tet, StlEncoding::Ascii);
  MeshData3 with_refs = tet;
  with_refs.triangle_refs = {1, 2, 3, 4};
  with_refs.edges = {{0, 1}};
  with_refs.edge_refs = {5};
  write_medit3((dir / "tet.mesh").string(), with_refs);
  Plc3 plc = sample_plc();
  plc.facets.pop_back();
  write_tetgen_poly((dir / "cube.poly").string(), plc);
  write_tetgen_smesh((dir / "cube.smesh").string(), plc);

  EXPECT_EQ(read_surface((dir / "tet.off").string()).plc, plc_from_triangles(tet));
  EXPECT_EQ(read_surface((dir / "tet.STL").string()).plc, plc_from_triangles(tet));
  const SurfaceInput medit = read_surface((dir / "tet.mesh").string());
  EXPECT_EQ(medit.plc, plc_from_triangles(with_refs));
  EXPECT_EQ(medit.facet_name(3), "triangle 4");
  EXPECT_EQ(medit.facet_name(4), "edge 1");
  EXPECT_EQ(read_surface((dir / "tet.off").string()).facet_name(2), "face 2");
  std::ofstream((dir / "tet.OBJ").string()) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
  const SurfaceInput obj = read_surface((dir / "tet.OBJ").string());
  EXPECT_EQ(obj.plc.facets.size(), 4u);
  EXPECT_EQ(obj.facet_name(3), "facet 4");
  for (const char* name : {"cube.poly", "cube.smesh"}) {
    const SurfaceInput s = read_surface((dir / name).string());
    EXPECT_EQ(s.plc, plc) << name;
    EXPECT_EQ(s.facet_name(0), "facet 1") << name;
    EXPECT_TRUE(is_closed(triangulate_plc_facets(s.plc))) << name;
  }

  MeshData3 volume = tet;
  volume.tetrahedra = {{0, 1, 2, 3}};
  std::ofstream((dir / "volume.mesh").string()) << "MeshVersionFormatted 2\nDimension 3\nVertices 4\n0 0 0 0\n1 0 0 0\n"
                                                   "0 1 0 0\n0 0 1 0\nTetrahedra 1\n1 2 3 4 0\nEnd\n";
  expect_input_error([&] { read_surface((dir / "volume.mesh").string()); }, "1 tetrahedra: a volume mesh");
  expect_input_error([&] { read_surface((dir / "tet.ply").string()); },
                     "unknown surface file extension '.ply'; supported: .off, .obj, .stl, .poly, .smesh, .mesh");
  expect_input_error([&] { read_surface((dir / "tet").string()); }, "extension (none)");
  EXPECT_THROW(read_surface((dir / "missing.off").string()), ParseError);
}

// --- Real data: Debian's CGAL data (libcgal-demo) --------------------------------------------------

const char* const kCgalData = "/usr/share/doc/libcgal-dev/data.tar.gz";

// Extracts data/meshes/<names> into a temporary directory; empty if the archive is absent.
std::filesystem::path extract_cgal_meshes(const std::vector<std::string>& names) {
  if (!std::filesystem::exists(kCgalData)) return {};
  const auto dir = temp_dir() / "cgal";
  std::filesystem::create_directories(dir);
  std::string command = "tar -xzf " + std::string(kCgalData) + " -C " + dir.string();
  for (const std::string& n : names) command += " data/meshes/" + n;
  if (std::system(command.c_str()) != 0) return {};
  return dir / "data" / "meshes";
}

TEST(RealData, CgalOffAndStlSurfaces) {
  const std::vector<std::string> closed = {"tetrahedron.off", "cube.off", "octahedron.off", "icosahedron.off",
                                           "sphere.stl"};
  const std::vector<std::string> open = {"open_cube.off", "triangular_hole.off"};
  const std::vector<std::string> polygons = {"cube_quad.off", "mesh_with_colors.off"};
  std::vector<std::string> all = closed;
  all.insert(all.end(), open.begin(), open.end());
  all.insert(all.end(), polygons.begin(), polygons.end());
  const auto dir = extract_cgal_meshes(all);
  if (dir.empty()) GTEST_SKIP() << kCgalData << " (Debian package libcgal-demo) is absent";

  for (const std::string& name : closed) {
    const MeshData3 m = triangulate_plc_facets(read_surface((dir / name).string()).plc);
    EXPECT_TRUE(is_closed(m)) << name;
    // A closed surface of genus 0: V - E + F = 2, so every vertex was merged where it should be.
    const auto edges = static_cast<std::int64_t>(edge_uses(m).size());
    EXPECT_EQ(static_cast<std::int64_t>(m.vertices.size()) - edges + static_cast<std::int64_t>(m.triangles.size()), 2)
        << name;
  }
  for (const std::string& name : open) {
    const MeshData3 m = triangulate_plc_facets(read_surface((dir / name).string()).plc);
    EXPECT_FALSE(is_closed(m)) << name;
    EXPECT_FALSE(m.triangles.empty()) << name;
  }
  // Quadrilaterals and a pentagon: read_off refuses them by name at their line (lines counted in
  // the files); read_surface carries them as polygon facets.
  for (const auto& [name, line] : std::vector<std::pair<std::string, std::uint64_t>>{{"cube_quad.off", 11},
                                                                                     {"mesh_with_colors.off", 23}}) {
    try {
      read_off((dir / name).string());
      ADD_FAILURE() << name << " was not refused";
    } catch (const ParseError& e) {
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_NE(std::string(e.what()).find("a polygon"), std::string::npos) << e.what();
    }
  }
  const Plc3 cube_quad = read_surface((dir / "cube_quad.off").string()).plc;
  ASSERT_EQ(cube_quad.facets.size(), 6u);
  for (const PlcFacet3& f : cube_quad.facets) EXPECT_EQ(f.polygons, (std::vector<std::vector<std::uint32_t>>{f.polygons[0]}));
  EXPECT_EQ(cube_quad.facets[0].polygons[0], (std::vector<std::uint32_t>{0, 3, 7, 4}));
  const Plc3 colours = read_surface((dir / "mesh_with_colors.off").string()).plc;
  EXPECT_TRUE(std::any_of(colours.facets.begin(), colours.facets.end(),
                          [](const PlcFacet3& f) { return f.polygons[0].size() == 5; }));
  // The binary sphere written back in both encodings reads back the same.
  const MeshData3 sphere = read_stl((dir / "sphere.stl").string());
  for (StlEncoding e : {StlEncoding::Ascii, StlEncoding::Binary}) {
    std::stringstream again;
    write_stl(again, sphere, e);
    EXPECT_EQ(read_stl(again, "again.stl"), sphere);
  }
}

// --- Properties --------------------------------------------------------------------------------------

RC_GTEST_PROP(SurfaceFormats, RandomSurfacesSurviveEveryFormat, ()) {
  const auto n = *rc::gen::inRange<std::uint32_t>(3, 20);
  MeshData3 m;
  for (std::uint32_t i = 0; i < n; ++i) {
    // Small integers over powers of two: exact in float32 too; distinct by construction.
    const auto k = *rc::gen::inRange(-1000, 1000);
    m.vertices.push_back({static_cast<double>(k) / 64.0, static_cast<double>(i), std::ldexp(1.0, static_cast<int>(i) - 10)});
  }
  const auto triangles = *rc::gen::container<std::vector<std::array<std::uint32_t, 3>>>(
      rc::gen::container<std::array<std::uint32_t, 3>>(rc::gen::inRange<std::uint32_t>(0, n)));
  m.vertex_refs.assign(n, 0);
  m.triangles = triangles;
  m.triangle_refs.assign(triangles.size(), 0);

  std::stringstream off;
  write_off(off, m);
  RC_ASSERT(read_off(off, "r.off") == m);

  // STL numbers vertices by first use and drops unused ones: compare the triangles' corners.
  for (StlEncoding e : {StlEncoding::Ascii, StlEncoding::Binary}) {
    std::stringstream stl;
    write_stl(stl, m, e);
    const MeshData3 back = read_stl(stl, "r.stl");
    RC_ASSERT(back.triangles.size() == m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      for (int k = 0; k < 3; ++k) RC_ASSERT(back.vertices[back.triangles[t][k]] == m.vertices[m.triangles[t][k]]);
    }
  }

  Plc3 plc;
  plc.vertices = m.vertices;
  plc.vertex_markers.assign(n, 3);
  for (const auto& t : m.triangles) plc.facets.push_back({{{t[0], t[1], t[2]}}, {}, static_cast<int>(t[0])});
  std::stringstream smesh;
  write_tetgen_smesh(smesh, plc);
  const Plc3 back = read_tetgen_smesh(smesh, "r.smesh");
  RC_ASSERT(back == plc);
  const MeshData3 tri = triangulate_plc_facets(back);
  RC_ASSERT(tri.triangles == m.triangles);
}

}  // namespace
}  // namespace dtlab
