// Recovery of the Hessian of a P1 field at the vertices of a triangle or tetrahedron mesh (book
// §12.2: the metric of the interpolation error is built from the second derivatives, which a P1
// field does not have: they are recovered). Two methods, both kept because neither is best
// everywhere (compared in verify/tests/adapt_metric_test.cpp):
//  - double L2 projection: the gradient, constant per element, is projected to the vertices (the
//    mean of the elements' gradients weighted by their measure: the lumped L2 projection), and
//    the same is done to each component of that P1 gradient field (Zienkiewicz and Zhu 1992, the
//    "superconvergent patch recovery" family; Frey and Alauzet 2005, §3.1). At boundary vertices
//    the patch is one-sided. On unstructured meshes it converges on average but not pointwise
//    (measured in adapt_metric_test: the mean error halves from h = 0.1 to 0.025, the largest
//    does not fall), since the lumped projection is exact only on symmetric patches.
//  - least squares: a quadratic through the vertex's value fitted to the values of its ring,
//    grown ring by ring (up to the 4-ring) until it has twice the unknowns and full rank:
//    exact for every quadratic field, at the boundary too, and first order pointwise on smooth
//    fields (Frey and Alauzet 2005, §3.2). The default.
// The tensor of a vertex is stored in Medit's order (2D h11, h12, h22; 3D h11, h12, h22, h13,
// h23, h33), as the metrics of kernel/metric.hpp, though a Hessian need not be positive.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

enum class HessianRecovery : std::uint8_t { L2Projection, LeastSquares };

// Throws InputError (numbered from 1) when `values` does not hold one value per point, a value is
// not finite, an element has a vertex out of range or no positive measure (in doubles), or a
// used vertex has too few neighbours for the least-squares fit even in its 4-ring. Unused points
// get a zero tensor.
std::vector<std::array<double, 3>> recover_hessian(std::span<const Vec2> points,
                                                    std::span<const std::array<std::uint32_t, 3>> triangles,
                                                    std::span<const double> values, HessianRecovery method);
std::vector<std::array<double, 6>> recover_hessian(std::span<const Vec3> points,
                                                    std::span<const std::array<std::uint32_t, 4>> tetrahedra,
                                                    std::span<const double> values, HessianRecovery method);

}  // namespace dtlab
