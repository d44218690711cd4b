// Constrained tetrahedralization of a piecewise linear complex (book §3.5-§3.7) and the empty
// mesh of its regions (§5.2): the public entry point. One call, any registered method
// (registry.hpp), one result for all.
//
//   dtlab::ConstrainedInput3 in{.points = pts, .triangles = tris};
//   dtlab::Constrained3dResult r = dtlab::constrained3d(in, {.method = "conforming"});
//   for (auto [a, b, c, d] : r.tetrahedra) ...      // positive, vertex ids into r.vertices
//   for (auto [a, b, c] : r.triangles) ...           // the input faces' pieces, r.triangle_refs
//
// The input is checked first, exactly (check_plc, plc_checks.hpp): every failure is an
// InputError naming its items; nothing is repaired.
//
// Steiner points and rounding (ROADMAP.md): every Steiner point is an exact point of an input
// edge (a + t (b - a), t a double in (0, 1)) or of an input triangle (a + s (b - a) + t (c - a),
// s, t doubles), correctly rounded to double (kernel/rounding.hpp); from then on the rounded
// point is the truth. An input edge is then a chain of mesh edges through its Steiner points,
// and an input triangle the union of mesh triangles on its vertices, which triangulate it in
// its own (s, t) parameters exactly; each Steiner point lies within its rounding bound of the
// exact point recorded in `steiner` (checked exactly: rounding_checks_failed stays 0).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/stats.hpp"
#include "kernel/vec.hpp"
#include "mesh/problems/constrained3.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

struct Constrained3dOptions {
  std::string method = "conforming";  // a name from constrained3d_methods()
  bool keep_exterior = false;         // keep the tetrahedra outside every closed surface
  // Drop the cavities: the regions bounded only by shells (edge-connected parts of the input
  // surface) that do not touch the exterior, i.e. nested inside another shell.
  bool remove_cavities = false;
  // The most Steiner points a method may add, as a multiple of (points + triangles); past it
  // constrained3d throws InputError naming the input triangle or edge being recovered.
  std::uint32_t steiner_limit_factor = 200;
};

// Throws InputError for an unknown method, a bad input (check_plc), a reference list of the
// wrong length, a hole or region point out of range, or when the Steiner limit is reached
// (naming the input triangle or edge); InternalError on a broken invariant.
Constrained3dResult constrained3d(const ConstrainedInput3& input, const Constrained3dOptions& options = {});

// The method names, in table order, with a line of description each.
struct Constrained3dMethodInfo {
  std::string_view name;
  std::string_view description;
};
std::vector<Constrained3dMethodInfo> constrained3d_method_list();

}  // namespace dtlab
