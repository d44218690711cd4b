// The shared mutable 3D mesh (mesh/mesh3.hpp) and its construction from a neutral mesh
// (mesh/mesh3_from_data.hpp): built from Delaunay tetrahedralizations (algorithms/delaunay3d)
// and from hand-made non-convex meshes, check() passes; ball, shell (with its ring's order),
// find_edge, find_facet and locate agree with brute force on random point sets (RapidCheck),
// locate's edge, facet and vertex cases on lattice points exactly; domain() round-trips through
// mesh3_from_data; bad input is refused by name, numbered from 1; check() finds broken meshes.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/element_grid.hpp"
#include "mesh/mesh3.hpp"
#include "mesh/mesh3_from_data.hpp"
#include "mesh/navigation3.hpp"
#include "verify/generators/kuhn_cubes.hpp"

namespace dtlab {
namespace {

// A Delaunay mesh of `points`: finite tetrahedra of reference `ref` (or 1 / 2 by the side of
// x = split when split is given), hull facets constrained with reference 7.
Mesh3 delaunay_mesh(const std::vector<Vec3>& points, double split = 1e300) {
  Delaunay3dResult r = delaunay3d(points);
  EXPECT_TRUE(r.degenerate_message.empty()) << r.degenerate_message;
  const Tetrahedralization3& tet = r.tetrahedralization;
  std::vector<int> refs(tet.tetrahedron_count(), Mesh3::kExterior);
  std::vector<MeshTriangle3> hull;
  for (std::uint32_t t = 0; t < tet.tetrahedron_count(); ++t) {
    if (tet.is_ghost(t)) {
      const auto f = tet.facet_vertices(Tetrahedralization3::facet(t, 0));
      hull.push_back({f[0], f[1], f[2], 7});
      continue;
    }
    double x = 0;
    for (std::uint32_t i = 0; i < 4; ++i) x += points[tet.vertex(t, i)].x / 4;
    refs[t] = x < split ? 1 : 2;
  }
  return Mesh3(tet, refs, hull);
}

std::vector<Vec3> random_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> p(n);
  for (Vec3& q : p) q = {u(rng), u(rng), u(rng)};
  return p;
}

// Points on a lattice of spacing 6 (so that edge midpoints and facet centroids are exact).
std::vector<Vec3> lattice_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> u(0, 12);
  std::set<std::array<int, 3>> seen;
  std::vector<Vec3> p;
  while (p.size() < n) {
    const std::array<int, 3> c{u(rng), u(rng), u(rng)};
    if (!seen.insert(c).second) continue;
    p.push_back({6.0 * c[0], 6.0 * c[1], 6.0 * c[2]});
  }
  return p;
}

bool has(const std::array<std::uint32_t, 4>& t, std::uint32_t v) { return std::find(t.begin(), t.end(), v) != t.end(); }

std::vector<std::uint32_t> live_with(const Mesh3& m, std::uint32_t a, std::uint32_t b = Mesh3::kNone) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t t = 0; t < m.tetrahedron_capacity(); ++t)
    if (m.is_alive(t) && has(m.tetrahedron(t), a) && (b == Mesh3::kNone || has(m.tetrahedron(t), b))) out.push_back(t);
  return out;
}

std::vector<std::uint32_t> sorted_copy(std::vector<std::uint32_t> v) {
  std::sort(v.begin(), v.end());
  return v;
}

// Ball, shell, ring order, find_edge, find_facet against brute force, for every vertex and the
// edges of every `stride`-th tetrahedron.
void check_queries(const Mesh3& m, std::uint32_t stride = 1) {
  std::vector<std::uint32_t> out, ring, shell;
  for (std::uint32_t v = 0; v < m.vertex_capacity(); ++v) {
    if (m.is_dead_vertex(v)) continue;
    m.ball(v, out);
    ASSERT_EQ(sorted_copy(out), live_with(m, v)) << "ball of " << v;
  }
  for (std::uint32_t t = 0; t < m.tetrahedron_capacity(); t += stride) {
    if (!m.is_alive(t)) continue;
    const auto tv = m.tetrahedron(t);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const std::uint32_t a = tv[i], b = tv[j];
        ASSERT_NE(m.find_edge(a, b), Mesh3::kNone);
        ASSERT_TRUE(m.shell(a, b, shell, &ring));
        ASSERT_EQ(shell.size(), ring.size());
        ASSERT_EQ(sorted_copy(shell), live_with(m, a, b)) << "shell of " << a << "-" << b;
        const std::size_t n = shell.size();
        for (std::size_t k = 0; k < n; ++k) {
          const std::uint32_t c = ring[k], d = ring[(k + 1) % n];
          const auto s = m.tetrahedron(shell[k]);
          ASSERT_TRUE(has(s, a) && has(s, b) && has(s, c) && has(s, d));
          // Consecutive tetrahedra share the facet (a, b, ring[k+1]).
          const auto s2 = m.tetrahedron(shell[(k + 1) % n]);
          ASSERT_TRUE(has(s2, d));
          if (a != Mesh3::kInfinite && b != Mesh3::kInfinite && c != Mesh3::kInfinite && d != Mesh3::kInfinite) {
            ASSERT_EQ(orient3d(m.point(a), m.point(b), m.point(c), m.point(d)), Sign::Positive);
          }
        }
      }
    for (std::uint32_t i = 0; i < 4; ++i) {
      const auto f = m.facet_vertices(Mesh3::facet(t, i));
      const std::uint32_t h = m.find_facet(f[2], f[0], f[1]);
      ASSERT_NE(h, Mesh3::kNone);
      ASSERT_TRUE(h == Mesh3::facet(t, i) || h == m.twin(Mesh3::facet(t, i)));
    }
  }
}

TEST(Mesh3, DelaunayMeshChecksAndQueries) {
  const Mesh3 m = delaunay_mesh(random_points(300, 1));
  m.check();
  check_queries(m);
  EXPECT_EQ(m.live_vertex_count(), 300u);
  // Hull vertices are on the boundary, hull edges constrained.
  std::size_t constrained_facets = 0;
  for (std::uint32_t h = 0; h < 4 * m.tetrahedron_capacity(); ++h) constrained_facets += m.is_constrained(h);
  EXPECT_GT(constrained_facets, 0u);
  EXPECT_GT(m.constrained_edge_count(), 0u);
}

TEST(Mesh3, FindEdgeOfNonEdgeIsNone) {
  const Mesh3 m = delaunay_mesh(random_points(200, 2));
  std::vector<std::uint32_t> ball;
  int tested = 0;
  for (std::uint32_t a = 0; a < 200 && tested < 50; ++a)
    for (std::uint32_t b = a + 1; b < 200 && tested < 50; ++b) {
      if (!live_with(m, a, b).empty()) continue;
      ++tested;
      std::vector<std::uint32_t> shell;
      EXPECT_EQ(m.find_edge(a, b), Mesh3::kNone);
      EXPECT_FALSE(m.shell(a, b, shell));
    }
  EXPECT_EQ(tested, 50);
}

TEST(Mesh3, LocateFindsTheHoldingTetrahedron) {
  const std::vector<Vec3> pts = random_points(400, 3);
  const Mesh3 m = delaunay_mesh(pts);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int inside = 0, outside = 0;
  for (int k = 0; k < 500; ++k) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const std::uint32_t start = static_cast<std::uint32_t>(rng() % m.tetrahedron_capacity());
    const Mesh3::Location loc = m.locate(p, start);
    if (loc.where == Mesh3::Where::Outside) {
      ++outside;
      ASSERT_TRUE(m.is_ghost(loc.tetrahedron));
      // Strictly beyond its hull facet: on the side of the ghost's infinite vertex.
      const auto f = m.facet_vertices(Mesh3::facet(loc.tetrahedron, 0));
      ASSERT_EQ(orient3d(m.point(f[0]), m.point(f[1]), m.point(f[2]), p), Sign::Positive);
      continue;
    }
    ++inside;
    ASSERT_EQ(loc.where, Mesh3::Where::Inside);
    for (std::uint32_t i = 0; i < 4; ++i) {
      const auto f = m.facet_vertices(Mesh3::facet(loc.tetrahedron, i));
      ASSERT_EQ(orient3d(m.point(f[0]), m.point(f[1]), m.point(f[2]), p), Sign::Positive);
    }
  }
  EXPECT_GT(inside, 50);
  EXPECT_GT(outside, 50);
  // Every vertex is found as a vertex.
  for (std::uint32_t v = 0; v < pts.size(); v += 7) {
    const Mesh3::Location loc = m.locate(pts[v], 0);
    EXPECT_EQ(loc.where, Mesh3::Where::Vertex);
    EXPECT_EQ(loc.handle, v);
  }
}

TEST(Mesh3, LocateOnEdgesAndFacetsExactly) {
  const std::vector<Vec3> pts = lattice_points(120, 5);
  const Mesh3 m = delaunay_mesh(pts);
  m.check();
  int edges = 0, facets = 0;
  for (std::uint32_t t = 0; t < m.tetrahedron_capacity(); t += 3) {
    if (m.is_ghost(t)) continue;
    const auto v = m.tetrahedron(t);
    const Vec3 mid = 0.5 * (m.point(v[0]) + m.point(v[1]));
    const Vec3 centroid = (1.0 / 3.0) * (m.point(v[0]) + m.point(v[1]) + m.point(v[2]));
    const bool mid_is_vertex = std::find(pts.begin(), pts.end(), mid) != pts.end();
    const Mesh3::Location e = m.locate(mid, t);
    if (!mid_is_vertex) {
      // Lattice points can be collinear: the midpoint lies on the edge, which is an edge of the
      // mesh, unless another vertex lies between the ends (then v0v1 would not be an edge).
      ASSERT_EQ(e.where, Mesh3::Where::Edge);
      ASSERT_EQ(std::minmax(e.edge_a, e.edge_b), std::minmax(v[0], v[1]));
      ++edges;
    }
    const Mesh3::Location f = m.locate(centroid, (t * 7) % m.tetrahedron_capacity());
    if (std::find(pts.begin(), pts.end(), centroid) == pts.end() && f.where == Mesh3::Where::Facet) {
      auto a = m.facet_vertices(f.handle);
      std::array<std::uint32_t, 3> b{v[0], v[1], v[2]};
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      ASSERT_EQ(a, b);
      ++facets;
    }
  }
  EXPECT_GT(edges, 20);
  EXPECT_GT(facets, 20);
}

TEST(Mesh3, LocateStopsAtConstraints) {
  const std::vector<Vec3> pts = random_points(300, 6);
  // Two regions split at x = 0; constrain the interface by building from the domain.
  const Mesh3 two = delaunay_mesh(pts, 0.0);
  const Mesh3 m = mesh3_from_data(two.domain());
  m.check();
  int blocked = 0;
  for (std::uint32_t t = 0; t < m.tetrahedron_capacity(); ++t) {
    if (!m.in_domain(t) || m.ref(t) != 1) continue;
    // From a region-1 tetrahedron towards a point deep in region 2.
    const Mesh3::Location loc = m.locate({0.9, 0.0, 0.0}, t, true);
    if (loc.blocked) {
      ++blocked;
      EXPECT_EQ(m.ref(loc.tetrahedron), 1);
    }
  }
  EXPECT_GT(blocked, 0);
}

// The shared walk (mesh/navigation3.hpp) with the control space's policy, in a ring of eight
// cubes around a hole (not convex): it ends in the tetrahedron holding p, or where every facet with p beyond it is on
// the boundary (skipped), never in a ghost; Mesh3::locate's policy ends Outside there instead.
TEST(Mesh3, SharedWalkSkipsTheBoundaryOfANonConvexMesh) {
  std::vector<std::array<int, 3>> ring;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != 1 || j != 1) ring.push_back({i, j, 0});
  const Mesh3 m = mesh3_from_data(gen::kuhn_cubes(ring));
  const auto skip_boundary = [&](std::uint32_t h) {
    return m.is_ghost(Mesh3::tetrahedron_of(m.twin(h))) ? nav3::Beyond::Skip : nav3::Beyond::Cross;
  };
  const auto rotate = [](std::uint64_t step) { return static_cast<std::uint32_t>(step & 3u); };
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.02, 0.98);
  for (int k = 0; k < 300; ++k) {
    const Vec3 p{u(rng) + (k % 2 ? 2 : 0), u(rng) + 1, u(rng)};  // left or right of the hole
    const bool across = k % 4 < 2;
    const Vec3 q{across == (p.x > 1) ? 0.5 : 2.5, p.y, p.z};
    std::uint32_t start = 0;
    while (m.is_ghost(start) || !closed_tetrahedron_holds(m.point(m.vertex(start, 0)), m.point(m.vertex(start, 1)),
                                                          m.point(m.vertex(start, 2)), m.point(m.vertex(start, 3)), q))
      ++start;
    const nav3::Walk w = nav3::visibility_walk(m, p, start, 1000, rotate, skip_boundary);
    ASSERT_EQ(w.end, nav3::Walk::End::Found);
    ASSERT_FALSE(m.is_ghost(w.tetrahedron));
    bool beyond_inner = false, beyond_any = false;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = Mesh3::facet(w.tetrahedron, i);
      const auto f = m.facet_vertices(h);
      if (orient3d(m.point(f[0]), m.point(f[1]), m.point(f[2]), p) != Sign::Negative) continue;
      beyond_any = true;
      beyond_inner = beyond_inner || !m.is_ghost(Mesh3::tetrahedron_of(m.twin(h)));
    }
    ASSERT_FALSE(beyond_inner);
    // Across the hole the straight way leaves the mesh (the walk stops at the hole's wall); along
    // a convex side of the ring it reaches p.
    ASSERT_EQ(beyond_any, across) << k;
    if (beyond_any) {
      EXPECT_EQ(m.locate(p, w.tetrahedron).where, Mesh3::Where::Outside);
    }
  }
}

MeshData3 cubes(const std::vector<std::array<int, 3>>& corners, int ref_of_second = 0) {
  return gen::kuhn_cubes(corners, ref_of_second);
}

TEST(Mesh3FromData, NonConvexMesh) {
  // An L of three cubes: not convex, so ghosts close concave boundary facets.
  const MeshData3 d = cubes({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  const Mesh3 m = mesh3_from_data(d);
  m.check();
  check_queries(m);
  std::uint32_t domain_count = 0;
  for (std::uint32_t t = 0; t < m.tetrahedron_capacity(); ++t) domain_count += m.in_domain(t);
  EXPECT_EQ(domain_count, 18u);
  // 3 cubes: 14 boundary squares = 28 triangles, all constrained with reference 0.
  const MeshData3 out = m.domain();
  EXPECT_EQ(out.tetrahedra.size(), 18u);
  EXPECT_EQ(out.triangles.size(), 28u);
  // Interior vertex none: all 16 vertices on the boundary, fixed.
  for (std::uint32_t v = 0; v < m.vertex_capacity(); ++v)
    EXPECT_EQ(m.flags(v), Mesh3::kFixed | Mesh3::kOnBoundary);
}

// Interior faces listed as Triangles with one region on both sides (issue 42, item 11): some of
// them are internal constraints; all of them (TetGen's -g output lists every face) none; said
// either way.
TEST(Mesh3FromData, InteriorFacesListedAsTriangles) {
  MeshData3 d = cubes({{0, 0, 0}, {1, 0, 0}});
  std::map<std::array<std::uint32_t, 3>, int> faces;
  for (const auto& t : d.tetrahedra)
    for (int i = 0; i < 4; ++i) {
      std::array<std::uint32_t, 3> f{t[(i + 1) % 4], t[(i + 2) % 4], t[(i + 3) % 4]};
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  std::vector<std::array<std::uint32_t, 3>> interior;
  for (const auto& [f, n] : faces)
    if (n == 2) interior.push_back(f);
  ASSERT_GT(interior.size(), 1u);

  MeshData3 some = d;
  some.triangles = {interior.front()};
  some.triangle_refs = {7};
  std::vector<std::string> messages;
  const Mesh3 kept = mesh3_from_data(some, {}, &messages);
  kept.check();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find("1 Triangles entry is interior face with one region on both sides, kept as internal"),
            std::string::npos)
      << messages[0];
  EXPECT_EQ(kept.domain().triangles.size(), 20u + 1u);  // 10 boundary squares and the listed face

  MeshData3 all = d;
  all.triangles = interior;
  all.triangle_refs.assign(interior.size(), 7);
  messages.clear();
  const Mesh3 none = mesh3_from_data(all, {}, &messages);
  none.check();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find(std::to_string(interior.size()) + " Triangles entries are interior faces"), std::string::npos);
  EXPECT_NE(messages[0].find("every interior face is listed"), std::string::npos);
  EXPECT_EQ(none.domain().triangles.size(), 20u);  // the boundary only
}

TEST(Mesh3FromData, InterfacesBetweenReferencesAreConstrained) {
  const MeshData3 d = cubes({{0, 0, 0}, {1, 0, 0}}, 5);
  const Mesh3 m = mesh3_from_data(d);
  m.check();
  // 10 boundary squares + 1 interface square.
  const MeshData3 out = m.domain();
  EXPECT_EQ(out.triangles.size(), 22u);
}

TEST(Mesh3FromData, InteriorVerticesAreFree) {
  std::vector<std::array<int, 3>> c;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z) c.push_back({x, y, z});
  const Mesh3 m = mesh3_from_data(cubes(c));
  m.check();
  check_queries(m, 5);
  int free_vertices = 0;
  for (std::uint32_t v = 0; v < m.vertex_capacity(); ++v) {
    const Vec3& p = m.point(v);
    const bool inner = p.x > 0 && p.x < 3 && p.y > 0 && p.y < 3 && p.z > 0 && p.z < 3;
    EXPECT_EQ(m.flags(v) == 0, inner) << v;
    free_vertices += m.flags(v) == 0;
  }
  EXPECT_EQ(free_vertices, 8);
}

TEST(Mesh3FromData, DomainRoundTrip) {
  const Mesh3 two = delaunay_mesh(random_points(250, 7), 0.1);
  const MeshData3 a = two.domain();
  const Mesh3 m = mesh3_from_data(a);
  m.check();
  check_queries(m, 3);
  const MeshData3 b = m.domain();
  const Mesh3 m2 = mesh3_from_data(b);
  EXPECT_EQ(m2.domain(), b);
  // Hull facets keep their reference 7, the interface gets 0.
  std::set<int> refs(b.triangle_refs.begin(), b.triangle_refs.end());
  EXPECT_EQ(refs, (std::set<int>{0, 7}));
  // Listed triangles keep their own reference and orientation need not match.
  MeshData3 c = b;
  for (auto& t : c.triangles) std::swap(t[0], t[1]);
  EXPECT_EQ(mesh3_from_data(c).domain().triangles.size(), b.triangles.size());
}

template <typename F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Mesh3FromData, Refusals) {
  const MeshData3 good = cubes({{0, 0, 0}});
  {
    MeshData3 d = good;
    std::swap(d.tetrahedra[1][0], d.tetrahedra[1][1]);
    EXPECT_NE(input_error([&] { mesh3_from_data(d); }).find("tetrahedron 2 is not positive"), std::string::npos);
  }
  {
    MeshData3 d = good;
    d.tetrahedra[2][3] = 99;
    EXPECT_NE(input_error([&] { mesh3_from_data(d); }).find("tetrahedron 3 uses vertex 100"), std::string::npos);
  }
  {
    // A facet in three tetrahedra: a third apex beside a cube's facet, on the side of one of
    // the two tetrahedra there.
    MeshData3 d;
    d.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {0.1, 0.1, 2}};
    d.tetrahedra = {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}};
    EXPECT_NE(input_error([&] { mesh3_from_data(d); }).find("shared by 3 tetrahedra"), std::string::npos);
  }
  {
    MeshData3 d = good;
    d.triangles = {{0, 1, 2}, {0, 1, 7}};  // vertex 7 is the cube's far corner
    d.triangle_refs = {1, 1};
    const std::string e = input_error([&] { mesh3_from_data(d); });
    EXPECT_TRUE(e.find("triangle 1 ") != std::string::npos || e.find("triangle 2 ") != std::string::npos) << e;
    EXPECT_NE(e.find("is not a facet"), std::string::npos) << e;
  }
  {
    // Two tetrahedra touching at one vertex: the boundary pinches there.
    MeshData3 d;
    d.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    d.tetrahedra = {{0, 1, 2, 3}, {0, 4, 6, 5}};
    if (orient3d(d.vertices[0], d.vertices[4], d.vertices[6], d.vertices[5]) != Sign::Positive)
      std::swap(d.tetrahedra[1][2], d.tetrahedra[1][3]);
    EXPECT_NE(input_error([&] { mesh3_from_data(d); }).find("vertex 1"), std::string::npos);
  }
  {
    MeshData3 d = good;
    // Vertices 0 (0,0,0), 1 (1,0,0), 7 (0,0,1): 0-7 and 0-1 are cube edges, 1-7 crosses the
    // face diagonal 0-(1,0,1).
    d.edges = {{0, 7}, {0, 1}, {1, 7}};
    d.edge_refs = {0, 0, 0};
    EXPECT_NE(input_error([&] { mesh3_from_data(d); }).find("edge 3 (2, 8) is not an edge"), std::string::npos);
    d.edges.pop_back();
    d.edge_refs.pop_back();
    const Mesh3 m = mesh3_from_data(d);
    EXPECT_TRUE(m.is_constrained_edge(7, 0));
  }
}

TEST(Mesh3, ConstructorRefusesAConstraintThatIsNoFacet) {
  const std::vector<Vec3> pts = random_points(50, 8);
  Delaunay3dResult r = delaunay3d(pts);
  std::vector<int> refs(r.tetrahedralization.tetrahedron_count(), 1);
  std::vector<MeshTriangle3> c;
  // Find three vertices that are not a facet.
  for (std::uint32_t a = 1; a < 50 && c.empty(); ++a) {
    const Mesh3 m(r.tetrahedralization, refs, {});
    if (m.find_facet(0, a, a + 1) == Mesh3::kNone) c.push_back({0, a, a + 1, 3});
  }
  ASSERT_FALSE(c.empty());
  EXPECT_THROW(Mesh3(r.tetrahedralization, refs, c), InputError);
}

TEST(Mesh3, FreeListsAndCheckFindsBreakage) {
  Mesh3 m = mesh3_from_data(cubes({{0, 0, 0}, {1, 0, 0}}));
  m.check();
  const std::uint32_t cap = m.tetrahedron_capacity();
  // Remove a tetrahedron and re-add it: same slot, links restored by hand.
  const auto v = m.tetrahedron(3);
  std::array<std::uint32_t, 4> twins;
  std::array<int, 4> frefs;
  std::array<bool, 4> cons;
  for (std::uint32_t i = 0; i < 4; ++i) {
    twins[i] = m.twin(Mesh3::facet(3, i));
    frefs[i] = m.facet_ref(Mesh3::facet(3, i));
    cons[i] = m.is_constrained(Mesh3::facet(3, i));
  }
  const int r = m.ref(3);
  m.remove_tetrahedron(3);
  EXPECT_THROW(m.check(), InternalError);
  const std::uint32_t t = m.add_tetrahedron(v[0], v[1], v[2], v[3], r);
  EXPECT_EQ(t, 3u);
  EXPECT_EQ(m.tetrahedron_capacity(), cap);
  EXPECT_THROW(m.check(), InternalError);  // not linked yet
  for (std::uint32_t i = 0; i < 4; ++i) {
    m.link(Mesh3::facet(t, i), twins[i]);
    m.set_facet(Mesh3::facet(t, i), cons[i], frefs[i]);
  }
  m.check();
  // A vertex moved across a facet inverts a tetrahedron.
  const Vec3 old = m.point(v[0]);
  m.set_point(v[0], {5, 5, 5});
  EXPECT_THROW(m.check(), InternalError);
  m.set_point(v[0], old);
  m.check();
  // A constraint on one side only.
  const std::uint32_t h = Mesh3::facet(0, 0);
  const bool was = m.is_constrained(h);
  const int was_ref = m.facet_ref(h);
  m.set_facet(h, !was, 0);
  EXPECT_THROW(m.check(), InternalError);
  m.set_facet(h, was, was_ref);
  m.check();
  // A constrained edge that is no edge.
  m.set_constrained_edge(0, 11, true);
  if (m.find_edge(0, 11) == Mesh3::kNone) {
    EXPECT_THROW(m.check(), InternalError);
  }
  m.set_constrained_edge(0, 11, false);
  m.check();
  // Vertex slots are reused.
  const std::uint32_t extra = m.add_vertex({9, 9, 9}, {});
  EXPECT_THROW(m.check(), InternalError);  // live but used by no tetrahedron
  m.remove_vertex(extra);
  m.check();
  EXPECT_EQ(m.add_vertex({9, 9, 9}, {}), extra);
}

RC_GTEST_PROP(Mesh3Properties, QueriesAgreeWithBruteForce, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(5, 120);
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const bool lattice = *rc::gen::arbitrary<bool>();
  const std::vector<Vec3> pts = lattice ? lattice_points(n, seed) : random_points(n, seed);
  Delaunay3dResult r = delaunay3d(pts);
  RC_PRE(r.degenerate_message.empty());
  const Mesh3 m = delaunay_mesh(pts, 0.0);
  m.check();
  check_queries(m);
  RC_ASSERT(!::testing::Test::HasFailure());
  const MeshData3 d = m.domain();
  const Mesh3 m2 = mesh3_from_data(d);
  m2.check();
  check_queries(m2);
  RC_ASSERT(!::testing::Test::HasFailure());
  RC_ASSERT(m2.domain().tetrahedra == d.tetrahedra);
}

}  // namespace
}  // namespace dtlab

namespace dtlab {
namespace {

// The domain as a set of tetrahedra by corner coordinates (sorted) with their references, and the
// constrained facets likewise: what a renumbering must keep.
std::multiset<std::pair<std::vector<std::array<double, 3>>, int>> geometry(const MeshData3& d, bool facets) {
  std::multiset<std::pair<std::vector<std::array<double, 3>>, int>> out;
  auto corners = [&](auto ids) {
    std::vector<std::array<double, 3>> c;
    for (const auto v : ids) c.push_back({d.vertices[v].x, d.vertices[v].y, d.vertices[v].z});
    std::sort(c.begin(), c.end());
    return c;
  };
  if (facets) {
    for (std::size_t k = 0; k < d.triangles.size(); ++k) out.emplace(corners(d.triangles[k]), d.triangle_refs[k]);
  } else {
    for (std::size_t k = 0; k < d.tetrahedra.size(); ++k) out.emplace(corners(d.tetrahedra[k]), d.tetrahedron_refs[k]);
  }
  return out;
}

TEST(Mesh3, RenumberKeepsEverythingAndDropsFreeSlots) {
  Mesh3 m = mesh3_from_data(cubes({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 2));
  // A dead vertex slot and a dead tetrahedron slot.
  const std::uint32_t dead_v = m.add_vertex({9, 9, 9}, Metric3::isotropic(1.0));
  m.remove_vertex(dead_v);
  const auto first = m.tetrahedron(0);
  m.remove_tetrahedron(m.add_tetrahedron(first[0], first[1], first[2], first[3], 7));
  for (const std::uint32_t v : first) m.set_vertex_tetrahedron(v, 0);
  m.check();
  const MeshData3 before = m.domain();
  std::vector<std::uint32_t> vorder, torder;
  for (std::uint32_t v = m.vertex_capacity(); v-- > 0;)
    if (!m.is_dead_vertex(v)) vorder.push_back(v);
  for (std::uint32_t t = m.tetrahedron_capacity(); t-- > 0;)
    if (m.is_alive(t)) torder.push_back(t);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> constrained;
  for (std::uint32_t a = 0; a < m.vertex_capacity(); ++a)
    for (std::uint32_t b = a + 1; b < m.vertex_capacity(); ++b)
      if (!m.is_dead_vertex(a) && !m.is_dead_vertex(b) && m.is_constrained_edge(a, b)) constrained.emplace_back(a, b);
  ASSERT_FALSE(constrained.empty());
  const std::uint32_t live_v = m.live_vertex_count(), live_t = m.live_tetrahedron_count();
  std::vector<std::uint8_t> flags;
  std::vector<Vec3> points;
  for (std::uint32_t v = 0; v < m.vertex_capacity(); ++v) {
    flags.push_back(m.flags(v));
    points.push_back(m.point(v));
  }
  m.renumber(vorder, torder);
  m.check();
  EXPECT_EQ(m.vertex_capacity(), live_v);
  EXPECT_EQ(m.tetrahedron_capacity(), live_t);
  const MeshData3 after = m.domain();
  EXPECT_EQ(geometry(after, false), geometry(before, false));
  EXPECT_EQ(geometry(after, true), geometry(before, true));
  // Vertex vorder[k] is k now: its constrained edges moved with it, and no other pair is one.
  std::vector<std::uint32_t> new_of(vorder.size() + 1, Mesh3::kNone);
  for (std::uint32_t k = 0; k < vorder.size(); ++k) new_of[vorder[k]] = k;
  for (const auto& [a, b] : constrained) EXPECT_TRUE(m.is_constrained_edge(new_of[a], new_of[b]));
  EXPECT_EQ(m.constrained_edge_count(), constrained.size());
  for (std::uint32_t k = 0; k < vorder.size(); ++k) {
    EXPECT_EQ(m.flags(k), flags[vorder[k]]);
    EXPECT_EQ(m.point(k), points[vorder[k]]);
  }
}

// metrics_all_scalar follows every way a metric enters a slot: set_metric both ways, a new
// vertex, a reused slot, a renumbering that drops a dead slot holding an anisotropic metric.
TEST(Mesh3, MetricsAllScalarFollowsEveryChange) {
  const Metric3 aniso{{1.0, 0.5, 2.0, 0.0, 0.0, 3.0}};
  ASSERT_FALSE(aniso.is_scalar());
  Mesh3 m = mesh3_from_data(cubes({{0, 0, 0}, {1, 0, 0}}, 2));
  EXPECT_TRUE(m.metrics_all_scalar());
  m.set_metric(0, aniso);
  EXPECT_FALSE(m.metrics_all_scalar());
  m.set_metric(0, aniso);  // the same again: still one
  m.set_metric(0, Metric3::isotropic(0.5));
  EXPECT_TRUE(m.metrics_all_scalar());
  const std::uint32_t v = m.add_vertex({9, 9, 9}, aniso);
  EXPECT_FALSE(m.metrics_all_scalar());
  m.remove_vertex(v);  // the dead slot keeps its metric: still counted
  EXPECT_FALSE(m.metrics_all_scalar());
  const std::uint32_t w = m.add_vertex({8, 8, 8}, Metric3::isotropic(1.0));  // reuses the slot
  EXPECT_EQ(w, v);
  EXPECT_TRUE(m.metrics_all_scalar());
  m.set_metric(w, aniso);
  m.remove_vertex(w);
  EXPECT_FALSE(m.metrics_all_scalar());
  std::vector<std::uint32_t> vorder, torder;
  for (std::uint32_t x = 0; x < m.vertex_capacity(); ++x)
    if (!m.is_dead_vertex(x)) vorder.push_back(x);
  for (std::uint32_t t = 0; t < m.tetrahedron_capacity(); ++t)
    if (m.is_alive(t)) torder.push_back(t);
  m.renumber(vorder, torder);  // the dead slot goes
  EXPECT_TRUE(m.metrics_all_scalar());
  m.set_metric(1, aniso);
  EXPECT_FALSE(m.metrics_all_scalar());
  const Mesh3 copy = m;
  EXPECT_FALSE(copy.metrics_all_scalar());
}

TEST(Mesh3, RenumberRefusesWhatIsNoPermutation) {
  Mesh3 m = mesh3_from_data(cubes({{0, 0, 0}}));
  std::vector<std::uint32_t> vorder(m.vertex_capacity()), torder(m.tetrahedron_capacity());
  for (std::uint32_t k = 0; k < vorder.size(); ++k) vorder[k] = k;
  for (std::uint32_t k = 0; k < torder.size(); ++k) torder[k] = k;
  auto twice = vorder;
  twice[1] = twice[0];
  EXPECT_THROW(m.renumber(twice, torder), InputError);
  auto short_list = torder;
  short_list.pop_back();
  EXPECT_THROW(m.renumber(vorder, short_list), InputError);
  auto outside = vorder;
  outside.back() = m.vertex_capacity() + 5;
  EXPECT_THROW(m.renumber(outside, torder), InputError);
  m.renumber(vorder, torder);  // the identity
  m.check();
}

}  // namespace
}  // namespace dtlab
