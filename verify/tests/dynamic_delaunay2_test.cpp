// DynamicDelaunay2 (algorithms/delaunay2d/dynamic_delaunay2.hpp): after any sequence of
// insertions, removals and moves, the finite triangles equal, as a canonical set of point
// tuples, those of delaunay2d() run from scratch on the survivors, for every registered variant
// (the registry is looped, so a new variant is checked without editing this file), on random
// and on degenerate generators (grids, exact circles, collinear runs). Bad input gets its named
// error. DTLAB_LONG=1 runs more and larger cases.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/delaunay2d/dynamic_delaunay2.hpp"
#include "algorithms/delaunay2d/registry.hpp"
#include "verify/tests/dynamic_delaunay_sequence.hpp"
#include "verify/generators/points2d.hpp"

namespace dtlab {
namespace {

using dynamic_test::long_runs;

// The degenerate and random generators the sequences draw their points from.
const std::vector<std::string>& distributions() {
  static const std::vector<std::string> names{"uniform", "grid", "exact_circle", "collinear", "clustered", "duplicates"};
  return names;
}

struct Traits {
  using Point = Vec2;
  using Dynamic = DynamicDelaunay2;
  static constexpr std::size_t kMinPoints = 3;
  static std::vector<std::array<std::uint32_t, 3>> scratch(const std::vector<Vec2>& points,
                                                           const std::string& variant, bool* flat) {
    const Delaunay2dResult r = delaunay2d(points, {.algorithm = variant});
    *flat = !r.degenerate_message.empty();
    return r.triangulation.finite_triangles();
  }
  static const auto& variants() { return delaunay2d_variants(); }
};

std::string compare_with_every_variant(const DynamicDelaunay2& d) { return dynamic_test::compare_with_every_variant<Traits>(d); }
auto canonical_set(const DynamicDelaunay2& d) { return dynamic_test::canonical_set<Traits>(d); }

RC_GTEST_PROP(DynamicDelaunay2, AnySequenceEqualsFromScratch, ()) {
  dynamic_test::random_sequence_property<Traits>(distributions(), generate_points2d, long_runs() ? 400 : 120, long_runs() ? 200 : 40);
}

// Every interior and hull vertex of a cocircular grid removed in turn, checked after each
// removal: the case where the perturbation decides every ear.
TEST(DynamicDelaunay2, GridRemovedToTheEnd) {
  const std::size_t side = long_runs() ? 30 : 12;
  std::vector<Vec2> grid;
  for (std::size_t i = 0; i < side; ++i)
    for (std::size_t j = 0; j < side; ++j) grid.push_back({static_cast<double>(i), static_cast<double>(j)});
  DynamicDelaunay2 d(grid);
  std::size_t removed = 0, refused = 0;
  EXPECT_EQ(dynamic_test::remove_all_in_turn<Traits>(d, removed, refused), "");
  EXPECT_EQ(d.vertex_count(), grid.size() - removed);
  EXPECT_GE(refused, 1u);  // the last three points are never all removed
}

// Insert then remove every point of an exact circle around its centre, and the centre itself.
TEST(DynamicDelaunay2, InsertThenRemoveOnACircle) {
  const std::vector<Vec2> circle = generate_points2d("exact_circle", 64, 3);
  DynamicDelaunay2 d(circle);
  const auto without = canonical_set(d);
  const std::uint32_t centre = d.insert({0.0, 0.0});
  EXPECT_EQ(compare_with_every_variant(d), "");
  d.remove(centre);
  EXPECT_EQ(canonical_set(d), without);
  for (std::uint32_t v = 0; v < 40; ++v) {
    const Vec2 p = d.mesh().point(v);
    const auto before = canonical_set(d);
    d.remove(v);
    EXPECT_EQ(compare_with_every_variant(d), "");
    const std::uint32_t back = d.insert(p);
    EXPECT_EQ(canonical_set(d), before) << "vertex " << v << " back as " << back;
  }
}

TEST(DynamicDelaunay2, BadInputGetsNamedErrors) {
  const std::vector<Vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  DynamicDelaunay2 d(square);
  EXPECT_THROW(d.remove(9), UnknownVertexError);
  try {
    d.insert({1, 1});
    ADD_FAILURE() << "duplicate accepted";
  } catch (const DuplicatePointError& e) {
    EXPECT_EQ(e.items(), std::vector<std::uint64_t>{2});
  }
  EXPECT_THROW(d.move(0, {1, 0}), DuplicatePointError);
  d.remove(3);
  EXPECT_THROW(d.remove(3), UnknownVertexError);  // twice
  try {
    d.remove(0);  // would leave two points
    ADD_FAILURE() << "removal to two points accepted";
  } catch (const DegenerateRemovalError& e) {
    EXPECT_EQ(e.items(), std::vector<std::uint64_t>{0});
  }
  EXPECT_EQ(d.finite_triangle_count(), 1u);
  // Three collinear survivors: refused too.
  DynamicDelaunay2 line(std::vector<Vec2>{{0, 0}, {1, 0}, {2, 0}, {1, 5}});
  EXPECT_THROW(line.remove(3), DegenerateRemovalError);
  EXPECT_EQ(compare_with_every_variant(line), "");
  EXPECT_THROW(DynamicDelaunay2(std::vector<Vec2>{{0, 0}, {1, 0}, {2, 0}}), DegenerateRemovalError);
  EXPECT_THROW(DynamicDelaunay2(std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}, {1, 0}}), DuplicatePointError);
  EXPECT_THROW(d.insert({std::numeric_limits<double>::quiet_NaN(), 0}), InputError);
}

}  // namespace
}  // namespace dtlab
