// The named errors of the dynamic Delaunay triangulations (DynamicDelaunay2, DynamicDelaunay3):
// each is an InputError whose items() hold the offending vertex ids or point indices, so that a
// caller can tell bad input apart from other failures and report the item.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "kernel/error.hpp"

namespace dtlab {

// remove()/move() of a vertex id that is not a live vertex (never inserted, removed already, or
// out of range). items: {vertex}.
class UnknownVertexError : public InputError {
 public:
  explicit UnknownVertexError(std::uint64_t vertex)
      : InputError("vertex " + std::to_string(vertex) + " is not in the triangulation (never inserted or removed already)",
                   {vertex}) {}
};

// insert() of a point equal to a live vertex, or a construction from points with a repeated
// one. items: {the existing vertex, the repeated input index} (construction) or {the vertex}.
class DuplicatePointError : public InputError {
 public:
  DuplicatePointError(const std::string& what, std::vector<std::uint64_t> items) : InputError(what, std::move(items)) {}
};

// A removal (or a construction) that would leave no triangle (2D: fewer than three points or all
// of them collinear; 3D: no tetrahedron, the points coplanar). The structure is left unchanged.
// items: {vertex} for a removal, empty for a construction.
class DegenerateRemovalError : public InputError {
 public:
  DegenerateRemovalError(const std::string& what, std::vector<std::uint64_t> items) : InputError(what, std::move(items)) {}
};

// The construction's refusals, from the Delaunay call's report (delaunay_call.hpp): a repeated
// point (naming both indices) or no element at all (`element`: "triangle", "tetrahedron").
template <class Report>
void refuse_unusable_start(const Report& r, const char* element) {
  if (!r.duplicates.empty())
    throw DuplicatePointError("point " + std::to_string(r.duplicates[0]) + " repeats point " +
                                  std::to_string(r.duplicate_of[0]),
                              {r.duplicate_of[0], r.duplicates[0]});
  if (!r.degenerate_message.empty())
    throw DegenerateRemovalError(std::string("no ") + element + ": " + r.degenerate_message, {});
}

}  // namespace dtlab
