// The registries (algorithms/common/registry.hpp) as a newcomer uses them (docs/architecture.md,
// "Where a new X goes"): a copy of a built-in registry with one trivial entry added runs through
// the capability's own entry point and passes its exact checks; names are unique, an unknown
// name is refused naming the known ones, and the built-in tables are what the CLI lists.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "algorithms/constrained2d/registry.hpp"
#include "algorithms/constrained3d/registry.hpp"
#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/delaunay2d/registry.hpp"
#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "algorithms/mesh2d/mesh2d.hpp"
#include "algorithms/mesh2d/registry.hpp"
#include "algorithms/mesh3d/registry.hpp"
#include "algorithms/optimize2d/registry.hpp"
#include "algorithms/optimize3d/registry.hpp"
#include "kernel/error.hpp"
#include "mesh/mesh2_from_data.hpp"
#include "verify/checks2d.hpp"
#include "verify/checks_mesh2d.hpp"
#include "verify/generators/domains2d.hpp"
#include "verify/generators/points2d.hpp"

namespace dtlab {
namespace {

// A "new" Delaunay variant: the first built-in one under another name, counting its calls.
int trivial_calls = 0;
void trivial_delaunay2d(const PreparedPoints2& input, Triangulation2& triangulation) {
  ++trivial_calls;
  delaunay2d_variants().front().run(input, triangulation);
}

TEST(Registry, AddedDelaunayVariantRunsThroughTheApiAndPassesTheExactChecks) {
  Registry<Delaunay2dVariant> variants = delaunay2d_variants();
  variants.add({"trivial", "the incremental variant under another name (registry_test.cpp)", &trivial_delaunay2d});
  ASSERT_EQ(variants.size(), delaunay2d_variants().size() + 1);
  EXPECT_EQ(delaunay2d_variants().find("trivial"), nullptr);  // the built-in table is not touched

  const std::vector<Vec2> points = generate_points2d("uniform", 2000, 7);
  trivial_calls = 0;
  const Delaunay2dResult r = delaunay2d(points, {.algorithm = "trivial", .variants = &variants});
  EXPECT_EQ(trivial_calls, 1);
  const std::vector<TriangleIds> triangles = r.triangulation.finite_triangles();
  EXPECT_TRUE(verify_delaunay2d(points, triangles, r.duplicates).ok);
  const Delaunay2dResult reference = delaunay2d(points, {});
  EXPECT_EQ(canonical_triangle_set(triangles), canonical_triangle_set(reference.triangulation.finite_triangles()));
}

// A "new" field point method: the edge method, counted.
int trivial_mesher_calls = 0;
void trivial_field_points(Mesh2& mesh, const ControlSpace2& control, const Mesh2dOptions& options, Mesh2dStats& stats) {
  ++trivial_mesher_calls;
  insert_edge_points(mesh, control, options, stats);
}

TEST(Registry, AddedFieldPointMethodRunsThroughTheMesher) {
  Registry<FieldPointMethod2> methods = mesh2d_methods();
  methods.add({"trivial", "the edge method under another name (registry_test.cpp)", &trivial_field_points});
  const gen::Domain2 d = gen::square_minus_disc(10);
  Mesh2dOptions options;
  options.method = "trivial";
  options.methods = &methods;
  trivial_mesher_calls = 0;
  const Mesh2dResult r = mesh2d(d.input(), options);
  EXPECT_EQ(trivial_mesher_calls, 1);
  EXPECT_TRUE(check_mesh2d(d.input(), constrained2d(d.input()), r.output).ok);
  EXPECT_GT(r.stats.field_points, 0u);
  // Without the copy the name is unknown, and the message names the known ones.
  options.methods = nullptr;
  try {
    mesh2d(d.input(), options);
    ADD_FAILURE() << "an unknown method was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown field point method 'trivial' (known: edge, front)"), std::string::npos)
        << e.what();
  }
}

// A "new" optimization operator: counts its calls and changes nothing.
int counted_passes = 0;
OperatorResult count_passes(Mesh2&, const Optimize2dOptions&, const MetricField2&, Optimize2dStats&) {
  ++counted_passes;
  return {};
}

TEST(Registry, AddedOptimizationOperatorRunsOnceARoundInItsPlace) {
  Registry<Optimize2dOperator> operators = optimize2d_operators();
  operators.add({"count", "counts its calls, changes nothing (registry_test.cpp)", &count_passes});
  // The unit square toward size 0.2: splits, swaps and relocations over several rounds.
  MeshData2 square;
  square.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  square.triangle_refs = {0, 0};
  square.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  square.edge_refs.assign(4, 1);
  const MetricField2 field = [](const Vec2&) { return Metric2::isotropic(0.2); };
  const auto run = [&](const Optimize2dOptions& options, Optimize2dStats& stats) {
    Mesh2 mesh = mesh2_from_data(square, Metric2::isotropic(0.2));
    stats = optimize2d(mesh, options, field);
    mesh.check();
    return mesh.domain();
  };
  Optimize2dStats plain_stats, counted_stats;
  const MeshData2 plain = run({}, plain_stats);

  Optimize2dOptions options;
  options.operators = &operators;
  for (const Optimize2dOperator& op : optimize2d_operators()) options.sequence.emplace_back(op.name);
  options.sequence.insert(std::find(options.sequence.begin(), options.sequence.end(), "swap"), "count");
  counted_passes = 0;
  const MeshData2 counted = run(options, counted_stats);
  EXPECT_GT(counted_stats.rounds, 1u);
  EXPECT_EQ(counted_passes, static_cast<int>(counted_stats.rounds));
  EXPECT_EQ(counted_stats.rounds, plain_stats.rounds);
  EXPECT_EQ(counted_stats.splits, plain_stats.splits);
  EXPECT_TRUE(counted == plain);
  // Without the copy the name is unknown, and the message names the known ones.
  options.operators = nullptr;
  try {
    (void)run(options, counted_stats);
    ADD_FAILURE() << "an unknown operator was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown optimization operator 'count' (known: bad, collapse"),
              std::string::npos)
        << e.what();
  }
}

TEST(Registry, NamesAreUniqueAndNonEmpty) {
  Registry<Delaunay2dVariant> variants = delaunay2d_variants();
  EXPECT_THROW(variants.add({"incremental", "again", &trivial_delaunay2d}), InputError);
  EXPECT_THROW(variants.add({"", "no name", &trivial_delaunay2d}), InputError);
  EXPECT_EQ(variants.size(), delaunay2d_variants().size());
}

TEST(Registry, BuiltInTablesInOrder) {
  EXPECT_EQ(delaunay2d_variants().names(","), "incremental,divide-conquer,sweep,flip");
  EXPECT_EQ(delaunay3d_variants().names(","), "incremental,flip,divide-conquer,parallel");
  EXPECT_EQ(constrained2d_methods().names(","), "cdt,swap,conforming");
  EXPECT_EQ(constrained3d_methods().names(","), "conforming,recover,cdt");
  EXPECT_EQ(mesh2d_methods().names(","), "edge,front");
  EXPECT_EQ(mesh3d_methods().names(","), "edge");
  EXPECT_EQ(optimize2d_operators().names(","), "bad,collapse,boundary_collapse,split,swap,relocate,valence");
  EXPECT_EQ(optimize3d_operators().names(","), "bad,collapse,split,swap,relocate");
  EXPECT_THROW(delaunay3d_variants().at("no-such"), InputError);
}

}  // namespace
}  // namespace dtlab
