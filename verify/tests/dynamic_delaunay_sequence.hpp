// What the two dynamic Delaunay tests (dynamic_delaunay2_test.cpp, dynamic_delaunay3_test.cpp)
// run alike, over a traits type T of the dimension:
//   T::Point, T::Dynamic (DynamicDelaunay2/3), T::kMinPoints (3 or 4),
//   T::canonical_set(d)               the finite elements as a canonical set of point tuples,
//   T::from_scratch(points, variant, &degenerate)  the same from delaunay*d() with `variant`,
//   T::variants()                     the registered variants (delaunay*d_variants()).
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "algorithms/common/dynamic_delaunay_errors.hpp"

namespace dtlab::dynamic_test {

inline bool long_runs() {
  const char* v = std::getenv("DTLAB_LONG");
  return v != nullptr && std::string(v) == "1";
}

// Uniform whatever rapidcheck's current size (inRange scales its range with the size).
inline int int_in(int lo, int hi) { return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(lo, hi + 1)); }

// The distinct points of `raw`, in order.
template <class Point>
std::vector<Point> distinct(const std::vector<Point>& raw) {
  std::vector<Point> out;
  for (const Point& p : raw)
    if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
  return out;
}

template <class Dynamic>
std::vector<std::uint32_t> live_vertices(const Dynamic& d) {
  std::vector<std::uint32_t> live;
  for (std::uint32_t v = 0; v < d.mesh().vertex_capacity(); ++v)
    if (d.contains(v)) live.push_back(v);
  return live;
}

// Whether delaunay*d() makes no element of `points`.
template <class T>
bool degenerate(const std::vector<typename T::Point>& points) {
  bool flat = false;
  (void)T::from_scratch(points, "incremental", &flat);
  return flat;
}

// "" or how d differs from the construction from scratch on its survivors by every registered
// variant (the registry is looped, so a new variant is checked without editing the tests).
template <class T>
std::string compare_with_every_variant(const typename T::Dynamic& d) {
  d.mesh().check();
  const auto mine = T::canonical_set(d);
  std::vector<typename T::Point> points;
  for (const std::uint32_t v : live_vertices(d)) points.push_back(d.mesh().point(v));
  for (const auto& variant : T::variants()) {
    bool flat = false;
    const auto ref = T::from_scratch(points, std::string(variant.name), &flat);
    if (flat) return "survivors degenerate for " + std::string(variant.name);
    if (mine != ref)
      return std::to_string(mine.size()) + " elements against " + std::to_string(ref.size()) + " from scratch by " +
             std::string(variant.name) + " on " + std::to_string(points.size()) + " points";
  }
  return "";
}

// One random sequence: start from the first `initial` points, then `steps` random insertions
// (of the points, alive or not), removals and moves, each checked against every variant. Errors
// are accepted only where they are due, and must leave the structure as it was.
template <class T>
void run_sequence(const std::vector<typename T::Point>& points, std::size_t initial, std::size_t steps,
                  std::uint64_t seed) {
  using Point = typename T::Point;
  RC_PRE(points.size() >= T::kMinPoints);
  initial = std::clamp<std::size_t>(initial, T::kMinPoints, points.size());
  const std::vector<Point> start(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(initial));
  if (degenerate<T>(start)) {
    RC_ASSERT_THROWS_AS(typename T::Dynamic{start}, DegenerateRemovalError);
    return;
  }
  typename T::Dynamic d(start);
  RC_ASSERT(compare_with_every_variant<T>(d) == "");
  std::mt19937_64 rng(seed);
  for (std::size_t step = 0; step < steps; ++step) {
    const int op = static_cast<int>(rng() % 3);  // insert, remove, move
    const Point p = points[rng() % points.size()];
    const std::vector<std::uint32_t> live = live_vertices(d);
    const std::uint32_t v = live[rng() % live.size()];
    const bool p_alive = std::any_of(live.begin(), live.end(), [&](std::uint32_t u) { return d.mesh().point(u) == p; });
    const auto before = T::canonical_set(d);
    if (op == 0) {
      if (p_alive) {
        RC_ASSERT_THROWS_AS(d.insert(p), DuplicatePointError);
        RC_ASSERT(T::canonical_set(d) == before);
      } else {
        const std::uint32_t id = d.insert(p);
        RC_ASSERT(d.contains(id) && d.mesh().point(id) == p);
      }
    } else {
      std::vector<Point> rest;
      for (const std::uint32_t u : live)
        if (u != v) rest.push_back(d.mesh().point(u));
      const bool rest_degenerate = rest.size() < T::kMinPoints || degenerate<T>(rest);
      const bool same = op == 2 && d.mesh().point(v) == p;
      const bool duplicate = op == 2 && p_alive && !same;
      if (duplicate) {
        RC_ASSERT_THROWS_AS(d.move(v, p), DuplicatePointError);
        RC_ASSERT(T::canonical_set(d) == before);
      } else if (rest_degenerate && !same) {
        if (op == 1) RC_ASSERT_THROWS_AS(d.remove(v), DegenerateRemovalError);
        else RC_ASSERT_THROWS_AS(d.move(v, p), DegenerateRemovalError);
        RC_ASSERT(T::canonical_set(d) == before);
      } else if (op == 1) {
        d.remove(v);
        RC_ASSERT(!d.contains(v));
      } else {
        const std::uint32_t id = d.move(v, p);
        RC_ASSERT(d.contains(id) && d.mesh().point(id) == p);
      }
    }
    const std::string difference = compare_with_every_variant<T>(d);
    RC_ASSERT(difference == "");
  }
}

// Every vertex removed in a shuffled order, checked after each removal; the removals refused as
// degenerate (the last few points) counted. Returns "" or the first difference.
template <class T>
std::string remove_all_in_turn(typename T::Dynamic& d, std::size_t& removed, std::size_t& refused) {
  std::vector<std::uint32_t> order = live_vertices(d);
  std::shuffle(order.begin(), order.end(), std::mt19937_64(7));
  removed = refused = 0;
  for (const std::uint32_t v : order) {
    try {
      d.remove(v);
      ++removed;
    } catch (const DegenerateRemovalError&) {
      ++refused;
    }
    const std::string difference = compare_with_every_variant<T>(d);
    if (!difference.empty()) return "after removing vertex " + std::to_string(v) + ": " + difference;
  }
  return "";
}

}  // namespace dtlab::dynamic_test
