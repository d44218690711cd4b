// The shell transformation n -> 2n - 4 of book §8.3.3: the shell of edge ab (the n tetrahedra
// around it, ring r_0 .. r_{n-1}) is replaced by {T + a, T + b : T in a triangulation of the
// ring}, the triangulation chosen among the Cat(n - 1) of Table 8.1 to minimise the worst Q_K.
// The min-max over triangulations decomposes over the ring's sub-polygons (the triangle on a
// chord splits a polygon into two independent ones), so dynamic programming finds it in O(n^3)
// instead of enumerating (Shewchuk, "Two discrete optimization algorithms for the topological
// improvement of tetrahedral meshes", 2002; the enumeration, algorithms/shell, checks it in the
// tests). n = 3 is the edge removal 3 -> 2, n = 4 the 4 -> 4 swap.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "algorithms/optimize3d/local.hpp"
#include "algorithms/optimize3d/operators.hpp"

namespace dtlab {

using namespace optimize3d_detail;

bool optimize3d_detail::shell_transformation(Mesh3& mesh, std::uint32_t a, std::uint32_t b, double margin,
                                             std::vector<std::uint32_t>* created, std::uint32_t hint,
                                             QualityCache* cache, EpochMemo* memo) {
  // The buffers live across calls: the swap pass asks for hundreds of thousands of shells,
  // nearly all refused, and their allocations cost as much as the dynamic program.
  thread_local std::vector<std::uint32_t> shell, ring, slots;
  thread_local std::vector<NewTetrahedron> fresh;
  thread_local std::vector<std::array<std::uint32_t, 2>> chords, stack;
  // A failure remembered on the hint's edge ab stands while neither a nor b has changed since:
  // a change to the shell (a tetrahedron at ab added or removed, a vertex of it moved: its ball,
  // a and b in it, touched) touches both.
  if (memo && hint != Mesh3::kNone &&
      memo->failed_since(6 * std::size_t{hint} + local_edge(mesh, hint, a, b),
                         std::min(mesh.changed_at(a), mesh.changed_at(b))))
    return false;
  auto remember = [&](bool whole_shell) {
    if (!memo) return false;
    const std::uint64_t epoch = mesh.new_epoch();
    if (whole_shell) {
      for (const std::uint32_t t : shell) memo->record(6 * std::size_t{t} + local_edge(mesh, t, a, b), epoch);
    } else if (hint != Mesh3::kNone) {
      memo->record(6 * std::size_t{hint} + local_edge(mesh, hint, a, b), epoch);
    }
    return false;
  };
  if (!is_free_edge(mesh, a, b, shell, ring, hint)) return remember(false);
  const std::uint32_t n = static_cast<std::uint32_t>(ring.size());
  if (n < 3 || n > kMaxShellSize) return remember(true);
  const double before = cache ? cache->worst(mesh, shell) : worst_quality(mesh, shell);
  const double bound = before * (1.0 - margin);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // The ring turns counter-clockwise seen from b: for i < j < k, (r_i, r_j, r_k, b) and
  // (r_i, r_k, r_j, a) are the two tetrahedra on triangle ijk.
  auto cost = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) {
    const double qb = quality_below(mesh, ring[i], ring[j], ring[k], b, bound);
    if (!(qb < bound)) return kInf;
    return std::max(qb, quality_below(mesh, ring[i], ring[k], ring[j], a, bound));
  };
  // best[i][k]: the min-max over triangulations of the sub-polygon r_i .. r_k; split[i][k] its apex.
  std::array<std::array<double, kMaxShellSize>, kMaxShellSize> best{};
  std::array<std::array<std::uint8_t, kMaxShellSize>, kMaxShellSize> split{};
  for (std::uint32_t len = 2; len < n; ++len) {
    for (std::uint32_t i = 0; i + len < n; ++i) {
      const std::uint32_t k = i + len;
      double value = kInf;
      std::uint8_t apex = 0;
      for (std::uint32_t j = i + 1; j < k; ++j) {
        const double sub = std::max(best[i][j], best[j][k]);
        if (!(sub < value)) continue;
        const double v = std::max(sub, cost(i, j, k));
        if (v < value) {
          value = v;
          apex = static_cast<std::uint8_t>(j);
        }
      }
      best[i][k] = value;
      split[i][k] = apex;
    }
  }
  if (!(best[0][n - 1] < bound)) return remember(true);
  fresh.clear();
  chords.clear();
  stack.assign(1, {0, n - 1});
  const int ref = mesh.ref(shell.front());
  while (!stack.empty()) {
    const auto [i, k] = stack.back();
    stack.pop_back();
    if (k - i < 2) continue;
    const std::uint32_t j = split[i][k];
    fresh.push_back({{ring[i], ring[j], ring[k], b}, ref});
    fresh.push_back({{ring[i], ring[k], ring[j], a}, ref});
    if (j - i >= 2) chords.push_back({ring[i], ring[j]});
    if (k - j >= 2) chords.push_back({ring[j], ring[k]});
    stack.push_back({i, j});
    stack.push_back({j, k});
  }
  // A chord that is already an edge elsewhere would be doubled (possible only on a ring that is
  // not in convex position: the tetrahedra are then positive but overlap a neighbour).
  for (const auto& c : chords)
    if (mesh.find_edge(c[0], c[1]) != Mesh3::kNone) return false;
  replace_tetrahedra(mesh, shell, fresh, slots);
  if (created) *created = slots;
  return true;
}

bool try_shell_transformation(Mesh3& mesh, std::uint32_t a, std::uint32_t b, double margin,
                              std::vector<std::uint32_t>* created, std::uint32_t hint) {
  return shell_transformation(mesh, a, b, margin, created, hint, nullptr, nullptr);
}

}  // namespace dtlab
