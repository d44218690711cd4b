// The CGAL side of predicates_bench (predicates_cgal.cpp, built only when CGAL is found): the
// same cases through CGAL's Exact_predicates_inexact_constructions_kernel, registered as
// "<predicate>/cgal_epick/<distribution>".
#pragma once

#include "bench/predicate_inputs.hpp"

namespace dtlab::bench {

const char* cgal_version();
void register_cgal_orient2d(Dist d);
void register_cgal_incircle(Dist d);
void register_cgal_orient3d(Dist d);
void register_cgal_insphere(Dist d);

}  // namespace dtlab::bench
