// Tests of the exact intersection tests (kernel/intersections.hpp) and of the PLC input checks
// (algorithms/constrained3d/plc/plc_checks.hpp): closed surfaces pass; open, self-intersecting,
// duplicated and degenerate ones are refused naming their items; every touching case of two
// faces (shared edge, shared vertex, coplanar overlap, a vertex on another face) is decided
// exactly; the grid search finds the same pairs as all pairs.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <string>
#include <vector>

#include "algorithms/constrained3d/plc/plc_checks.hpp"
#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "kernel/error.hpp"
#include "kernel/intersections.hpp"

namespace dtlab {
namespace {

struct Surface {
  std::vector<Vec3> points;
  std::vector<Face3> faces;
};

// The unit cube, 12 faces oriented outwards.
Surface cube(Vec3 o = {0, 0, 0}, double s = 1.0) {
  Surface c;
  for (int i = 0; i < 8; ++i) c.points.push_back({o.x + s * (i & 1), o.y + s * ((i >> 1) & 1), o.z + s * ((i >> 2) & 1)});
  c.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
             {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return c;
}

Surface join(const Surface& a, const Surface& b) {
  Surface out = a;
  const auto offset = static_cast<std::uint32_t>(a.points.size());
  out.points.insert(out.points.end(), b.points.begin(), b.points.end());
  for (Face3 f : b.faces) out.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  return out;
}

// The hull of random points as a closed surface (from the 3D Delaunay ghosts).
Surface hull_of_random_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> pts(n);
  for (Vec3& p : pts) p = {u(rng), u(rng), u(rng)};
  const Delaunay3dResult r = delaunay3d(pts);
  Surface s{pts, {}};
  const auto& T = r.tetrahedralization;
  for (std::uint32_t t = 0; t < T.tetrahedron_count(); ++t)
    if (T.is_ghost(t)) s.faces.push_back(T.facet_vertices(4 * t));
  return s;
}

std::string error_of(const Surface& s) {
  try {
    check_plc(s.points, s.faces);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Intersections, SegmentsInThePlane) {
  EXPECT_TRUE(segments_intersect2({0, 0}, {2, 2}, {0, 2}, {2, 0}));
  EXPECT_TRUE(segments_intersect2({0, 0}, {2, 2}, {1, 1}, {5, 0}));    // endpoint on the other
  EXPECT_TRUE(segments_intersect2({0, 0}, {2, 0}, {1, 0}, {3, 0}));    // collinear overlap
  EXPECT_TRUE(segments_intersect2({0, 0}, {2, 0}, {2, 0}, {3, 0}));    // collinear, touching
  EXPECT_FALSE(segments_intersect2({0, 0}, {2, 0}, {2.5, 0}, {3, 0}));  // collinear, apart
  EXPECT_FALSE(segments_intersect2({0, 0}, {1, 1}, {0, 1}, {0.4, 0.6}));
  // One ulp off the other's endpoint.
  EXPECT_FALSE(segments_intersect2({0, 0}, {1, 0}, {0.5, std::nextafter(0.0, 1.0)}, {0.5, 1}));
}

TEST(Intersections, SegmentAndTriangle) {
  const Vec3 a{0, 0, 0}, b{4, 0, 0}, c{0, 4, 0};
  EXPECT_TRUE(segment_meets_triangle3({1, 1, -1}, {1, 1, 1}, a, b, c));   // pierces
  EXPECT_TRUE(segment_meets_triangle3({1, 1, 0}, {1, 1, 1}, a, b, c));    // endpoint inside
  EXPECT_TRUE(segment_meets_triangle3({2, 2, -1}, {2, 2, 1}, a, b, c));   // through the edge bc
  EXPECT_TRUE(segment_meets_triangle3({0, 0, -1}, {0, 0, 1}, a, b, c));   // through a vertex
  EXPECT_FALSE(segment_meets_triangle3({3, 3, -1}, {3, 3, 1}, a, b, c));  // beside it
  EXPECT_FALSE(segment_meets_triangle3({1, 1, 0.5}, {1, 1, 1}, a, b, c)); // above it
  EXPECT_TRUE(segment_meets_triangle3({-1, 1, 0}, {5, 1, 0}, a, b, c));   // coplanar, across
  EXPECT_FALSE(segment_meets_triangle3({3, 3, 0}, {5, 1, 0}, a, b, c));   // coplanar, beside
  const double off = std::nextafter(2.0, 3.0);
  EXPECT_FALSE(segment_meets_triangle3({off, 2, -1}, {off, 2, 1}, a, b, c));  // one ulp outside bc
}

TEST(PlcChecks, ClosedSurfacesPass) {
  EXPECT_EQ(error_of(cube()), "");
  EXPECT_EQ(error_of(join(cube(), cube({3, 0, 0}))), "");
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    const Surface s = hull_of_random_points(3000, seed);
    ASSERT_GT(s.faces.size(), 100u);
    EXPECT_EQ(error_of(s), "") << seed;
  }
}

TEST(PlcChecks, OpenSurfaceNamesItsFreeEdges) {
  Surface s = cube();
  s.faces.pop_back();  // face (3, 7, 5) leaves edges 3-7, 7-5, 5-3 (4-8, 8-6, 6-4 from 1)
  const std::string e = error_of(s);
  EXPECT_NE(e.find("open"), std::string::npos) << e;
  EXPECT_NE(e.find("3 free edge"), std::string::npos) << e;
  EXPECT_NE(e.find("4-8"), std::string::npos) << e;
  const PlcReport r = inspect_plc(s.points, s.faces);
  EXPECT_EQ(r.free_edges.size(), 3u);
}

TEST(PlcChecks, FaceNamesSayWhichFacetATriangleWasCutFrom) {
  Surface s = join(cube(), cube({0.5, 0.25, 0.25}));
  const FaceNamer name = [](std::uint32_t f) { return "quadrilateral " + std::to_string(f / 2 + 1); };
  try {
    check_plc(s.points, s.faces, name);
    ADD_FAILURE() << "interpenetrating cubes passed";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("vertex: quadrilateral 2 and quadrilateral 9, quadrilateral 2 and quadrilateral 9, "
                        "quadrilateral 2 and quadrilateral 11"),
              std::string::npos)
        << what;
  }
  s = cube();
  s.faces.push_back(s.faces[3]);
  EXPECT_NE(error_of(s).find("faces 4 and 13"), std::string::npos) << error_of(s);
  try {
    check_plc(s.points, s.faces, name);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("duplicate face pair(s): quadrilateral 2 and quadrilateral 7"), std::string::npos)
        << e.what();
  }
}

TEST(PlcChecks, InterpenetratingCubesNameTheFaces) {
  const Surface s = join(cube(), cube({0.5, 0.25, 0.25}));
  const PlcReport r = inspect_plc(s.points, s.faces);
  ASSERT_FALSE(r.intersecting_faces.empty());
  for (const auto& [f, g] : r.intersecting_faces) {
    EXPECT_LT(f, 12u);  // one face of each cube
    EXPECT_GE(g, 12u);
  }
  EXPECT_NE(error_of(s).find("intersects itself"), std::string::npos);
}

TEST(PlcChecks, TouchingCases) {
  Surface s;
  s.points = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}, {1, 1, 2}, {5, 5, 0}, {0, -4, 0}, {2, 2, 3}, {4, 4, 0}};
  const auto bad = [&](Face3 f, Face3 g) { return faces_intersect_improperly(s.points, f, g); };
  EXPECT_FALSE(bad({0, 1, 2}, {0, 1, 6}));  // coplanar, across the shared edge
  EXPECT_TRUE(bad({0, 1, 2}, {0, 1, 3}));   // coplanar, folded onto each other
  EXPECT_FALSE(bad({0, 1, 2}, {0, 1, 4}));  // a dihedral angle
  EXPECT_TRUE(bad({0, 1, 2}, {3, 4, 7}));   // a vertex in the other's interior
  EXPECT_TRUE(bad({0, 1, 2}, {0, 3, 4}));   // shared vertex, and an edge lies on the face
  EXPECT_FALSE(bad({0, 1, 2}, {0, 6, 4}));  // shared vertex only
  EXPECT_TRUE(bad({0, 1, 2}, {1, 2, 5}) == false);  // coplanar across edge 1-2 (5,5 is beyond)
  EXPECT_TRUE(bad({0, 1, 2}, {1, 8, 2}) == false);  // shares edge 1-2, on the other side
}

// Coplanar neighbours on a flat face, where an edge line of one separates most pairs before any
// segment test: the cases where it must not (a vertex on an edge, overlaps) and where a shared
// vertex or a collinear vertex beyond an edge leaves the line unable to separate strictly.
TEST(PlcChecks, CoplanarNeighboursOnAFlatFace) {
  Surface s;
  s.points = {{0, 0, 5}, {4, 0, 5}, {0, 4, 5}, {2, 0, 5}, {3, -2, 5}, {1, -2, 5}, {6, 0, 5},
              {8, 0, 5}, {7, 3, 5}, {-1, -1, 5}, {-2, 1, 5}, {1, 1, 5}, {5, 1, 5}, {1, -1, 5}};
  const auto bad = [&](Face3 f, Face3 g) {
    const bool r = faces_intersect_improperly(s.points, f, g);
    EXPECT_EQ(faces_intersect_improperly(s.points, g, f), r);
    return r;
  };
  EXPECT_TRUE(bad({0, 1, 2}, {3, 4, 5}));    // a vertex on the other's edge (a T-junction)
  EXPECT_FALSE(bad({0, 1, 2}, {6, 7, 8}));   // disjoint, on the extension of an edge
  EXPECT_FALSE(bad({0, 1, 2}, {0, 9, 10}));  // a shared vertex only
  EXPECT_FALSE(bad({0, 1, 2}, {1, 6, 4}));   // a shared vertex, the other's edge along the line
  EXPECT_TRUE(bad({0, 1, 2}, {0, 13, 11}));  // a shared vertex and an overlap
  EXPECT_TRUE(bad({0, 1, 2}, {12, 11, 8}));  // an edge crossing the other's interior
}

TEST(PlcChecks, DuplicatesAndDegenerateFaces) {
  Surface s = cube();
  s.points.push_back(s.points[7]);  // vertex 9 = vertex 8
  s.faces[11] = {3, 8, 5};
  s.faces.push_back({3, 7, 8});
  EXPECT_NE(error_of(s).find("vertices 8 and 9"), std::string::npos) << error_of(s);

  Surface d = cube();
  d.points.push_back({0.5, 0, 0});  // on the edge 1-2
  d.faces.push_back({0, 1, 8});
  EXPECT_NE(error_of(d).find("degenerate face(s) (zero area: repeated or collinear vertices): face(s) 13"),
            std::string::npos)
      << error_of(d);

  Surface twice = cube();
  twice.faces.push_back({2, 1, 0});
  EXPECT_NE(error_of(twice).find("faces 1 and 13"), std::string::npos) << error_of(twice);

  Surface out_of_range = cube();
  out_of_range.faces[3][1] = 8;
  EXPECT_THROW(check_plc(out_of_range.points, out_of_range.faces), InputError);
}

TEST(PlcChecks, InternalFaceEdgesAreListedNotRefused) {
  // Two cubes sharing a face: the shared face is stored once, as an internal face; its four
  // edges lie on three faces... no: a box split by an internal square.
  Surface s;
  for (int i = 0; i < 12; ++i) s.points.push_back({double(i % 3), double((i / 3) % 2), double(i / 6)});
  // Box [0,2]x[0,1]x[0,1] with the internal square x = 1.
  auto id = [](int x, int y, int z) { return static_cast<std::uint32_t>(x + 3 * y + 6 * z); };
  for (int x = 0; x < 2; ++x) {
    s.faces.push_back({id(x, 0, 0), id(x, 1, 0), id(x + 1, 0, 0)});
    s.faces.push_back({id(x + 1, 0, 0), id(x, 1, 0), id(x + 1, 1, 0)});
    s.faces.push_back({id(x, 0, 1), id(x + 1, 0, 1), id(x, 1, 1)});
    s.faces.push_back({id(x + 1, 0, 1), id(x + 1, 1, 1), id(x, 1, 1)});
    s.faces.push_back({id(x, 0, 0), id(x + 1, 0, 0), id(x, 0, 1)});
    s.faces.push_back({id(x + 1, 0, 0), id(x + 1, 0, 1), id(x, 0, 1)});
    s.faces.push_back({id(x, 1, 0), id(x, 1, 1), id(x + 1, 1, 0)});
    s.faces.push_back({id(x + 1, 1, 0), id(x, 1, 1), id(x + 1, 1, 1)});
  }
  for (int x = 0; x <= 2; ++x) {
    s.faces.push_back({id(x, 0, 0), id(x, 0, 1), id(x, 1, 0)});
    s.faces.push_back({id(x, 1, 0), id(x, 0, 1), id(x, 1, 1)});
  }
  const PlcReport r = inspect_plc(s.points, s.faces);
  EXPECT_TRUE(r.ok()) << error_of(s);
  EXPECT_EQ(r.nonmanifold_edges.size(), 4u);  // the internal square's boundary
}

TEST(PlcChecks, PiercedHullIsFound) {
  Surface s = hull_of_random_points(2000, 7);
  // Push one hull vertex through the far side: its faces now cross others.
  const std::uint32_t v = s.faces[0][0];
  s.points[v] = {-3 * s.points[v].x, -3 * s.points[v].y, -3 * s.points[v].z};
  const PlcReport r = inspect_plc(s.points, s.faces);
  EXPECT_FALSE(r.intersecting_faces.empty());
  // The grid finds exactly the pairs that testing all pairs finds.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> brute;
  for (std::uint32_t f = 0; f < s.faces.size(); ++f)
    for (std::uint32_t g = f + 1; g < s.faces.size(); ++g)
      if (faces_intersect_improperly(s.points, s.faces[f], s.faces[g])) brute.push_back({f, g});
  EXPECT_EQ(r.intersecting_faces, brute);
}

// Small integer coordinates: many touching and coplanar configurations. (elementOf draws
// uniformly whatever RapidCheck's size, unlike inRange.)
Vec3 small_point() {
  static const std::vector<Vec3> grid = [] {
    std::vector<Vec3> g;
    for (int x = -2; x <= 2; ++x)
      for (int y = -2; y <= 2; ++y)
        for (int z = -2; z <= 2; ++z) g.push_back({double(x), double(y), double(z)});
    return g;
  }();
  return *rc::gen::elementOf(grid);
}

RC_GTEST_PROP(PlcChecks, PairTestIsSymmetricAndInvariant, ()) {
  std::vector<Vec3> p;
  for (int i = 0; i < 6; ++i) p.push_back(small_point());
  // Optionally share vertices.
  const int shared = *rc::gen::inRange(0, 3);
  Face3 f{0, 1, 2}, g{3, 4, 5};
  for (int k = 0; k < shared; ++k) g[k] = f[k];
  RC_PRE(!collinear3(p[f[0]], p[f[1]], p[f[2]]) && !collinear3(p[g[0]], p[g[1]], p[g[2]]));
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) RC_PRE(!(p[i] == p[j]));
  const bool r = faces_intersect_improperly(p, f, g);
  RC_ASSERT(faces_intersect_improperly(p, g, f) == r);
  RC_ASSERT(faces_intersect_improperly(p, {f[1], f[2], f[0]}, {g[2], g[1], g[0]}) == r);
  std::vector<Vec3> q = p;  // permute the axes and translate
  for (Vec3& v : q) v = {v.z + 7, v.x - 3, v.y + 0.5};
  RC_ASSERT(faces_intersect_improperly(q, f, g) == r);
}

// The pair test against its definition, without its shortcuts (plane separation, the 2D path
// for coplanar faces): with a shared vertex, the faces meet elsewhere iff the edge of one
// opposite it meets the other; with none, iff an edge of one meets the other (closed sets,
// kernel/intersections.hpp). Points on a small grid, half of the cases in one plane (z = 0),
// where the shortcuts take the 2D path.
RC_GTEST_PROP(PlcChecks, PairTestAgreesWithItsDefinition, ()) {
  const bool flat = *rc::gen::arbitrary<bool>();
  std::vector<Vec3> p;
  for (int i = 0; i < 6; ++i) {
    Vec3 v = small_point();
    if (flat) v.z = 0;
    p.push_back(v);
  }
  const int shared = *rc::gen::inRange(0, 2);
  Face3 f{0, 1, 2}, g{3, 4, 5};
  if (shared == 1) g[*rc::gen::inRange(0, 3)] = f[*rc::gen::inRange(0, 3)];
  RC_PRE(!collinear3(p[f[0]], p[f[1]], p[f[2]]) && !collinear3(p[g[0]], p[g[1]], p[g[2]]));
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) RC_PRE(!(p[i] == p[j]));
  const auto meets = [&](const Face3& a, const Face3& b) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = a[k], v = a[(k + 1) % 3];
      if (std::count(b.begin(), b.end(), u) || std::count(b.begin(), b.end(), v)) continue;  // at the shared vertex
      if (segment_meets_triangle3(p[u], p[v], p[b[0]], p[b[1]], p[b[2]])) return true;
    }
    return false;
  };
  const bool expected = meets(f, g) || meets(g, f);
  RC_ASSERT(faces_intersect_improperly(p, f, g) == expected);
  RC_TAG(expected ? "intersecting" : "apart");
}

}  // namespace
}  // namespace dtlab
