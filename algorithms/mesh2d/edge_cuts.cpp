// Cut points along an edge under a linearly varying size (edge_cuts.hpp).
#include "algorithms/mesh2d/edge_cuts.hpp"

#include <algorithm>
#include <cmath>

namespace dtlab {

void cut_points(double ha, double hb, std::uint32_t n, std::vector<double>& out) {
  out.clear();
  const bool uniform = std::fabs(hb - ha) <= 1e-9 * std::max(ha, hb);
  for (std::uint32_t k = 1; k < n; ++k) {
    const double s = static_cast<double>(k) / n;
    out.push_back(uniform ? s : (ha * std::pow(hb / ha, s) - ha) / (hb - ha));
  }
}

}  // namespace dtlab
