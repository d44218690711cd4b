// The enumeration of a convex polygon's triangulations (algorithms/shell): its counts against
// Catalan's numbers, and the pruned search (find_polygon_triangulation) against its definition,
// the first triangulation of the full enumeration whose triangles all pass and that is accepted.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <set>
#include <vector>

#include "algorithms/shell/polygon_triangulations.hpp"
#include "kernel/error.hpp"

namespace dtlab {
namespace {

TEST(PolygonTriangulations, CountsAreCatalanNumbers) {
  for (int n = 3; n <= 11; ++n) {
    std::uint64_t count = 0;
    for_each_polygon_triangulation(n, [&](const std::vector<PolygonTriangle>& t) {
      EXPECT_EQ(t.size(), static_cast<std::size_t>(n - 2));
      ++count;
    });
    EXPECT_EQ(count, catalan_book(n - 1)) << "n = " << n;
  }
}

TEST(PolygonTriangulations, SearchFindsTheFirstAcceptedAndStops) {
  int visits = 0;
  const auto any = [](const PolygonTriangle&) { return true; };
  const auto found = find_polygon_triangulation(8, any, [&](const std::vector<PolygonTriangle>&) { return ++visits == 3; });
  EXPECT_EQ(visits, 3);  // nothing visited after the accepted one
  EXPECT_EQ(found.size(), 6u);
  EXPECT_TRUE(find_polygon_triangulation(6, [](const PolygonTriangle&) { return false; },
                                         [](const std::vector<PolygonTriangle>&) { return true; })
                  .empty());
  EXPECT_THROW(find_polygon_triangulation(2, any, [](const std::vector<PolygonTriangle>&) { return true; }), InputError);
}

// Random refused triangles and a random acceptance (the k-th triangulation it is shown, or
// those holding a given triangle): the pruned search returns what filtering the full enumeration
// gives, and shows accept only triangulations made of allowed triangles.
RC_GTEST_PROP(PolygonTriangulations, PrunedSearchAgreesWithTheFullEnumeration, ()) {
  const int n = *rc::gen::inRange(3, 10);
  const int refuse_per_mille = *rc::gen::inRange(0, 400);
  std::set<PolygonTriangle> refused;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k)
        if (*rc::gen::inRange(0, 1000) < refuse_per_mille)
          refused.insert({static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(j), static_cast<std::uint8_t>(k)});
  const bool by_triangle = *rc::gen::arbitrary<bool>();
  const int kth = *rc::gen::inRange(1, 6);
  const PolygonTriangle wanted{0, static_cast<std::uint8_t>(*rc::gen::inRange(1, n - 1)), static_cast<std::uint8_t>(n - 1)};
  const auto ok = [&](const PolygonTriangle& t) { return refused.count(t) == 0; };
  const auto holds_wanted = [&](const std::vector<PolygonTriangle>& ts) {
    for (const PolygonTriangle& t : ts)
      if (t == wanted) return true;
    return false;
  };

  std::vector<PolygonTriangle> expected;
  int shown = 0;
  for_each_polygon_triangulation(n, [&](const std::vector<PolygonTriangle>& ts) {
    if (!expected.empty()) return;
    for (const PolygonTriangle& t : ts)
      if (!ok(t)) return;
    if (by_triangle ? holds_wanted(ts) : ++shown == kth) expected = ts;
  });

  shown = 0;
  const auto found = find_polygon_triangulation(n, ok, [&](const std::vector<PolygonTriangle>& ts) {
    for (const PolygonTriangle& t : ts) RC_ASSERT(ok(t));
    return by_triangle ? holds_wanted(ts) : ++shown == kth;
  });
  RC_ASSERT(found == expected);
}

}  // namespace
}  // namespace dtlab
