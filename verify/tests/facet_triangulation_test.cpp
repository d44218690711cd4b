// Tests of the facet triangulation (algorithms/constrained3d/plc/facet_triangulation.hpp): polygon
// facets (OFF quadrilaterals, TetGen facets of several polygons with holes, Medit
// Quadrilaterals) become triangles in their planes, turned like their polygons, with their
// references; non-planar facets are refused naming the farthest vertex, non-simple polygons and
// crossing polygons by name; coplanar neighbours merge only where asked and allowed; and the
// facets go through every constrained3d method to a result that verifies exactly
// (verify/checks_constrained3d.hpp), CGAL's cube_quad.off (libcgal-demo) included when present.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "algorithms/constrained3d/constrained3d.hpp"
#include "algorithms/constrained3d/plc/facet_triangulation.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/io/surface_input.hpp"
#include "verify/checks_constrained3d.hpp"

namespace dtlab {
namespace {

using Tri = std::array<std::uint32_t, 3>;

template <class F>
void expect_input_error(F&& f, const std::vector<std::string>& parts, std::vector<std::uint64_t> items = {}) {
  try {
    f();
    ADD_FAILURE() << "no InputError (expected '" << parts.front() << "')";
  } catch (const InputError& e) {
    for (const std::string& what : parts)
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << "message '" << e.what() << "' lacks '" << what << "'";
    if (!items.empty()) {
      EXPECT_EQ(e.items(), items) << e.what();
    }
  }
}

// Twice the signed area of triangle t projected by dropping `axis` (exact for small integers).
double area2(const std::vector<Vec3>& P, const Tri& t, int axis) {
  const auto pr = [&](const Vec3& p) { return axis == 0 ? Vec2{p.y, p.z} : axis == 1 ? Vec2{p.z, p.x} : Vec2{p.x, p.y}; };
  const Vec2 a = pr(P[t[0]]), b = pr(P[t[1]]), c = pr(P[t[2]]);
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Every undirected edge of the triangles is on exactly two, turned opposite ways: a closed,
// consistently oriented surface.
bool closed_and_oriented(const std::vector<Tri>& tris) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const Tri& t : tris)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, n] : directed) {
    const auto it = directed.find({e.second, e.first});
    if (n != 1 || it == directed.end() || it->second != 1) return false;
  }
  return !tris.empty();
}

Plc3 quad_cube() { return read_surface(std::string(DTLAB_SOURCE_DIR) + "/data/quad_cube.off").plc; }

// Outward turn: every triangle of a convex solid around `centre` has it on its negative side.
bool all_outward(const std::vector<Vec3>& P, const std::vector<Tri>& tris, const Vec3& centre) {
  return std::all_of(tris.begin(), tris.end(), [&](const Tri& t) {
    return orient3d(P[t[0]], P[t[1]], P[t[2]], centre) == Sign::Negative;
  });
}

TEST(FacetTriangulation, QuadCubeBecomesTwelveOutwardTrianglesWithTheirFacets) {
  Plc3 plc = quad_cube();
  for (std::size_t f = 0; f < plc.facets.size(); ++f) plc.facets[f].marker = static_cast<int>(10 + f);
  const FacetTriangulation t = triangulate_facets(plc);
  ASSERT_EQ(t.triangles.size(), 12u);
  EXPECT_EQ(t.polygon_facets, 6u);
  for (std::size_t i = 0; i < t.triangles.size(); ++i) {
    EXPECT_EQ(t.triangle_facet[i], i / 2);
    EXPECT_EQ(t.triangle_refs[i], static_cast<int>(10 + i / 2));
    // Each triangle's corners are corners of its quadrilateral.
    const auto& q = plc.facets[t.triangle_facet[i]].polygons[0];
    for (const std::uint32_t v : t.triangles[i]) EXPECT_NE(std::find(q.begin(), q.end(), v), q.end());
  }
  EXPECT_TRUE(closed_and_oriented(t.triangles));
  EXPECT_TRUE(all_outward(plc.vertices, t.triangles, {1, 1, 1}));
}

TEST(FacetTriangulation, NonConvexPolygonKeepsItsAreaAndTurnInEveryPlane) {
  // An L-shaped hexagon and a comb (12 corners), in the planes z = 0, x = 3 and y = 2x (tilted),
  // each both ways round.
  const std::vector<std::array<double, 2>> L = {{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}};
  const std::vector<std::array<double, 2>> comb = {{0, 0}, {6, 0}, {6, 3}, {5, 3}, {5, 1}, {4, 1},
                                                   {4, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  const auto planes = std::vector<std::pair<int, std::function<Vec3(double, double)>>>{
      {2, [](double u, double v) { return Vec3{u, v, 0}; }},
      {0, [](double u, double v) { return Vec3{3, u, v}; }},
      {1, [](double u, double v) { return Vec3{u, 2 * u, v}; }}};
  for (const auto& shape : {L, comb})
    for (const auto& [axis, lift] : planes)
      for (const bool reversed : {false, true}) {
        Plc3 plc;
        std::vector<std::uint32_t> polygon;
        for (const auto& [u, v] : shape) {
          polygon.push_back(static_cast<std::uint32_t>(plc.vertices.size()));
          plc.vertices.push_back(lift(u, v));
        }
        if (reversed) std::reverse(polygon.begin(), polygon.end());
        plc.facets = {{{polygon}, {}, 4}};
        const FacetTriangulation t = triangulate_facets(plc);
        ASSERT_EQ(t.triangles.size(), shape.size() - 2);
        double polygon_area = 0, sum = 0;
        for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
          polygon_area += area2(plc.vertices, {polygon[0], polygon[i], polygon[i + 1]}, axis);
        for (const Tri& tri : t.triangles) {
          const double a = area2(plc.vertices, tri, axis);
          EXPECT_EQ(a > 0, polygon_area > 0) << "a triangle turned against its polygon";
          sum += a;
        }
        EXPECT_EQ(sum, polygon_area);
      }
}

TEST(FacetTriangulation, FacetOfTwoPolygonsWithAHoleKeepsTheRingOnly) {
  const SurfaceInput in = read_surface(std::string(DTLAB_SOURCE_DIR) + "/data/box_with_window.poly");
  const FacetTriangulation t = triangulate_facets(in.plc);
  std::size_t ring = 0, window = 0;
  for (std::size_t i = 0; i < t.triangles.size(); ++i) {
    if (t.triangle_refs[i] == 3) {
      ++ring;
      EXPECT_EQ(t.triangle_facet[i], 5u);
      // No triangle of the ring lies inside the window square (1, 3) x (1, 3).
      Vec3 c{0, 0, 0};
      for (const std::uint32_t v : t.triangles[i]) c = c + in.plc.vertices[v];
      EXPECT_FALSE(c.x / 3 > 1 && c.x / 3 < 3 && c.y / 3 > 1 && c.y / 3 < 3);
    }
    window += t.triangle_refs[i] == 7;
  }
  EXPECT_EQ(ring, 8u);  // a square ring on 8 vertices: 8 triangles
  EXPECT_EQ(window, 2u);
  EXPECT_TRUE(closed_and_oriented(t.triangles));
  EXPECT_TRUE(all_outward(in.plc.vertices, t.triangles, {2, 2, 1}));
  // Without the hole point the ring's facet covers the window too: an overlap check_plc names.
  Plc3 no_hole = in.plc;
  no_hole.facets[5].holes.clear();
  EXPECT_EQ(triangulate_facets(no_hole).triangles.size(), 22u);
}

TEST(FacetTriangulation, NonPlanarFacetIsRefusedNamingItsFarthestVertex) {
  Plc3 plc = quad_cube();
  plc.vertices.push_back({2, 2, 2.5});   // vertex 8: far above the top face
  plc.vertices.push_back({0, 2, 2.25});  // vertex 9: above it too, less far
  plc.facets[1].polygons[0] = {4, 5, 6, 8, 9, 7};
  FacetTriangulationOptions o;
  o.facet_name = [](std::size_t f) { return "face " + std::to_string(f); };
  o.first_vertex_number = 0;
  expect_input_error([&] { triangulate_facets(plc, o); },
                     {"face 1 is not planar", "2 of its vertices lie off the plane of vertices 4, 5, 6",
                      "the farthest vertex 8 at distance 0.5"},
                     {1});
  // A quadrilateral a single ulp off its plane is refused just the same (decided exactly).
  Plc3 ulp = quad_cube();
  ulp.vertices[6].z = std::nextafter(2.0, 3.0);
  expect_input_error([&] { triangulate_facets(ulp); }, {"facet 2 is not planar", "the farthest vertex 8 at"}, {1});
}

// Asked for (triangulate_nonplanar), the same non-planar facets are triangulated in their
// projection: the cube stays closed and outward, each triangle's corners are its face's, the
// count and the message say how many facets were.
TEST(FacetTriangulation, NonPlanarFacetTriangulatedInItsProjectionWhereAsked) {
  Plc3 ulp = quad_cube();
  ulp.vertices[6].z = std::nextafter(2.0, 3.0);  // one corner of the top face an ulp off its plane
  Plc3 bent = quad_cube();
  bent.vertices[6].z = 2.25;                      // a quarter off
  for (const Plc3* plc : {&ulp, &bent}) {
    FacetTriangulationOptions o;
    o.triangulate_nonplanar = true;
    const FacetTriangulation t = triangulate_facets(*plc, o);
    EXPECT_EQ(t.triangles.size(), 12u);
    // Vertex 6 moves along z: in the planes of its two side faces, off the top face's.
    EXPECT_EQ(t.nonplanar_facets, 1u);
    ASSERT_FALSE(t.messages.empty());
    EXPECT_NE(t.messages.back().find("1 facet(s) not planar, triangulated in their projection"), std::string::npos);
    for (std::size_t i = 0; i < t.triangles.size(); ++i) {
      const auto& q = plc->facets[t.triangle_facet[i]].polygons[0];
      for (const std::uint32_t v : t.triangles[i]) EXPECT_NE(std::find(q.begin(), q.end(), v), q.end());
    }
    EXPECT_TRUE(closed_and_oriented(t.triangles));
    EXPECT_TRUE(all_outward(plc->vertices, t.triangles, {1, 1, 1}));
  }
  // Planar facets are not counted.
  FacetTriangulationOptions o;
  o.triangulate_nonplanar = true;
  EXPECT_EQ(triangulate_facets(quad_cube(), o).nonplanar_facets, 0u);
}

TEST(FacetTriangulation, NonSimplePolygonsAreRefusedByName) {
  Plc3 plc;
  plc.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 0}, {1, 0, 0}, {3, 1, 0}, {4, 0, 0}};
  const auto facet = [&](std::vector<std::vector<std::uint32_t>> polygons) {
    Plc3 p = plc;
    p.facets = {{std::move(polygons), {}, 0}};
    return p;
  };
  // A bow tie crosses itself.
  expect_input_error([&] { triangulate_facets(facet({{0, 1, 3, 2}})); },
                     {"facet 1 crosses itself: its edges (", "cross (not a simple polygon)"}, {0});
  // A corner on a non-adjacent edge: self-touching.
  expect_input_error([&] { triangulate_facets(facet({{0, 5, 1, 2, 3, 4, 5}})); }, {"facet 1 touches itself: vertex 6 is two of its corners"});
  expect_input_error([&] { triangulate_facets(facet({{0, 1, 2, 5, 3}})); },
                     {"facet 1 touches itself: its edges", "meet (not a simple polygon)"});
  // Folding back along a line (a spike): its edges overlap, and the spike's tip touches an edge.
  expect_input_error([&] { triangulate_facets(facet({{0, 7, 1, 2, 3}})); }, {"facet 1 touches itself: its edges"});
  expect_input_error([&] { triangulate_facets(facet({{0, 1, 5, 3}})); }, {"facet 1 touches itself: its edges"});
  // All corners on one line.
  expect_input_error([&] { triangulate_facets(facet({{0, 5, 1, 7}})); }, {"facet 1 is degenerate: all its vertices lie on one line"});
  expect_input_error([&] { triangulate_facets(facet({{0, 1, 2, 3}, {0, 5, 1}})); },
                     {"facet 1, polygon 2 is degenerate: all its corners lie on one line"});
  // Two polygons of one facet that cross.
  expect_input_error([&] { triangulate_facets(facet({{0, 1, 2, 3}, {4, 7, 6}})); },
                     {"facet 1: its polygons cross each other"});
  // Two vertices at one point.
  plc.vertices.push_back({2, 2, 0});
  expect_input_error([&] { triangulate_facets(facet({{0, 1, 8, 3}, {0, 1, 2}})); },
                     {"facet 1: vertices 3 and 9 are at the same point"});
  expect_input_error([&] { triangulate_facets(facet({{0, 1, 12, 3}})); }, {"vertex 13 is out of range"});
  expect_input_error([&] { triangulate_facets(facet({{0, 1, 2, 3}, {4, 4}})); },
                     {"facet 1, polygon 2 is a segment from vertex 5 to itself"});
  Plc3 nan = facet({{0, 1, 2, 3}});
  nan.vertices[5].y = std::numeric_limits<double>::quiet_NaN();
  expect_input_error([&] { triangulate_facets(nan); }, {"PLC vertex"});
  // Polygons sharing an edge and a segment inside are fine.
  const FacetTriangulation ok = triangulate_facets(facet({{0, 1, 2}, {0, 2, 3}, {0, 4}, {5}}));
  // The square on 4 corners, vertex 6 on its edge and 5 inside (on the diagonal): 5 + 2 - 2 triangles.
  EXPECT_EQ(ok.triangles.size(), 5u);
}

TEST(FacetTriangulation, MergesCoplanarNeighboursOnlyWhereAsked) {
  // The quad cube as 12 triangles, each its own facet; the top two with different references.
  const Plc3 quads = quad_cube();
  Plc3 plc;
  plc.vertices = quads.vertices;
  const FacetTriangulation split = triangulate_facets(quads);
  for (std::size_t i = 0; i < split.triangles.size(); ++i) {
    const Tri& t = split.triangles[i];
    plc.facets.push_back({{{t[0], t[1], t[2]}}, {}, i == 2 ? 5 : 0});
  }
  const FacetTriangulation kept = triangulate_facets(plc);
  EXPECT_EQ(kept.triangles, split.triangles);
  EXPECT_TRUE(kept.merged.empty());
  const FacetTriangulation merged = triangulate_facets(plc, {.merge_coplanar = true, .facet_name = {}, .first_vertex_number = 1});
  EXPECT_EQ(merged.merged.size(), 5u);  // the top pair differs in reference
  EXPECT_EQ(merged.merged_facets, 10u);
  EXPECT_EQ(merged.merged.front(), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(merged.triangles.size(), 12u);
  EXPECT_TRUE(closed_and_oriented(merged.triangles));
  EXPECT_TRUE(all_outward(plc.vertices, merged.triangles, {1, 1, 1}));

  // A face cut into a fan of 4 around its centre, merged, becomes the Delaunay triangulation of
  // its 5 vertices again: 4 triangles, the centre kept.
  Plc3 fan = quads;
  fan.vertices.push_back({1, 1, 2});
  fan.facets[1] = {{{4, 5, 8}}, {}, 0};
  for (const Tri t : {Tri{5, 6, 8}, Tri{6, 7, 8}, Tri{7, 4, 8}}) fan.facets.push_back({{{t[0], t[1], t[2]}}, {}, 0});
  const FacetTriangulation joined = triangulate_facets(fan, {.merge_coplanar = true, .facet_name = {}, .first_vertex_number = 1});
  EXPECT_EQ(joined.triangles.size(), 14u);
  ASSERT_EQ(joined.merged.size(), 1u);
  EXPECT_EQ(joined.merged[0], (std::vector<std::uint32_t>{1, 6, 7, 8}));
  EXPECT_TRUE(closed_and_oriented(joined.triangles));
}

// Every constrained3d method on the facets: a result that verifies exactly, boundary triangles
// with their facets' references.
void expect_every_method_verifies(const Plc3& plc, std::size_t expected_refs) {
  const FacetTriangulation t = triangulate_facets(plc);
  for (const char* method : {"recover", "cdt", "conforming"}) {
    ConstrainedInput3 input{.points = plc.vertices,
                            .triangles = t.triangles,
                            .triangle_refs = t.triangle_refs,
                            .holes = plc.holes,
                            .regions = {}};
    const Constrained3dResult r = constrained3d(input, {.method = method});
    const ConstrainedCheckReport3 c = check_constrained3d(input, r, {.method = method});
    EXPECT_TRUE(c.ok) << method << ": " << to_text(c);
    std::vector<int> refs = r.triangle_refs;
    std::sort(refs.begin(), refs.end());
    refs.erase(std::unique(refs.begin(), refs.end()), refs.end());
    EXPECT_EQ(refs.size(), expected_refs) << method;
  }
}

TEST(FacetTriangulation, EveryMethodMeshesPolygonFacets) {
  Plc3 cube = quad_cube();
  for (std::size_t f = 0; f < cube.facets.size(); ++f) cube.facets[f].marker = static_cast<int>(f + 1);
  expect_every_method_verifies(cube, 6);
  expect_every_method_verifies(read_surface(std::string(DTLAB_SOURCE_DIR) + "/data/box_with_window.poly").plc, 4);
}

TEST(FacetTriangulation, CgalCubeQuad) {
  const char* archive = "/usr/share/doc/libcgal-dev/data.tar.gz";
  if (!std::filesystem::exists(archive)) GTEST_SKIP() << archive << " (Debian package libcgal-demo) is absent";
  const auto dir = std::filesystem::temp_directory_path() / "dtlab_facet_triangulation_test";
  std::filesystem::create_directories(dir);
  const std::string command = "tar -xzf " + std::string(archive) + " -C " + dir.string() + " data/meshes/cube_quad.off";
  if (std::system(command.c_str()) != 0) GTEST_SKIP() << "cube_quad.off is not in " << archive;
  const SurfaceInput in = read_surface((dir / "data" / "meshes" / "cube_quad.off").string());
  const FacetTriangulation t = triangulate_facets(in.plc);
  EXPECT_EQ(t.triangles.size(), 12u);
  EXPECT_TRUE(closed_and_oriented(t.triangles));
  EXPECT_TRUE(all_outward(in.plc.vertices, t.triangles, {0, 0, 0}));
  expect_every_method_verifies(in.plc, 1);
}

// Random star-shaped polygons (corners on distinct lattice directions, gaps under half a turn)
// lifted to a random integer plane: n - 2 triangles, each turned like the polygon, whose
// projected areas add up to the polygon's exactly.
RC_GTEST_PROP(FacetTriangulation, StarShapedPolygonsTriangulateExactly, ()) {
  static const std::array<std::array<int, 2>, 16> kDirections = {{{1, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 1}, {-1, 3},
                                                                  {-1, 1}, {-3, 1}, {-1, 0}, {-3, -1}, {-1, -1},
                                                                  {-1, -3}, {0, -1}, {1, -3}, {1, -1}, {3, -1}}};
  std::vector<int> picked;
  for (int d = 0; d < 16; ++d)
    if (*rc::gen::inRange(0, 3) > 0 || d % 4 == 0) picked.push_back(d);  // every quarter turn kept: gaps < 180 degrees
  const int a = *rc::gen::inRange(-3, 4), b = *rc::gen::inRange(-3, 4);
  const int axis = *rc::gen::inRange(0, 3);
  const bool reversed = *rc::gen::arbitrary<bool>();
  Plc3 plc;
  std::vector<std::uint32_t> polygon;
  for (const int d : picked) {
    const int r = *rc::gen::inRange(1, 6);
    const double u = kDirections[d][0] * r, v = kDirections[d][1] * r, w = a * u + b * v;
    polygon.push_back(static_cast<std::uint32_t>(plc.vertices.size()));
    plc.vertices.push_back(axis == 2 ? Vec3{u, v, w} : axis == 0 ? Vec3{w, u, v} : Vec3{v, w, u});
  }
  if (reversed) std::reverse(polygon.begin(), polygon.end());
  plc.facets = {{{polygon}, {}, 3}};
  const FacetTriangulation t = triangulate_facets(plc);
  RC_ASSERT(t.triangles.size() == polygon.size() - 2);
  double polygon_area = 0, sum = 0;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
    polygon_area += area2(plc.vertices, {polygon[0], polygon[i], polygon[i + 1]}, axis);
  for (const Tri& tri : t.triangles) {
    const double ar = area2(plc.vertices, tri, axis);
    RC_ASSERT((ar > 0) == (polygon_area > 0));
    RC_ASSERT(orient3d(plc.vertices[tri[0]], plc.vertices[tri[1]], plc.vertices[tri[2]],
                       plc.vertices[polygon[0]]) == Sign::Zero);
    sum += ar;
  }
  RC_ASSERT(sum == polygon_area);
  RC_ASSERT(std::all_of(t.triangle_refs.begin(), t.triangle_refs.end(), [](int r) { return r == 3; }));
}

}  // namespace
}  // namespace dtlab
