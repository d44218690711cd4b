// DynamicDelaunay3 (algorithms/delaunay3d/dynamic_delaunay3.hpp): after any sequence of
// insertions, removals and moves, the finite tetrahedra equal, as a canonical set of point
// tuples, those of delaunay3d() run from scratch on the survivors, for every registered variant
// (the registry is looped), on random and on degenerate generators (grids, exact spheres,
// coplanar and collinear sets). Bad input gets its named error. DTLAB_LONG=1 runs more and
// larger cases.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "algorithms/delaunay3d/dynamic_delaunay3.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "verify/tests/dynamic_delaunay_sequence.hpp"
#include "verify/generators/points3d.hpp"

namespace dtlab {
namespace {

using dynamic_test::long_runs;

const std::vector<std::string>& distributions() {
  static const std::vector<std::string> names{"uniform", "grid", "exact_sphere", "coplanar", "collinear", "duplicates"};
  return names;
}

struct Traits {
  using Point = Vec3;
  using Dynamic = DynamicDelaunay3;
  static constexpr std::size_t kMinPoints = 4;
  static std::vector<std::array<std::uint32_t, 4>> scratch(const std::vector<Vec3>& points,
                                                           const std::string& variant, bool* flat) {
    const Delaunay3dResult r = delaunay3d(points, {.algorithm = variant});
    *flat = !r.degenerate_message.empty();
    return r.tetrahedralization.finite_tetrahedra();
  }
  static const auto& variants() { return delaunay3d_variants(); }
};

std::string compare_with_every_variant(const DynamicDelaunay3& d) { return dynamic_test::compare_with_every_variant<Traits>(d); }
auto canonical_set(const DynamicDelaunay3& d) { return dynamic_test::canonical_set<Traits>(d); }

RC_GTEST_PROP(DynamicDelaunay3, AnySequenceEqualsFromScratch, ()) {
  dynamic_test::random_sequence_property<Traits>(distributions(), generate_points3d, long_runs() ? 300 : 60, long_runs() ? 120 : 25);
}

// Every vertex of a cospherical grid removed in turn, checked after each removal.
TEST(DynamicDelaunay3, GridRemovedToTheEnd) {
  const std::size_t side = long_runs() ? 8 : 4;
  std::vector<Vec3> grid;
  for (std::size_t i = 0; i < side; ++i)
    for (std::size_t j = 0; j < side; ++j)
      for (std::size_t k = 0; k < side; ++k)
        grid.push_back({static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)});
  DynamicDelaunay3 d(grid);
  std::size_t removed = 0, refused = 0;
  EXPECT_EQ(dynamic_test::remove_all_in_turn<Traits>(d, removed, refused), "");
  EXPECT_EQ(d.vertex_count(), grid.size() - removed);
  EXPECT_GE(refused, 1u);
}

// Insert then remove the centre of an exact sphere, then each sphere point in turn.
TEST(DynamicDelaunay3, InsertThenRemoveOnASphere) {
  const std::vector<Vec3> sphere = generate_points3d("exact_sphere", 60, 3);
  DynamicDelaunay3 d(sphere);
  const auto without = canonical_set(d);
  const std::uint32_t centre = d.insert({0.0, 0.0, 0.0});
  EXPECT_EQ(compare_with_every_variant(d), "");
  d.remove(centre);
  EXPECT_EQ(canonical_set(d), without);
  for (std::uint32_t v = 0; v < 30; ++v) {
    const Vec3 p = d.mesh().point(v);
    const auto before = canonical_set(d);
    d.remove(v);
    EXPECT_EQ(compare_with_every_variant(d), "");
    d.insert(p);
    EXPECT_EQ(canonical_set(d), before) << "vertex " << v;
  }
}

// A hull vertex whose link is flat (the apex of a pyramid over a square, a point below): the
// square becomes hull facets, split as the perturbation says.
TEST(DynamicDelaunay3, HullVertexAboveAFlatLink) {
  DynamicDelaunay3 d(std::vector<Vec3>{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 3}, {1, 1, -3}});
  d.remove(4);
  EXPECT_EQ(d.stats().flat_links, 1u);
  EXPECT_EQ(compare_with_every_variant(d), "");
  d.insert({1, 1, 3});
  EXPECT_EQ(compare_with_every_variant(d), "");
  d.remove(5);
  EXPECT_EQ(compare_with_every_variant(d), "");
}

TEST(DynamicDelaunay3, BadInputGetsNamedErrors) {
  const std::vector<Vec3> cube{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  DynamicDelaunay3 d(cube);
  EXPECT_THROW(d.remove(9), UnknownVertexError);
  try {
    d.insert({0, 1, 0});
    ADD_FAILURE() << "duplicate accepted";
  } catch (const DuplicatePointError& e) {
    EXPECT_EQ(e.items(), std::vector<std::uint64_t>{2});
  }
  EXPECT_THROW(d.move(0, {1, 0, 0}), DuplicatePointError);
  d.remove(4);
  EXPECT_THROW(d.remove(4), UnknownVertexError);  // twice
  try {
    d.remove(0);  // would leave three points
    ADD_FAILURE() << "removal to three points accepted";
  } catch (const DegenerateRemovalError& e) {
    EXPECT_EQ(e.items(), std::vector<std::uint64_t>{0});
  }
  EXPECT_EQ(d.finite_tetrahedron_count(), 1u);
  DynamicDelaunay3 flat(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 5}});
  EXPECT_THROW(flat.remove(4), DegenerateRemovalError);  // four coplanar survivors
  EXPECT_EQ(compare_with_every_variant(flat), "");
  EXPECT_THROW(DynamicDelaunay3(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}), DegenerateRemovalError);
  EXPECT_THROW(DynamicDelaunay3(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}}),
               DuplicatePointError);
  EXPECT_THROW(d.insert({std::numeric_limits<double>::quiet_NaN(), 0, 0}), InputError);
}

}  // namespace
}  // namespace dtlab
