#include "algorithms/shell/polygon_triangulations.hpp"

#include <set>
#include <string>

#include "kernel/error.hpp"

namespace dtlab {

namespace {

// Triangulations of the sub-polygon i, i+1, ..., j (j - i >= 2): the edge (i, j) lies in exactly
// one triangle (i, k, j), i < k < j; the rest triangulates i..k and k..j independently. The
// recursion is depth-first with one shared triangle list, so memory stays O(n).
class Enumerator {
 public:
  // visit returns true to stop; triangle_ok (if any) prunes every triangulation holding a
  // triangle it refuses.
  Enumerator(const std::function<bool(const std::vector<PolygonTriangle>&)>& visit,
             const std::function<bool(const PolygonTriangle&)>* triangle_ok)
      : visit_(visit), triangle_ok_(triangle_ok) {}

  void run(int n) {
    pending_.push_back({0, n - 1});
    step();
  }

 private:
  void step() {
    if (stop_) return;
    if (pending_.empty()) {
      stop_ = visit_(triangles_);
      return;
    }
    const auto [i, j] = pending_.back();
    pending_.pop_back();
    if (j - i < 2) {
      step();
    } else {
      for (int k = i + 1; k < j && !stop_; ++k) {
        const PolygonTriangle t{static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(k), static_cast<std::uint8_t>(j)};
        if (triangle_ok_ != nullptr && !(*triangle_ok_)(t)) continue;
        triangles_.push_back(t);
        pending_.push_back({k, j});
        pending_.push_back({i, k});
        step();
        pending_.pop_back();
        pending_.pop_back();
        triangles_.pop_back();
      }
    }
    pending_.push_back({i, j});
  }

  const std::function<bool(const std::vector<PolygonTriangle>&)>& visit_;
  const std::function<bool(const PolygonTriangle&)>* triangle_ok_;
  std::vector<PolygonTriangle> triangles_;
  std::vector<std::pair<int, int>> pending_;
  bool stop_ = false;
};

void check_polygon_size(int n) {
  if (n < 3 || n > 24) {
    throw InputError("polygon triangulations: n = " + std::to_string(n) + " is outside [3, 24]");
  }
}

}  // namespace

void for_each_polygon_triangulation(int n, const std::function<void(const std::vector<PolygonTriangle>&)>& visit) {
  check_polygon_size(n);
  const std::function<bool(const std::vector<PolygonTriangle>&)> all = [&](const std::vector<PolygonTriangle>& t) {
    visit(t);
    return false;
  };
  Enumerator(all, nullptr).run(n);
}

std::vector<PolygonTriangle> find_polygon_triangulation(int n, const std::function<bool(const PolygonTriangle&)>& triangle_ok,
                                                        const std::function<bool(const std::vector<PolygonTriangle>&)>& accept) {
  check_polygon_size(n);
  std::vector<PolygonTriangle> found;
  const std::function<bool(const std::vector<PolygonTriangle>&)> first = [&](const std::vector<PolygonTriangle>& t) {
    if (!accept(t)) return false;
    found = t;
    return true;
  };
  Enumerator(first, &triangle_ok).run(n);
  return found;
}

PolygonTriangulationCounts count_polygon_triangulations(int n) {
  PolygonTriangulationCounts counts;
  std::set<PolygonTriangle> distinct;
  for_each_polygon_triangulation(n, [&](const std::vector<PolygonTriangle>& triangulation) {
    ++counts.triangulations;
    distinct.insert(triangulation.begin(), triangulation.end());
  });
  counts.distinct_triangles = distinct.size();
  return counts;
}

std::uint64_t catalan_book(int n) {
  if (n < 1 || n > 30) throw InputError("catalan_book: n = " + std::to_string(n) + " is outside [1, 30]");
  // Cat(n) = C_{n-1} (standard numbering), C_{k+1} = C_k * 2(2k + 1) / (k + 2): the division is
  // exact and the product stays below 2^64 for n <= 30 (C_28 * 114 < 1.2e17).
  std::uint64_t c = 1;
  for (int k = 0; k < n - 1; ++k) c = c * 2 * static_cast<std::uint64_t>(2 * k + 1) / static_cast<std::uint64_t>(k + 2);
  return c;
}

}  // namespace dtlab
