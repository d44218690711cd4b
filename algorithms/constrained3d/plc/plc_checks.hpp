// The checks a piecewise linear complex (a triangulated surface plus optional internal faces)
// must pass before a constrained tetrahedralization is built from it (issue 8, "Input"). Each is
// exact, and each failure names its items, because the codes users compare us with do not:
// TetGen 1.5 returns zero tetrahedra with exit status 0 on an open surface and aborts on a
// self-intersecting one. Nothing is repaired.
//
// In order (the first category that fails is the error):
//   1. face vertex ids in range;
//   2. duplicate vertices (equal coordinates), among the vertices the faces use;
//   3. degenerate faces: a repeated vertex, or three collinear vertices (zero area);
//   4. duplicate faces (the same three vertices);
//   5. open boundary: an edge on exactly one face (a "free edge");
//   6. faces that intersect other than along their shared edge or vertex (coplanar overlaps,
//      a face piercing another, two faces crossing, a vertex touching a face's interior).
// Edges on three or more faces are accepted (an internal face meets a shell along them; whether
// each is explained by an internal face is known only once regions are coloured) and listed in
// the report.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

using Face3 = std::array<std::uint32_t, 3>;

struct PlcReport {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicate_vertices;  // (first, later)
  std::vector<std::uint32_t> degenerate_faces;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicate_faces;      // (first, later)
  std::vector<std::array<std::uint32_t, 2>> free_edges;                       // vertex ids, a < b
  std::vector<std::array<std::uint32_t, 2>> nonmanifold_edges;                // on 3 or more faces
  std::vector<std::pair<std::uint32_t, std::uint32_t>> intersecting_faces;   // face ids, a < b
  bool ok() const noexcept {
    return duplicate_vertices.empty() && degenerate_faces.empty() && duplicate_faces.empty() &&
           free_edges.empty() && intersecting_faces.empty();
  }
};

// Runs checks 2-6 and reports every finding (self-intersections only when 2-4 passed, since
// they presuppose proper faces). Throws InputError for check 1 or for a coordinate outside the
// supported range (kernel/coordinate_range.hpp), naming the face or vertex.
PlcReport inspect_plc(std::span<const Vec3> points, std::span<const Face3> faces);

// inspect_plc, then InputError for the first failed category, naming up to 10 of its items
// (vertex and face numbers counted from 1, as in the input files) and how many there are;
// the exception's items() holds them 0-based.
// face_name, where given, names each face in the messages instead of its number: the input item
// it is (the facet a triangle was cut from: facet_triangulation.hpp), e.g. "... meet other than
// along a shared edge or vertex: face 5 and quadrilateral 2 (triangle 1 of 2)".
using FaceNamer = std::function<std::string(std::uint32_t)>;
void check_plc(std::span<const Vec3> points, std::span<const Face3> faces, const FaceNamer& face_name = {});

// The pair-of-faces test behind check 6, for callers that test their own pairs.
bool faces_intersect_improperly(std::span<const Vec3> points, const Face3& f, const Face3& g) noexcept;

}  // namespace dtlab
