// Cutting an edge into sub-edges of metric length close to 1 (book §7.5-§7.6): shared by the
// edge method (field points) and the boundary resampling.
#pragma once

#include <cstdint>
#include <vector>

namespace dtlab {

// Parameters t_1..t_{n-1} in (0, 1) of the points cutting an edge into n sub-edges of equal
// metric length, for a size varying linearly from ha (at t = 0) to hb (at t = 1) along it:
// h(t_k) = ha (hb/ha)^(k/n), a geometric progression of the sizes.
void cut_points(double ha, double hb, std::uint32_t n, std::vector<double>& out);

}  // namespace dtlab
