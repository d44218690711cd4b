// What a constrained3d method works on (registry.hpp): the input's edges and triangles as
// chains and vertex sets that grow with the Steiner points, the Delaunay tetrahedralization, and
// the bookkeeping every method shares (recovery.hpp).
//
// Parameters, the exact model of a constraint (constrained3d.hpp): vertex x of input edge (a, b)
// is the rounding of a + t (b - a), t in [0, 1] a double; vertex x of input triangle (A, B, C)
// the rounding of A + s (B - A) + t (C - A). Corners: A = (0, 0), B = (1, 0), C = (0, 1), so
// that counter-clockwise in (s, t) is the input triangle's own turn.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "algorithms/constrained3d/constrained3d.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

struct ConstraintEdge3 {
  std::uint32_t a = 0, b = 0;          // input vertex ids, a < b
  std::uint32_t face = 0;              // one input triangle on it (for messages and records)
  std::vector<std::uint32_t> chain;    // vertex ids from a to b
  std::vector<double> t;               // their parameters, increasing from 0 to 1
};

struct ConstraintFacet3 {
  std::array<std::uint32_t, 3> corners{};  // A, B, C in input order
  // Edge k runs from corner k to corner k + 1 (mod 3): the input edge and whether it is
  // stored the other way round (b to a).
  std::array<std::uint32_t, 3> edges{};
  std::array<bool, 3> reversed{};
  std::vector<std::uint32_t> interior;               // Steiner points inside the triangle
  std::vector<std::array<double, 2>> interior_st;    // their (s, t)
  std::vector<std::array<std::uint32_t, 3>> pieces;  // once recovered: mesh faces, input turn
  std::size_t pieces_vertex_count = 0;               // vertices on the triangle when they were found
  int ref = 0;
};

struct Constrained3dContext {
  Tetrahedralization3 mesh;  // Delaunay of every vertex so far (input first, then Steiner)
  std::uint32_t input_point_count = 0;
  std::vector<ConstraintEdge3> edges;
  std::vector<ConstraintFacet3> facets;
  std::vector<SteinerPoint3> steiner;  // steiner[i] is vertex input_point_count + i
  std::uint32_t steiner_limit = 0;
  std::uint32_t rounds = 0;
  std::uint32_t rounding_checks_failed = 0;  // Steiner points off their rounding bound (must stay 0)
  double edge_seconds = 0, face_seconds = 0;
  // Vertices of tetrahedra that recovery's transformations made; elsewhere the mesh is the
  // Delaunay tetrahedralization, locally Delaunay (method cdt's flips start at these).
  std::vector<std::uint8_t> changed;
  bool keep_exterior = false;         // the output keeps the exterior region (Constrained3dOptions)
  bool constrained_delaunay = false;  // the method made a CDT (Constrained3dResult)
  std::vector<std::string> messages;  // what the method did that the user should know (Constrained3dResult)
};

}  // namespace dtlab
