// Exact checkers for constrained tetrahedralizations (algorithms/constrained3d), library code
// for the tests and `dtlab constrain --verify` in 3D.
//
// What they prove (book §3.5-§3.7, §5.2; ROADMAP.md "Steiner points and rounding"):
//  - validity: the input points come first, unchanged; the whole tetrahedralization is a closed
//    3-manifold (checks3d.hpp check_topology3) with every finite tetrahedron positive by the
//    exact orient3d in doubles, Delaunay (verify_delaunay3d) for "conforming", constrained
//    Delaunay for "cdt" where it reports one (every facet between two kept tetrahedra that is no
//    piece locally Delaunay: a CDT of the domain it meshes, checks3d.hpp); the kept
//    tetrahedra are some of its tetrahedra, each with one region, and two tetrahedra of
//    different regions (or a kept one and a removed one) meet only across a piece of an input
//    triangle;
//  - faces: every piece is a mesh face on vertices of its input triangle, positive in the
//    triangle's own (s, t) parameters (exact rationals from the Steiner records); the pieces'
//    directed edges cancel except along the triangle's sides, where each runs counter-clockwise,
//    and their (s, t) areas add up to the triangle's exactly. A positive 2-chain whose boundary
//    winds k >= 1 times along the triangle covers it k times, and the area makes k = 1: the
//    pieces triangulate the input triangle exactly;
//  - edges: every input edge is the chain of mesh edges through its Steiner points, in the order
//    of their parameters, which lie strictly inside (0, 1) and are distinct;
//  - Steiner points: each within its rounding bound of the exact point its record names
//    (steiner_point_within_rounding_bound, decided exactly), the counts by kind agree;
//  - volumes: for every bounded region, 6 x the exact sum of its tetrahedra's volumes against
//    6 x the volume the input encloses for it (divergence theorem over the input triangles with
//    the region on one side, each signed by the side it is on): equal in GMP rationals when no
//    Steiner point on those triangles was moved by rounding, else within a bound (each moved
//    point's rounding error times the area of its star, in doubles: a tolerance of a check, not
//    of a decision).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "mesh/problems/constrained3.hpp"
#include "kernel/exact_rational.hpp"
#include "verify/problem_report.hpp"

namespace dtlab {

struct ConstrainedCheckReport3 : ProblemReport {  // ok, problems (each naming its item), problem_count
  std::size_t points = 0;           // input and Steiner
  std::size_t steiner_points = 0;
  std::size_t tetrahedra = 0;       // kept
  std::size_t input_triangles = 0;  // whose cover was checked
  std::size_t pieces = 0;
  std::size_t input_edges = 0;      // whose chain was checked
  std::size_t chain_edges = 0;
  std::size_t regions = 0;          // bounded regions whose volume was checked
  std::size_t exact_volumes = 0;    // of those, compared exactly

  // 6 x the meshed volume of each region (the exterior too when kept), exact.
  std::map<int, Rational> region_volume6;

};

struct ConstrainedCheckOptions3 {
  std::string method = "conforming";  // "conforming": the tetrahedralization must be Delaunay
  bool keep_exterior = false;         // as given to constrained3d: region 0 is then unbounded
  std::uint32_t first_number = 0;     // of points, triangles and tetrahedra in problem texts
};

// All the checks above. `input` is what constrained3d was given.
ConstrainedCheckReport3 check_constrained3d(const ConstrainedInput3& input, const Constrained3dResult& result,
                                            const ConstrainedCheckOptions3& options = {});

// The volume part alone (used by check_constrained3d; needs a result whose pieces passed the
// face check for its figures to mean anything).
void check_region_volumes3(const ConstrainedInput3& input, const Constrained3dResult& result,
                           const ConstrainedCheckOptions3& options, ConstrainedCheckReport3& report);

// {"ok":true,"problem_count":0,"counts":{...},"region_volume6":{"1":"6"},"problems":[...]}
std::string to_json(const ConstrainedCheckReport3& report);
// One summary line, then one problem per line.
std::string to_text(const ConstrainedCheckReport3& report);

}  // namespace dtlab
