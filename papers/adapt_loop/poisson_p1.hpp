// A small P1 finite element solver for the closed adaptive loop (papers/adapt_loop): the Poisson
// problem -Δu = f on a triangle mesh with u = g on its boundary, assembled with the 7-point
// degree-5 rule of Dunavant 1985 ("High degree efficient symmetrical Gaussian quadrature rules
// for the triangle", IJNME 21) for the load, Dirichlet values eliminated, and solved by Eigen's
// sparse LDL^T (the stiffness matrix is symmetric positive definite once the boundary values are
// eliminated). Also the errors the loop plots, by the same rule and by sampling.
#pragma once

#include <functional>
#include <vector>

#include "kernel/vec.hpp"
#include "mesh/io/mesh_data.hpp"

namespace dtlab::paper {

using ScalarField = std::function<double(const Vec2&)>;

// The P1 solution at the vertices. Boundary vertices are those of edges that one triangle only
// has; they take g. Throws InputError when the mesh has no interior vertex or the factorization
// fails (a degenerate mesh).
std::vector<double> solve_poisson(const MeshData2& mesh, const ScalarField& f, const ScalarField& g);

struct FieldErrors {
  double fe_max = 0.0;      // max |u - u_h|, sampled (the finite element error)
  double interp_max = 0.0;  // max |u - Π_h u|, sampled (the P1 interpolation error)
  double fe_l2 = 0.0;       // ||u - u_h||_L2, Dunavant's rule on each triangle
};

// The errors of u_h against the exact u: the maxima over the barycentric lattice of order
// `lattice` in each triangle (its (lattice+1)(lattice+2)/2 points, vertices included).
FieldErrors field_errors(const MeshData2& mesh, const std::vector<double>& uh, const ScalarField& u, int lattice = 8);

}  // namespace dtlab::paper
