#include "verify/cgal_constrained2d.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <sstream>
#include <utility>

#include "kernel/error.hpp"
#include "kernel/exact_rational.hpp"
#include "kernel/rounding.hpp"

namespace dtlab {

namespace {

constexpr std::uint32_t kNew = 0xFFFFFFFFu;  // a vertex CGAL created

struct VertexId {
  std::uint32_t id = kNew;
};

template <class Kernel, class Itag>
struct Cdt {
  using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexId, Kernel>;
  using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel>;
  using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
  using Type = CGAL::Constrained_Delaunay_triangulation_2<Kernel, DataStructure, Itag>;
};

using EpickCdt = Cdt<CGAL::Exact_predicates_inexact_constructions_kernel,
                     CGAL::No_constraint_intersection_requiring_constructions_tag>::Type;
using EpeckCdt = Cdt<CGAL::Exact_predicates_exact_constructions_kernel, CGAL::Exact_intersections_tag>::Type;

// The exact value of a CGAL number, correctly rounded: its exact representation printed as
// "num/den" (GMP's and Boost's rationals both print so) and read back into a Rational.
template <class FT>
double rounded(const FT& x) {
  std::ostringstream text;
  text << CGAL::exact(x);
  Rational q;
  if (mpq_set_str(q.get(), text.str().c_str(), 10) != 0) throw InternalError("cannot read CGAL's number " + text.str());
  mpq_canonicalize(q.get());
  return round_to_double(q);
}

double rounded(double x) { return x; }

template <class T>
CgalConstrained2d run(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 2>> segments) {
  using Point = typename T::Point;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  std::vector<std::pair<Point, VertexId>> input;
  input.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    input.emplace_back(Point(points[i].x, points[i].y), VertexId{static_cast<std::uint32_t>(i)});
  T cdt;
  cdt.insert(input.begin(), input.end());
  std::vector<typename T::Vertex_handle> handle(points.size());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) handle[v->info().id] = v;
  // Coincident points: CGAL kept one of them; every index gets that vertex.
  if (cdt.number_of_vertices() != points.size()) {
    std::map<std::pair<double, double>, typename T::Vertex_handle> at;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      at.emplace(std::pair{points[v->info().id].x, points[v->info().id].y}, v);
    for (std::size_t i = 0; i < points.size(); ++i)
      if (handle[i] == typename T::Vertex_handle()) handle[i] = at.at({points[i].x, points[i].y});
  }
  try {
    for (const auto& [a, b] : segments)
      if (handle[a] != handle[b]) cdt.insert_constraint(handle[a], handle[b]);
  } catch (const typename T::Intersection_of_constraints_exception&) {
    throw InputError("cgal_constrained2d: segments cross (give CgalCdtKernel::EpeckExactIntersections)");
  }
  CgalConstrained2d out;
  out.seconds = std::chrono::duration<double>(Clock::now() - start).count();

  // Ids: the smallest input index at a vertex's coordinates; created vertices numbered after the
  // input, in CGAL's order.
  std::map<std::pair<double, double>, std::uint32_t> first;
  if (cdt.number_of_vertices() != points.size())
    for (std::uint32_t i = 0; i < points.size(); ++i) first.emplace(std::pair{points[i].x, points[i].y}, i);
  out.points.assign(points.begin(), points.end());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    std::uint32_t& id = v->info().id;
    if (id == kNew) {
      id = static_cast<std::uint32_t>(out.points.size());
      out.points.push_back({rounded(v->point().x()), rounded(v->point().y())});
      ++out.created_points;
    } else if (!first.empty()) {
      id = first.at({points[id].x, points[id].y});
    }
  }
  if (cdt.dimension() < 2) return out;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    out.triangles.push_back({f->vertex(0)->info().id, f->vertex(1)->info().id, f->vertex(2)->info().id});
    for (int i = 0; i < 3; ++i) {
      if (!f->is_constrained(i)) continue;
      const std::uint32_t a = f->vertex(T::cw(i))->info().id, b = f->vertex(T::ccw(i))->info().id;
      out.constrained_edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(out.constrained_edges.begin(), out.constrained_edges.end());
  out.constrained_edges.erase(std::unique(out.constrained_edges.begin(), out.constrained_edges.end()),
                              out.constrained_edges.end());
  return out;
}

}  // namespace

CgalConstrained2d cgal_constrained2d(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 2>> segments,
                                     CgalCdtKernel kernel) {
  for (std::size_t k = 0; k < segments.size(); ++k)
    if (segments[k][0] >= points.size() || segments[k][1] >= points.size())
      throw InputError("cgal_constrained2d: segment " + std::to_string(k) + " has an endpoint out of range", {k});
  return kernel == CgalCdtKernel::Epick ? run<EpickCdt>(points, segments) : run<EpeckCdt>(points, segments);
}

}  // namespace dtlab
