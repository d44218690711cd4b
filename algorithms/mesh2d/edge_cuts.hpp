// Cutting an edge into sub-edges of metric length close to 1 (book §7.5-§7.6): shared by the
// edge method (field points) and the boundary resampling.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace dtlab {

// Parameters t_1..t_{n-1} in (0, 1) of the points cutting an edge into n sub-edges of equal
// metric length, for a size varying linearly from ha (at t = 0) to hb (at t = 1) along it:
// h(t_k) = ha (hb/ha)^(k/n), a geometric progression of the sizes.
void cut_points(double ha, double hb, std::uint32_t n, std::vector<double>& out);

// The edge method's candidates on edge (a, b) of `mesh` (2D or 3D), of metric length `length`
// (at least split_length): n = round(length) sub-edges, the sizes from the ends' metrics along
// the edge; `emit(p)` for each cut point p, `cuts` the scratch of their parameters.
template <class Mesh, class Emit>
void cut_edge(const Mesh& mesh, std::uint32_t a, std::uint32_t b, double length, std::vector<double>& cuts,
              const Emit& emit) {
  const auto pa = mesh.point(a), pb = mesh.point(b);
  const auto ab = pb - pa;
  const double la = mesh.metric(a).length(ab), lb = mesh.metric(b).length(ab);
  const double euclid = norm(ab);
  const std::uint32_t n = static_cast<std::uint32_t>(std::max(1.0, std::round(length)));
  cut_points(euclid / la, euclid / lb, n, cuts);
  for (const double s : cuts) emit(pa + s * ab);
}

}  // namespace dtlab
