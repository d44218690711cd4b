// The domain of a constrained triangulation (book §5.2): see domain.cpp.
#pragma once

#include <span>

#include "algorithms/constrained2d/context.hpp"

namespace dtlab {

// Fills result.triangles and result.triangle_region from the constrained mesh. Throws InputError
// naming a hole or region seed with a coordinate out of range; seeds outside the hull, or
// (regions) in a removed part, are reported and ignored. A seed on an edge or vertex takes one
// of the triangles there.
void build_domain(const Constrained2dContext& context, std::span<const Vec2> holes,
                  std::span<const RegionSeed2> regions);

}  // namespace dtlab
