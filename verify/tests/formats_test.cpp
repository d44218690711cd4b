// The finite-element formats (Gmsh .msh, Medit binary .meshb, VTK .vtu): write/read round trips
// through every pair of formats that can hold the data keep every bit of every point and every
// reference; the files Gmsh 4.8 wrote (data/gmsh) read with their counts, references and names,
// each encoding and version giving the same mesh; malformed files are refused naming the problem.
#include <bit>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "kernel/error.hpp"
#include "mesh/io/gmsh_format.hpp"
#include "mesh/io/medit.hpp"
#include "mesh/io/medit3.hpp"
#include "mesh/io/medit_binary.hpp"
#include "mesh/io/planar_mesh.hpp"
#include "mesh/io/tetgen_format.hpp"
#include "mesh/io/triangle_format.hpp"
#include "mesh/io/vtu_format.hpp"

namespace dtlab {
namespace {

namespace fs = std::filesystem;

const std::string kData = std::string(DTLAB_SOURCE_DIR) + "/data/gmsh/";

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

void expect_same(const MeshData3& a, const MeshData3& b) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    EXPECT_TRUE(same_bits(a.vertices[i].x, b.vertices[i].x) && same_bits(a.vertices[i].y, b.vertices[i].y) &&
                same_bits(a.vertices[i].z, b.vertices[i].z))
        << "vertex " << i;
  }
  EXPECT_EQ(a.vertex_refs, b.vertex_refs);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.edge_refs, b.edge_refs);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.triangle_refs, b.triangle_refs);
  EXPECT_EQ(a.tetrahedra, b.tetrahedra);
  EXPECT_EQ(a.tetrahedron_refs, b.tetrahedron_refs);
}

void expect_same(const MeshData2& a, const MeshData2& b) { expect_same(planar_to_mesh3(a), planar_to_mesh3(b)); }

// A unit cube of 6 positive tetrahedra (Kuhn), its 12 boundary triangles by face, 4 edges, with
// coordinates that no short decimal writes exactly and a -0.
MeshData3 cube() {
  MeshData3 m;
  const double a = 1.0 / 3.0, b = 0.1 + 0.2;
  m.vertices = {{-0.0, 0, 0}, {b, 0, 0}, {0, a, 0}, {b, a, 0}, {0, 0, 1e-7}, {b, 0, 1e-7}, {0, a, 1e-7}, {b, a, 1e-7}};
  m.vertex_refs = {5, 0, 0, 0, 0, 0, 0, 9};
  // Kuhn's subdivision along the diagonal 0-7.
  const std::array<std::array<std::uint32_t, 4>, 6> kuhn = {
      {{0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}}};
  for (std::size_t i = 0; i < kuhn.size(); ++i) {
    m.tetrahedra.push_back(kuhn[i]);
    m.tetrahedron_refs.push_back(i < 3 ? 2 : 1);
  }
  m.triangles = {{0, 1, 3}, {0, 3, 2}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 3, 7}, {1, 7, 5}};
  m.triangle_refs = {1, 1, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4};
  m.edges = {{0, 1}, {1, 3}, {3, 2}, {2, 0}};
  m.edge_refs = {7, 0, 7, 8};
  return m;
}

// A square of 2 counter-clockwise triangles in two regions, boundary edges with references.
MeshData2 square() {
  MeshData2 m;
  m.vertices = {{-0.0, 0}, {0.1 + 0.2, 0}, {0.1 + 0.2, 1.0 / 3.0}, {0, 1.0 / 3.0}};
  m.vertex_refs = {1, 0, 4, 0};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.triangle_refs = {3, 5};
  m.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  m.edge_refs = {1, 2, 1, 0};
  return m;
}

const std::vector<PhysicalName> kNames = {{2, 3, "left part"}, {1, 1, "wall"}, {0, 4, "corner"}};

// --- Gmsh ----------------------------------------------------------------------------------------

GmshMesh gmsh_round_trip(const MeshData3& m, GmshEncoding e, std::span<const PhysicalName> names = {}) {
  std::stringstream s;
  write_gmsh(s, m, names, e);
  return read_gmsh(s, "rewritten.msh");
}

TEST(Gmsh, RoundTrip3dBothEncodings) {
  for (GmshEncoding e : {GmshEncoding::Ascii, GmshEncoding::Binary}) {
    const GmshMesh back = gmsh_round_trip(cube(), e, kNames);
    expect_same(cube(), back.mesh);
    EXPECT_EQ(back.names, kNames);
    EXPECT_TRUE(back.notes.empty());
  }
}

TEST(Gmsh, RoundTrip2dIsPlanar) {
  for (GmshEncoding e : {GmshEncoding::Ascii, GmshEncoding::Binary}) {
    const GmshMesh back = gmsh_round_trip(planar_to_mesh3(square()), e);
    ASSERT_TRUE(is_planar(back.mesh));
    expect_same(square(), planar_to_mesh2(back.mesh, "back"));
  }
}

TEST(Gmsh, RoundTripWithoutReferencesAndEmpty) {
  MeshData3 m = cube();
  m.vertex_refs.clear();
  m.edge_refs.clear();
  m.triangle_refs.clear();
  m.tetrahedron_refs.clear();
  MeshData3 zero = m;
  zero.vertex_refs.assign(m.vertices.size(), 0);
  zero.edge_refs.assign(m.edges.size(), 0);
  zero.triangle_refs.assign(m.triangles.size(), 0);
  zero.tetrahedron_refs.assign(m.tetrahedra.size(), 0);
  expect_same(zero, gmsh_round_trip(m, GmshEncoding::Binary).mesh);
  MeshData3 points_only;
  points_only.vertices = {{1, 2, 3}, {4, 5, 6}};
  points_only.vertex_refs = {0, 0};
  expect_same(points_only, gmsh_round_trip(points_only, GmshEncoding::Ascii).mesh);
  expect_same(MeshData3{}, gmsh_round_trip(MeshData3{}, GmshEncoding::Binary).mesh);
}

// Random meshes of random references: every bit back, in both encodings.
RC_GTEST_PROP(Gmsh, RoundTripProperty, ()) {
  MeshData3 m = cube();
  for (auto& p : m.vertices) {
    p = Vec3{p.x + *rc::gen::inRange(-1000, 1000) * 1e-5, p.y + *rc::gen::inRange(-1000, 1000) * 1e-5,
             p.z + *rc::gen::inRange(0, 10) * 0.1};
  }
  // Keep the tetrahedra positive: only the boundary pieces' references and the vertices move
  // here; the tetrahedra stay those of a slightly moved cube, checked by the reader.
  m.tetrahedra.clear();
  m.tetrahedron_refs.clear();
  for (int& r : m.triangle_refs) r = *rc::gen::inRange(0, 1 << 30);
  for (int& r : m.edge_refs) r = *rc::gen::inRange(0, 100);
  for (int& r : m.vertex_refs) r = *rc::gen::inRange(0, 3);
  const GmshEncoding e = *rc::gen::element(GmshEncoding::Ascii, GmshEncoding::Binary);
  std::stringstream s;
  write_gmsh(s, m, {}, e);
  const MeshData3 back = read_gmsh(s, "p.msh").mesh;
  RC_ASSERT(back == m);
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    RC_ASSERT(same_bits(m.vertices[i].x, back.vertices[i].x) && same_bits(m.vertices[i].z, back.vertices[i].z));
  }
}

TEST(Gmsh, NegativeReferenceRefusedByWriter) {
  MeshData3 m = cube();
  m.triangle_refs[4] = -2;
  std::stringstream s;
  try {
    write_gmsh(s, m, {});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("triangle 4: reference -2 is negative"), std::string::npos) << e.what();
  }
}

// The files Gmsh wrote: counts, references, names; ASCII and binary, 4.1 and 2.2 the same mesh.
TEST(Gmsh, ReadsGmshSquare) {
  const GmshMesh m = read_gmsh(kData + "square_41.msh");
  ASSERT_TRUE(is_planar(m.mesh));
  EXPECT_EQ(m.mesh.vertices.size(), 12u);
  EXPECT_EQ(m.mesh.edges.size(), 8u);
  EXPECT_EQ(m.mesh.triangles.size(), 14u);
  EXPECT_EQ(m.mesh.vertex_refs[0], 11);
  EXPECT_EQ(std::count(m.mesh.vertex_refs.begin(), m.mesh.vertex_refs.end(), 0), 11);
  EXPECT_EQ(std::count(m.mesh.edge_refs.begin(), m.mesh.edge_refs.end(), 7), 2);
  EXPECT_EQ(std::count(m.mesh.edge_refs.begin(), m.mesh.edge_refs.end(), 8), 6);
  EXPECT_EQ(std::count(m.mesh.triangle_refs.begin(), m.mesh.triangle_refs.end(), 3), 14);
  const std::vector<PhysicalName> names = {{0, 11, "corner"}, {1, 7, "bottom"}, {2, 3, "domain"}};
  EXPECT_EQ(m.names, names);
  // Gmsh writes %.16g in ASCII, so the ASCII files agree with each other, the binary ones too.
  expect_same(m.mesh, read_gmsh(kData + "square_22.msh").mesh);
  const GmshMesh b = read_gmsh(kData + "square_41_binary.msh");
  EXPECT_EQ(b.names, names);
  expect_same(b.mesh, read_gmsh(kData + "square_22_binary.msh").mesh);
  EXPECT_EQ(b.mesh.triangles, m.mesh.triangles);
  EXPECT_EQ(b.mesh.edge_refs, m.mesh.edge_refs);
  // MeshData2's triangles are counter-clockwise; Gmsh's are too on this square.
  const MeshData2 m2 = planar_to_mesh2(m.mesh, "square");
  for (const auto& t : m2.triangles) {
    const Vec2 &p = m2.vertices[t[0]], &q = m2.vertices[t[1]], &r = m2.vertices[t[2]];
    EXPECT_GT((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x), 0.0);
  }
}

TEST(Gmsh, ReadsGmshCube) {
  const GmshMesh m = read_gmsh(kData + "cube_41.msh");
  EXPECT_FALSE(is_planar(m.mesh));
  EXPECT_EQ(m.mesh.vertices.size(), 45u);
  EXPECT_EQ(m.mesh.tetrahedra.size(), 100u);
  EXPECT_EQ(m.mesh.triangles.size(), 84u);
  EXPECT_EQ(m.mesh.edges.size(), 8u);
  for (int r : m.mesh.tetrahedron_refs) EXPECT_EQ(r, 10);
  for (int r : m.mesh.edge_refs) EXPECT_EQ(r, 20);
  for (int ref : {1, 2, 3}) {
    EXPECT_GT(std::count(m.mesh.triangle_refs.begin(), m.mesh.triangle_refs.end(), ref), 0) << ref;
  }
  EXPECT_EQ(m.names.size(), 5u);
  const GmshMesh b = read_gmsh(kData + "cube_41_binary.msh");
  expect_same(b.mesh, read_gmsh(kData + "cube_22_binary.msh").mesh);
  EXPECT_EQ(b.names, m.names);
  EXPECT_EQ(b.mesh.tetrahedra, m.mesh.tetrahedra);
  EXPECT_EQ(b.mesh.triangle_refs, m.mesh.triangle_refs);
}

void expect_parse_error(const std::string& text, const std::string& expected, std::uint64_t line) {
  std::istringstream in(text);
  try {
    read_gmsh(in, "bad.msh");
    FAIL() << "no error for:\n" << text;
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
  }
}

TEST(Gmsh, RefusesElementsItCannotHold) {
  for (const char* file : {"square_order2_41.msh", "square_quads_22.msh"}) {
    try {
      read_gmsh(kData + file);
      FAIL() << file;
    } catch (const ParseError& e) {
      EXPECT_NE(std::string(e.what()).find("which dtlab's meshes cannot hold"), std::string::npos) << e.what();
    }
  }
  try {
    read_gmsh(kData + "square_quads_22.msh");
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("element 10 is of type 3 (4-node quadrangle)"), std::string::npos) << e.what();
    EXPECT_EQ(e.line(), 35u);
  }
}

const std::string kHead = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
const std::string kNodes = "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n";

TEST(Gmsh, RefusesMalformed) {
  expect_parse_error("", "empty file", 1);
  expect_parse_error("$MeshFormat\n4 0 8\n$EndMeshFormat\n", "MSH 4.0 is not supported", 2);
  expect_parse_error("$MeshFormat\n4.1 0 4\n$EndMeshFormat\n", "data size 4", 2);
  expect_parse_error(kHead + kNodes + "$Elements\n1\n1 4 0 1 3 2 4\n$EndElements\n",
                     "tetrahedron 1 is negatively oriented", 13);
  expect_parse_error(kHead + kNodes + "$Elements\n1\n1 2 0 1 2 9\n$EndElements\n",
                     "element 1: node 9 is not in $Nodes", 13);
  expect_parse_error(kHead + kNodes + "$Elements\n2\n1 2 0 1 2 3\n$EndElements\n",
                     "expected element number, found '$EndElements' (fewer entries than the count?)", 14);
  expect_parse_error(kHead + "$Nodes\n2\n1 0 0 0\n1 1 0 0\n$EndNodes\n", "node tag 1 is used twice", 7);
  expect_parse_error(kHead + "$Nodes\n1\n1 0 nan 0\n$EndNodes\n", "node 1 y is not finite", 6);
  expect_parse_error(kHead + "$Nodes\n1\n1 0 0 0\n", "file ends before $EndNodes", 7);
  expect_parse_error(kHead + kNodes + "junk\n", "expected a section ($Name), found 'junk'", 11);
  expect_parse_error(kHead + "$PhysicalNames\n1\n2 3 domain\n$EndPhysicalNames\n" + kNodes,
                     "physical name 1 is not a quoted name", 6);
  expect_parse_error(kHead + kNodes + "$Elements\n1\n1 5 0 1 2 3 4 1 2 3 4\n$EndElements\n",
                     "element 1 is of type 5 (8-node hexahedron)", 13);
  expect_parse_error("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PartitionedEntities\n$EndPartitionedEntities\n",
                     "partitioned meshes are not supported", 4);
  // 4.1: counts that do not add up.
  expect_parse_error("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2 1 2\n2 1 0 1\n1\n0 0 0\n$EndNodes\n",
                     "$Nodes header counts 2 nodes, the blocks hold 1", 8);
  // Skipped sections are named.
  std::istringstream in(kHead + kNodes + "$NodeData\n1\n\"T\"\n$EndNodeData\n");
  const GmshMesh m = read_gmsh(in, "data.msh");
  ASSERT_EQ(m.notes.size(), 1u);
  EXPECT_EQ(m.notes[0], "section $NodeData skipped (it carries no mesh)");
}

TEST(Gmsh, RefusesTruncatedBinary) {
  std::stringstream s;
  write_gmsh(s, cube(), kNames, GmshEncoding::Binary);
  const std::string whole = s.str();
  // Every prefix is refused (none reads as a complete file), and no count allocates beyond the file.
  for (std::size_t n = 0; n + 1 < whole.size(); n += 7) {
    std::istringstream in(whole.substr(0, n));
    EXPECT_THROW(read_gmsh(in, "cut.msh"), ParseError) << n;
  }
  // A count that the rest of the file cannot hold.
  std::string big = whole;
  const std::size_t nodes = big.find("$Nodes\n") + 7;
  big[nodes + 8 + 3] = 0x7f;  // the number of nodes, little-endian size_t
  std::istringstream in(big);
  try {
    read_gmsh(in, "big.msh");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("at byte " + std::to_string(nodes + 8)), std::string::npos) << e.what();
  }
}

// --- Medit binary --------------------------------------------------------------------------------

TEST(MeditBinary, RoundTripEveryVersion) {
  for (int version : {2, 3, 4}) {
    std::stringstream s3, s2;
    write_meshb3(s3, cube(), version);
    EXPECT_TRUE(is_medit_binary(s3.str()));
    EXPECT_EQ(medit_binary_dimension(s3.str(), "c.meshb"), 3);
    expect_same(cube(), read_meshb3(s3, "c.meshb"));
    write_meshb2(s2, square(), version);
    EXPECT_EQ(medit_binary_dimension(s2.str(), "s.meshb"), 2);
    expect_same(square(), read_meshb2(s2, "s.meshb"));
  }
}

TEST(MeditBinary, RefusesMalformed) {
  std::stringstream s;
  write_meshb3(s, cube());
  const std::string whole = s.str();
  for (std::size_t n = 0; n < whole.size(); n += 5) {
    std::istringstream in(whole.substr(0, n));
    EXPECT_THROW(read_meshb3(in, "cut.meshb"), ParseError) << n;
  }
  auto expect_error = [](const std::string& bytes, const std::string& expected, bool two_d = false) {
    std::istringstream in(bytes);
    try {
      if (two_d) {
        read_meshb2(in, "bad.meshb");
      } else {
        read_meshb3(in, "bad.meshb");
      }
      FAIL() << expected;
    } catch (const ParseError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  expect_error(whole, "Dimension 3: this is a 3D mesh", true);
  // Vertices start at byte 8 + 12 (Dimension) + 8 (keyword header) + 4 (count); the first
  // triangle's first vertex number follows the vertices and the edges.
  std::string bad = whole;
  const std::size_t vertices = 8 + 12;
  bad[vertices] = 7;  // keyword code 7: Quadrilaterals
  expect_error(bad, "keyword code 7 (Quadrilaterals) is not supported");
  bad = whole;
  const std::size_t first_edge = vertices + 12 + 8 * (3 * 8 + 4) + 12;
  bad[first_edge] = 99;
  expect_error(bad, "edge 1: vertex number 99 out of range 1..8");
  bad = whole;
  bad[vertices + 4] = 1;  // a wrong next-keyword offset
  expect_error(bad, "is not where the next keyword begins");
  expect_error(whole + "x", "1 bytes after End");
}

// --- VTU -----------------------------------------------------------------------------------------

TEST(Vtu, WritesCellsReferencesAndFields) {
  VtuFields fields;
  fields.point_data.push_back({"size", 1, std::vector<double>(8, 0.5)});
  fields.cell_data.push_back({"quality", 1, std::vector<double>(4 + 12 + 6, 1.0)});
  std::stringstream s;
  write_vtu(s, cube(), fields);
  const std::string t = s.str();
  EXPECT_NE(t.find("NumberOfPoints=\"8\" NumberOfCells=\"22\""), std::string::npos);
  EXPECT_NE(t.find("Name=\"ref\""), std::string::npos);
  EXPECT_NE(t.find("Name=\"vertex_ref\""), std::string::npos);
  EXPECT_NE(t.find("Name=\"size\""), std::string::npos);
  EXPECT_NE(t.find("Name=\"quality\""), std::string::npos);
  // Exact coordinates: 0.1 + 0.2 in its shortest exact form.
  EXPECT_NE(t.find("0.30000000000000004"), std::string::npos);
  fields.cell_data[0].values.pop_back();
  EXPECT_THROW(write_vtu(s, cube(), fields), InputError);
}

// --- Every pair of formats -----------------------------------------------------------------------

struct Format3 {
  const char* name;
  bool holds_edges;
  std::function<void(const std::string&, const MeshData3&)> write;
  std::function<MeshData3(const std::string&)> read;
};

class FormatPairs : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("dtlab-formats-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                        "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(FormatPairs, EveryPair3d) {
  const std::vector<Format3> formats = {
      {"mesh", true, [](auto& p, auto& m) { write_medit3(p + ".mesh", m); }, [](auto& p) { return read_medit3(p + ".mesh"); }},
      {"meshb", true, [](auto& p, auto& m) { write_meshb3(p + ".meshb", m); }, [](auto& p) { return read_meshb3(p + ".meshb"); }},
      {"msh", true, [](auto& p, auto& m) { write_gmsh(p + ".msh", m, {}); }, [](auto& p) { return read_gmsh(p + ".msh").mesh; }},
      {"msh-binary", true, [](auto& p, auto& m) { write_gmsh(p + ".msh", m, {}, GmshEncoding::Binary); },
       [](auto& p) { return read_gmsh(p + ".msh").mesh; }},
      {"tetgen", false, [](auto& p, auto& m) { write_tetgen_mesh(p, m); }, [](auto& p) { return read_tetgen_mesh(p); }},
  };
  for (const Format3& a : formats) {
    for (const Format3& b : formats) {
      SCOPED_TRACE(std::string(a.name) + " -> " + b.name);
      MeshData3 m = cube();
      if (!a.holds_edges || !b.holds_edges) {
        m.edges.clear();
        m.edge_refs.clear();
      }
      a.write(path(std::string("a-") + a.name), m);
      const MeshData3 via_a = a.read(path(std::string("a-") + a.name));
      b.write(path(std::string("b-") + a.name + "-" + b.name), via_a);
      expect_same(m, b.read(path(std::string("b-") + a.name + "-" + b.name)));
    }
  }
}

struct Format2 {
  const char* name;
  bool holds_edges;
  std::function<void(const std::string&, const MeshData2&)> write;
  std::function<MeshData2(const std::string&)> read;
};

TEST_F(FormatPairs, EveryPair2d) {
  const std::vector<Format2> formats = {
      {"mesh", true, [](auto& p, auto& m) { write_medit2(p + ".mesh", m); }, [](auto& p) { return read_medit2(p + ".mesh"); }},
      {"meshb", true, [](auto& p, auto& m) { write_meshb2(p + ".meshb", m); }, [](auto& p) { return read_meshb2(p + ".meshb"); }},
      {"msh", true, [](auto& p, auto& m) { write_gmsh(p + ".msh", planar_to_mesh3(m), {}); },
       [](auto& p) { return planar_to_mesh2(read_gmsh(p + ".msh").mesh, p); }},
      {"msh-binary", true, [](auto& p, auto& m) { write_gmsh(p + ".msh", planar_to_mesh3(m), {}, GmshEncoding::Binary); },
       [](auto& p) { return planar_to_mesh2(read_gmsh(p + ".msh").mesh, p); }},
      {"triangle", false, [](auto& p, auto& m) { write_triangle_mesh(p, m); }, [](auto& p) { return read_triangle_mesh(p); }},
  };
  for (const Format2& a : formats) {
    for (const Format2& b : formats) {
      SCOPED_TRACE(std::string(a.name) + " -> " + b.name);
      MeshData2 m = square();
      if (!a.holds_edges || !b.holds_edges) {
        m.edges.clear();
        m.edge_refs.clear();
      }
      a.write(path(std::string("a-") + a.name), m);
      const MeshData2 via_a = a.read(path(std::string("a-") + a.name));
      b.write(path(std::string("b-") + a.name + "-" + b.name), via_a);
      expect_same(m, b.read(path(std::string("b-") + a.name + "-" + b.name)));
    }
  }
}

}  // namespace
}  // namespace dtlab
