// Method "conforming": conforming Delaunay triangulation by constraint partitioning (book §3.2,
// §3.3.2). The segments are first resolved as for every method (enforce.cpp), the constraints
// then forgotten and the triangulation made Delaunay; each piece that is not a Delaunay edge is
// split, the split point inserted with Lawson flips, until every piece is an edge. Split points:
// the midpoint, or, for a piece with exactly one end at an input vertex or crossing point, the point at a power-of-two
// distance from it (Ruppert 1995's concentric shells, which stop the ping-pong of splits between
// segments meeting at a small angle); both exact constructions correctly rounded.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "algorithms/constrained2d/context.hpp"
#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/rounding.hpp"

namespace dtlab {

namespace {

// A piece shorter than this many ulps of its coordinates is not split: its rounded split
// points would bend the chain by a sizeable fraction of the piece.
constexpr double kShortestSplit = 2;

struct Piece {
  std::uint32_t a, b, segment;
};

RoundedPoint2 split_point(const Vec2& a, const Vec2& b, bool a_input, bool b_input) {
  if (a_input == b_input) return midpoint(a, b);
  const Vec2& o = a_input ? a : b;
  const Vec2& f = a_input ? b : a;
  const double length = norm(f - o);
  const double distance = std::exp2(std::floor(std::log2(length * 2.0 / 3.0)));  // in (L/3, 2L/3]
  return point_on_segment(o, f, Rational(distance / length));
}

// (w - a) . (B - A) and (b - w) . (B - A) of one sign, not zero, exactly: w lies between the
// ends of piece ab (either way round) along its input segment AB, so the chain through it keeps
// going forward, as the chain checks require. Rounding breaks this only on pieces a few ulps
// long.
bool splits_forward(const Vec2& a, const Vec2& w, const Vec2& b, const Vec2& A, const Vec2& B) {
  const Rational ex = Rational(B.x) - Rational(A.x), ey = Rational(B.y) - Rational(A.y);
  const auto dot = [&](const Vec2& from, const Vec2& to) {
    return ((Rational(to.x) - Rational(from.x)) * ex + (Rational(to.y) - Rational(from.y)) * ey).sign();
  };
  const Sign first = dot(a, w);
  return first != Sign::Zero && dot(w, b) == first;
}

}  // namespace

void constrained2d_conforming(const Constrained2dContext& context) {
  resolve_and_enforce_segments(context);
  ConstrainedMesh2& mesh = context.mesh;
  Triangulation2& tri = mesh.tri();
  Constrained2dResult& result = context.result;

  std::vector<Piece> pieces;
  const auto size = static_cast<std::uint32_t>(tri.vertices().size());
  for (std::uint32_t h = 0; h < size; ++h)
    if (h < tri.twin(h) && mesh.constraint(h) != ConstrainedMesh2::kNone) {
      pieces.push_back({tri.origin(h), tri.destination(h), mesh.constraint(h)});
      for (const std::uint32_t s : mesh.shared_segments(h)) pieces.push_back({tri.origin(h), tri.destination(h), s});
    }
  mesh.clear_constraints();
  mesh.lawson(mesh.take_changed_edges(), false);  // the rest is still Delaunay

  const std::uint64_t limit =
      static_cast<std::uint64_t>(context.options.conforming_steiner_factor) * (tri.point_count() + context.segments.size()) + 16;
  // Shell centres: the vertices where segments may meet, input vertices and crossing points.
  const auto corners = static_cast<std::uint32_t>(tri.point_count());
  std::vector<std::uint32_t> outward;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const Piece p = pieces[k];
      if (mesh.find_half_edge(p.a, p.b) != ConstrainedMesh2::kNone) continue;
      changed = true;
      const ConstrainedMesh2::SegmentWalk walk = mesh.walk(p.a, p.b);
      std::uint32_t w = walk.stop;
      if (w == p.b) {
        {
          const Vec2 A = mesh.point(p.a), B = mesh.point(p.b);
          const double unit = std::max({ulp(A.x), ulp(A.y), ulp(B.x), ulp(B.y)});
          if (std::max(std::fabs(B.x - A.x), std::fabs(B.y - A.y)) < kShortestSplit * unit)
            throw InputError("conforming: segment " + context.number(p.segment) + " cannot be split further: its piece " +
                                 context.number(p.a) + "-" + context.number(p.b) + " is shorter than " +
                                 std::to_string(static_cast<int>(kShortestSplit)) +
                                 " ulps of its coordinates (points closer than the doubles can separate)",
                             {p.segment});
        }
        const RoundedPoint2 m =
            split_point(mesh.point(p.a), mesh.point(p.b), p.a < corners, p.b < corners);
        if (!coordinate_in_range(m.point.x) || !coordinate_in_range(m.point.y))
          throw InputError("conforming: a split point of segment " + context.number(p.segment) +
                               " falls outside the supported coordinate range",
                           {p.segment});
        const ConstrainedMesh2::Location where = mesh.locate(m.point, mesh.triangle_of_vertex(p.a));
        if (where.where == ConstrainedMesh2::Where::Vertex) {
          w = where.handle;
          if (w == p.a || w == p.b)
            throw InputError("conforming: segment " + context.number(p.segment) + " cannot be split further: its piece " +
                                 context.number(p.a) + "-" + context.number(p.b) + " has no double point between its ends",
                             {p.segment});
        } else {
          const auto& [ia, ib] = context.input_segment(p.segment);
          if (!splits_forward(mesh.point(p.a), m.point, mesh.point(p.b), mesh.point(ia), mesh.point(ib)))
            throw InputError("conforming: segment " + context.number(p.segment) + " cannot be split further: its piece " +
                                 context.number(p.a) + "-" + context.number(p.b) +
                                 " is a few ulps long, and its rounded split point does not lie between its ends "
                                 "along the segment (points closer than the doubles can separate)",
                             {p.segment});
          if (result.split_steiner_points >= limit)
            throw InputError("conforming: Steiner point limit (" + std::to_string(limit) + ") reached while splitting segment " +
                                 context.number(p.segment),
                             {p.segment});
          w = mesh.insert(m.point, where, &outward);
          mesh.lawson(outward, false);
          ++result.split_steiner_points;
        }
      }
      pieces[k] = {p.a, w, p.segment};
      pieces.push_back({w, p.b, p.segment});
    }
  }
  for (const Piece& p : pieces) {
    const std::uint32_t h = mesh.find_half_edge(p.a, p.b);
    DTLAB_ASSERT(h != ConstrainedMesh2::kNone);
    mesh.add_constraint(h, p.segment);
  }
}

}  // namespace dtlab
