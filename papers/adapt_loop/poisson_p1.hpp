// A small P1 finite element solver for the closed adaptation loop of book §9 (adapt_loop.cpp):
// -Δu = f on a triangle mesh with u = g on its boundary (every edge with one triangle), the
// stiffness matrix assembled element by element, the Dirichlet rows eliminated symmetrically,
// solved by Eigen's sparse Cholesky (SimplicialLDLT). Plus the errors the loop plots: the P1
// interpolation error and the finite element error of a known solution, in L-infinity (sampled
// on a fine lattice of points in every triangle) and in L2 (a degree-5 quadrature).
#pragma once

#include <functional>
#include <vector>

#include "kernel/vec.hpp"
#include "mesh/io/mesh_data.hpp"

namespace dtlab::papers {

using ScalarField = std::function<double(const Vec2&)>;

// The nodal values of the P1 solution. Throws std::runtime_error when the factorisation fails.
std::vector<double> solve_poisson_p1(const MeshData2& mesh, const ScalarField& f, const ScalarField& g);

struct FieldErrors {
  double linf = 0.0;  // max |u - v_h| over the samples
  double l2 = 0.0;    // (∫ (u - v_h)²)^1/2
};
// The error of the P1 function with nodal values `values` against `u`.
FieldErrors p1_errors(const MeshData2& mesh, const std::vector<double>& values, const ScalarField& u);

}  // namespace dtlab::papers
