// What the two dynamic Delaunay tests (dynamic_delaunay2_test.cpp, dynamic_delaunay3_test.cpp)
// run alike, over a traits type T of the dimension:
//   T::Point, T::Dynamic (DynamicDelaunay2/3), T::kMinPoints (3 or 4),
//   T::scratch(points, variant, &degenerate)  delaunay*d()'s finite elements (vertex ids) with
//                                     `variant`, and whether it made none,
//   T::variants()                     the registered variants (delaunay*d_variants()).
// Elements are compared as canonical sets of oriented point tuples, independent of numbering.
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <span>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "algorithms/common/dynamic_delaunay_errors.hpp"
#include "kernel/vec.hpp"

namespace dtlab::dynamic_test {

inline bool long_runs() {
  const char* v = std::getenv("DTLAB_LONG");
  return v != nullptr && std::string(v) == "1";
}

// Uniform whatever rapidcheck's current size (inRange scales its range with the size).
inline int int_in(int lo, int hi) { return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(lo, hi + 1)); }

inline bool lex_less(const Vec2& a, const Vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
inline bool lex_less(const Vec3& a, const Vec3& b) {
  return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
}

// An oriented simplex as its points sorted lexicographically and the parity of the permutation
// that sorted them: equal for two simplices iff they have the same points and orientation.
template <class Point, std::size_t K>
struct Simplex {
  std::array<Point, K> points;
  bool odd = false;
  bool operator==(const Simplex&) const = default;
  bool operator<(const Simplex& o) const {
    for (std::size_t k = 0; k < K; ++k) {
      if (lex_less(points[k], o.points[k])) return true;
      if (lex_less(o.points[k], points[k])) return false;
    }
    return odd < o.odd;
  }
};

template <class Point, std::size_t K>
std::vector<Simplex<Point, K>> canonical(std::span<const std::array<std::uint32_t, K>> elements,
                                         const auto& point_of) {
  std::vector<Simplex<Point, K>> out;
  out.reserve(elements.size());
  for (const auto& e : elements) {
    Simplex<Point, K> s;
    for (std::size_t k = 0; k < K; ++k) s.points[k] = point_of(e[k]);
    for (std::size_t i = 1; i < K; ++i)  // insertion sort, counting swaps
      for (std::size_t j = i; j > 0 && lex_less(s.points[j], s.points[j - 1]); --j) {
        std::swap(s.points[j], s.points[j - 1]);
        s.odd = !s.odd;
      }
    out.push_back(s);
  }
  std::sort(out.begin(), out.end());
  return out;
}

template <class T>
auto canonical_set(const typename T::Dynamic& d) {
  const auto elements = d.finite_elements();
  return canonical<typename T::Point>(std::span(elements), [&](std::uint32_t v) { return d.mesh().point(v); });
}

template <class T>
auto from_scratch(const std::vector<typename T::Point>& points, const std::string& variant, bool* flat) {
  const auto elements = T::scratch(points, variant, flat);
  return canonical<typename T::Point>(std::span(elements), [&](std::uint32_t v) { return points[v]; });
}

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
  (void)from_scratch<T>(points, "incremental", &flat);
  return flat;
}

// "" or how d differs from the construction from scratch on its survivors by every registered
// variant (the registry is looped, so a new variant is checked without editing the tests).
template <class T>
std::string compare_with_every_variant(const typename T::Dynamic& d) {
  d.mesh().check();
  const auto mine = canonical_set<T>(d);
  std::vector<typename T::Point> points;
  for (const std::uint32_t v : live_vertices(d)) points.push_back(d.mesh().point(v));
  for (const auto& variant : T::variants()) {
    bool flat = false;
    const auto ref = from_scratch<T>(points, std::string(variant.name), &flat);
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
    const auto before = canonical_set<T>(d);
    if (op == 0) {
      if (p_alive) {
        RC_ASSERT_THROWS_AS(d.insert(p), DuplicatePointError);
        RC_ASSERT(canonical_set<T>(d) == before);
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
        RC_ASSERT(canonical_set<T>(d) == before);
      } else if (rest_degenerate && !same) {
        if (op == 1) RC_ASSERT_THROWS_AS(d.remove(v), DegenerateRemovalError);
        else RC_ASSERT_THROWS_AS(d.move(v, p), DegenerateRemovalError);
        RC_ASSERT(canonical_set<T>(d) == before);
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

// The property: a random sequence on points of one of `distributions` made by generate(name, n,
// seed), sizes up to `big` points and `steps` changes.
template <class T, class Generate>
void random_sequence_property(const std::vector<std::string>& distributions, Generate&& generate, int big, int steps) {
  const std::string distribution = *rc::gen::elementOf(distributions);
  const int least = static_cast<int>(T::kMinPoints);
  const auto n = static_cast<std::size_t>(int_in(least, big));
  const auto initial = static_cast<std::size_t>(int_in(least, big));
  const auto changes = static_cast<std::size_t>(int_in(1, steps));
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 30);
  RC_TAG(distribution);
  run_sequence<T>(distinct(generate(distribution, n, seed)), initial, changes, seed);
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
