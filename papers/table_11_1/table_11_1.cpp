// Book §11.4.1, Tables 11.1 and 11.2: a straight segment meshed under a discrete size map
// (linear, geometric and sinusoidal interpolation, Figs. 11.16-11.18) and under a discrete
// metric map (Fig. 11.19). Prints, for each, the map length L, the number of sub-segments
// n = round(L), their map length L / n and their extreme Euclidean lengths, beside the book's.
// Exit status 1 when a sub-segment's map length differs from L / n by more than 1e-9 L.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "algorithms/surface/curve3.hpp"

using namespace dtlab;

namespace {

bool report(const char* name, const CurveMesh& mesh) {
  double lo = 1e300, hi = 0.0;
  for (std::size_t k = 1; k < mesh.points.size(); ++k) {
    const double d = norm(mesh.points[k] - mesh.points[k - 1]);
    lo = std::min(lo, d), hi = std::max(hi, d);
  }
  const auto n = mesh.lengths.size();
  bool ok = true;
  for (const double l : mesh.lengths) ok = ok && std::abs(l - mesh.map_length / n) <= 1e-9 * mesh.map_length;
  std::printf("| %-11s | %8.4f | %3zu | %.6f | %.4f | %.4f | figure only |%s\n", name, mesh.map_length, n,
              mesh.map_length / n, lo, hi, ok ? "" : "  <- a sub-segment off L / n");
  return ok;
}

}  // namespace

int main() {
  const Curve3 segment = Curve3::segment({0, 0, 0}, {10, 0, 0});
  std::printf("Table 11.1: s = 0, 3, 4, 8, 10 with h = 1.5, 0.5, 2.0, 0.1, 0.7 on [Q1, Q5] (length 10)\n\n");
  std::printf("| interpolation | L | n | L / n | shortest | longest | book's n |\n|---|---|---|---|---|---|---|\n");
  bool ok = true;
  const std::pair<const char*, SizeInterpolation> modes[] = {
      {"linear", SizeInterpolation::Linear}, {"geometric", SizeInterpolation::Geometric}, {"sinusoidal", SizeInterpolation::Sinusoidal}};
  for (const auto& [name, mode] : modes) {
    CurveMap map;
    map.abscissas = {0, 3, 4, 8, 10};
    map.sizes = {1.5, 0.5, 2.0, 0.1, 0.7};
    map.interpolation = mode;
    ok = report(name, mesh_curve(segment, map)) && ok;
  }
  std::printf("\nTable 11.2: metrics at s = 0, 2, 3, 6 (angle of the first direction, h1, h2) = (30 deg, 0.70, 0.25),\n"
              "(90, 1.10, 0.15), (0, 0.30, 0.30), (-60, 1.50, 0.40) on a segment of length 6 along x\n\n");
  std::printf("| map | L | n | L / n | shortest | longest | book's n |\n|---|---|---|---|---|---|---|\n");
  const double rows[4][4] = {{0, 30, 0.70, 0.25}, {2, 90, 1.10, 0.15}, {3, 0, 0.30, 0.30}, {6, -60, 1.50, 0.40}};
  CurveMap metric;
  for (const auto& r : rows) {
    const double a = r[1] * std::numbers::pi / 180.0;
    metric.abscissas.push_back(r[0]);
    metric.metrics.push_back(Metric3::from_sizes({std::cos(a), std::sin(a), 0}, {-std::sin(a), std::cos(a), 0}, r[2], r[3], 1.0));
  }
  ok = report("anisotropic", mesh_curve(Curve3::segment({0, 0, 0}, {6, 0, 0}), metric)) && ok;
  return ok ? 0 : 1;
}
