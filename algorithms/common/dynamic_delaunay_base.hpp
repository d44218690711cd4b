// What DynamicDelaunay2 and DynamicDelaunay3 share (algorithms/delaunay2d/dynamic_delaunay2.hpp,
// algorithms/delaunay3d/dynamic_delaunay3.hpp): the mesh they change, its count of finite
// elements, where the next walk starts, the statistics, and the calls that only read them.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "algorithms/common/dynamic_delaunay_errors.hpp"
#include "algorithms/common/dynamic_delaunay_move.hpp"
#include "kernel/coordinate_range.hpp"

namespace dtlab {

// Derived: the dimension's class (CRTP), with insert(p) and remove(v).
template <class Derived, class Mesh, class Stats, std::size_t kVertices>
class DynamicDelaunayBase {
 public:
  using Element = std::array<std::uint32_t, kVertices>;
  using Point = std::remove_cvref_t<decltype(std::declval<const Mesh&>().point(0))>;

  // remove(v) then insert(p); returns p's id. If p is a live vertex other than v, nothing
  // changes and DuplicatePointError is thrown (dynamic_delaunay_move.hpp).
  std::uint32_t move(std::uint32_t v, const Point& p) {
    return move_vertex(static_cast<Derived&>(*this), mesh_, hint_, v, p);
  }

  // Whether v is a live vertex of the triangulation.
  bool contains(std::uint32_t v) const noexcept { return mesh_.is_live_vertex(v); }
  std::uint32_t vertex_count() const noexcept { return mesh_.live_vertex_count(); }
  const Mesh& mesh() const noexcept { return mesh_; }
  const Stats& stats() const noexcept { return stats_; }
  // The live finite elements (positive: counter-clockwise, positively oriented), vertex ids.
  std::vector<Element> finite_elements() const {
    std::vector<Element> out;
    out.reserve(finite_);
    std::uint32_t capacity;
    if constexpr (kVertices == 3) capacity = mesh_.triangle_capacity();
    else capacity = mesh_.tetrahedron_capacity();
    for (std::uint32_t t = 0; t < capacity; ++t) {
      if (!mesh_.is_alive(t) || mesh_.is_ghost(t)) continue;
      Element e;
      for (std::uint32_t i = 0; i < kVertices; ++i) e[i] = mesh_.vertex(t, i);
      out.push_back(e);
    }
    return out;
  }

 protected:
  // The mesh of a closed triangulation (Triangulation2 / Tetrahedralization3) with `stored`
  // elements, ghosts included, `finite` of them finite.
  template <class Structure>
  void adopt(const Structure& structure, std::size_t stored, std::uint64_t finite) {
    const std::vector<int> refs(stored, 0);
    mesh_ = Mesh(structure, refs, {});
    finite_ = finite;
    hint_ = 0;
  }

  // Where an insertion of p starts: the element holding p, found by a walk from the last change.
  // InputError for a coordinate out of range, DuplicatePointError naming the vertex at p.
  template <class Point>
  std::uint32_t insertion_start(const Point& p) const {
    check_coordinates(std::span<const Point>(&p, 1), "inserted point");
    const auto loc = mesh_.locate(p, hint_);
    if (loc.where == Mesh::Where::Vertex) {
      std::string at = "(" + std::to_string(p.x) + ", " + std::to_string(p.y);
      if constexpr (kVertices == 4) at += ", " + std::to_string(p.z);
      throw DuplicatePointError("inserted point " + at + ") is vertex " + std::to_string(loc.handle) + " already",
                                {loc.handle});
    }
    if constexpr (kVertices == 3) return loc.triangle;
    else return loc.tetrahedron;
  }

  Mesh mesh_;
  std::uint64_t finite_ = 0;  // live finite elements
  std::uint32_t hint_ = 0;    // a live element near the last change, where locate starts
  Stats stats_;
};

}  // namespace dtlab
