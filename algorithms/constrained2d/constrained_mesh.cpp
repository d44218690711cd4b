// The constrained triangulation's operations (constrained_mesh.hpp): walk along a segment (the
// pipe, book §1.7 and §3.3.3), stochastic visibility walk (Devillers, Pion, Teillaud 2002),
// Steiner point insertion by cavity and ball (§2.4, restricted to the triangles holding the
// point or the ghosts that see it), edge flip, and Lawson's flips (§2, Theorem 2.2; §3.4 with
// constrained edges left alone).
#include "algorithms/constrained2d/constrained_mesh.hpp"

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/element_sets2.hpp"
#include "mesh/navigation2_walk.hpp"

namespace dtlab {

namespace {

using T2 = Triangulation2;

// p on the line through a and b: is it strictly between them?
bool strictly_between(const Vec2& a, const Vec2& b, const Vec2& p) noexcept {
  if (a.x != b.x) return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
  return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
}

std::pair<std::uint32_t, std::uint32_t> edge_key(std::uint32_t a, std::uint32_t b) {
  return {std::min(a, b), std::max(a, b)};
}

}  // namespace

ConstrainedMesh2::ConstrainedMesh2(Triangulation2& tri)
    : tri_(tri), vtri_(vertex_triangles(tri_)) {  // finite triangles first: walks start inside the hull
  cons_.assign(tri_.vertices().size(), kNone);
}

void ConstrainedMesh2::set_constraint(std::uint32_t h, std::uint32_t segment) noexcept {
  cons_[h] = segment;
  cons_[tri_.twin(h)] = segment;
  if (!shared_.empty()) shared_.erase(edge_key(tri_.origin(h), tri_.destination(h)));
}

std::uint32_t ConstrainedMesh2::add_constraint(std::uint32_t h, std::uint32_t segment) {
  const std::uint32_t existing = cons_[h];
  if (existing == segment) return existing;
  if (existing == kNone) {
    set_constraint(h, segment);
    return existing;
  }
  std::vector<std::uint32_t>& others = shared_[edge_key(tri_.origin(h), tri_.destination(h))];
  const std::uint32_t kept = std::min(existing, segment), other = std::max(existing, segment);
  cons_[h] = cons_[tri_.twin(h)] = kept;
  const auto at = std::lower_bound(others.begin(), others.end(), other);
  if (at == others.end() || *at != other) others.insert(at, other);
  if (kept != existing) {  // the old constraint joins the shared ones; the new one is not among them
    const auto old_at = std::lower_bound(others.begin(), others.end(), kept);
    if (old_at != others.end() && *old_at == kept) others.erase(old_at);
  }
  return existing;
}

std::vector<std::uint32_t> ConstrainedMesh2::shared_segments(std::uint32_t h) const {
  if (shared_.empty()) return {};
  const auto it = shared_.find(edge_key(tri_.origin(h), tri_.destination(h)));
  return it == shared_.end() ? std::vector<std::uint32_t>{} : it->second;
}

std::vector<std::array<std::uint32_t, 3>> ConstrainedMesh2::shared_constraints() const {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (const auto& [key, segments] : shared_)
    for (const std::uint32_t s : segments) out.push_back({key.first, key.second, s});
  return out;
}

void ConstrainedMesh2::clear_constraints() noexcept {
  std::fill(cons_.begin(), cons_.end(), kNone);
  shared_.clear();
}

void ConstrainedMesh2::write_triangle(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c) noexcept {
  // Ghosts keep kInfinite at index 0 (triangulation2.hpp).
  if (b == kInf) std::tie(a, b, c) = std::tuple(b, c, a);
  if (c == kInf) std::tie(a, b, c) = std::tuple(c, a, b);
  std::uint32_t* v = tri_.mutable_vertices().data() + 3 * t;
  v[0] = a, v[1] = b, v[2] = c;
  note_written(t);
}

void ConstrainedMesh2::note_written(std::uint32_t t) noexcept {
  written_.push_back(t);
  const std::uint32_t* v = tri_.vertices().data() + 3 * t;
  for (std::uint32_t i = 0; i < 3; ++i)
    if (v[i] != kInf) vtri_[v[i]] = t;
}

std::uint32_t ConstrainedMesh2::find_half_edge(std::uint32_t u, std::uint32_t v) const {
  const std::uint32_t first = vtri_[u];
  if (first == kNone) return kNone;
  const std::uint32_t h0 = nav2::opposite(tri_, first, u);
  DTLAB_ASSERT(h0 != kNone);
  return nav2::find_half_edge(tri_, h0, v, tri_.triangle_count() + 1);
}

ConstrainedMesh2::SegmentWalk ConstrainedMesh2::walk(std::uint32_t s, std::uint32_t q) const {
  DTLAB_ASSERT(s != q && s < vertex_count() && q < vertex_count() && vtri_[s] != kNone);
  const std::size_t bound = tri_.triangle_count() + 1;
  SegmentWalk out;
  const nav2::PipeStart start = nav2::pipe_start(tri_, nav2::opposite(tri_, vtri_[s], s), q, bound);
  out.stop = start.stop;
  if (out.stop == kNone)
    out.stop = nav2::pipe_cross(tri_, start.at, point(s), q, bound, [&](std::uint32_t h) { out.crossed.push_back(h); });
  return out;
}

ConstrainedMesh2::Location ConstrainedMesh2::locate(const Vec2& p, std::uint32_t start) {
  return nav2::locate(tri_, p, start, rng_, 64 * tri_.triangle_count() + 64, [](std::uint32_t) { return false; });
}

std::uint32_t ConstrainedMesh2::insert(const Vec2& p, const Location& where, std::vector<std::uint32_t>* outward) {
  DTLAB_ASSERT(where.where != Where::Vertex);
  if (tri_.point_count() + 1 >= T2::kMaxPoints) throw InputError("constrained triangulation: too many Steiner points");
  // The cavity: triangles whose removal leaves a star-shaped polygon around p.
  std::vector<std::uint32_t> cavity;
  std::uint32_t split_segment = kNone, split_u = kNone, split_v = kNone;
  if (where.where == Where::Triangle) {
    cavity = {where.triangle};
  } else if (where.where == Where::Edge) {
    const std::uint32_t h = where.handle;
    cavity = {T2::triangle_of(h), T2::triangle_of(tri_.twin(h))};
    split_segment = cons_[h], split_u = tri_.origin(h), split_v = tri_.destination(h);
  } else {
    // Ghosts (inf, b, a) whose hull edge a -> b p is beyond, or strictly inside of on its line;
    // they are consecutive around the hull.
    in_cavity_.resize(tri_.triangle_count(), 0);
    cavity = {where.triangle};
    in_cavity_[where.triangle] = 1;
    for (std::size_t k = 0; k < cavity.size(); ++k) {
      const std::uint32_t t = cavity[k];
      for (std::uint32_t i : {1u, 2u}) {
        const std::uint32_t u = T2::triangle_of(tri_.twin(T2::half_edge(t, i)));
        if (in_cavity_[u] || !tri_.is_ghost(u)) continue;
        const Vec2& a = point(tri_.vertex(u, 1));
        const Vec2& b = point(tri_.vertex(u, 2));
        const Sign s = orient2d(a, b, p);
        if (s == Sign::Positive || (s == Sign::Zero && strictly_between(a, b, p))) {
          in_cavity_[u] = 1;
          cavity.push_back(u);
        }
      }
    }
    for (const std::uint32_t t : cavity) in_cavity_[t] = 0;
  }
  std::sort(cavity.begin(), cavity.end());

  struct Boundary {
    std::uint32_t u, v, outer, segment;
  };
  std::vector<Boundary> boundary;
  for (const std::uint32_t t : cavity)
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = T2::half_edge(t, i);
      const std::uint32_t outer = tri_.twin(h);
      if (std::binary_search(cavity.begin(), cavity.end(), T2::triangle_of(outer))) continue;
      boundary.push_back({tri_.origin(h), tri_.destination(h), outer, cons_[h]});
    }
  DTLAB_ASSERT(boundary.size() == cavity.size() + 2);

  const auto x = static_cast<std::uint32_t>(tri_.point_count());
  tri_.mutable_points().push_back(p);
  vtri_.push_back(kNone);
  for (int k = 0; k < 2; ++k) {
    cavity.push_back(static_cast<std::uint32_t>(tri_.triangle_count()));
    tri_.mutable_vertices().resize(tri_.mutable_vertices().size() + 3, kNone);
    tri_.mutable_neighbours().resize(tri_.mutable_neighbours().size() + 3, kNone);
    cons_.resize(cons_.size() + 3, kNone);
  }
  // One triangle (x, u, v) per boundary edge u -> v; remember x -> u (by u) to link the fans.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> starts;  // (u, half-edge x -> u)
  std::vector<std::uint32_t> enters(boundary.size());           // half-edge v -> x
  if (outward) outward->clear();
  for (std::size_t j = 0; j < boundary.size(); ++j) {
    const std::uint32_t t = cavity[j];
    const Boundary& e = boundary[j];
    write_triangle(t, x, e.u, e.v);
    const std::uint32_t out = nav2::opposite(tri_, t, x);
    tri_.link(out, e.outer);
    cons_[out] = e.segment;
    if (outward) outward->push_back(out);
    starts.emplace_back(e.u, nav2::opposite(tri_, t, e.v));
    enters[j] = nav2::opposite(tri_, t, e.u);
    for (std::uint32_t h : {T2::half_edge(t, 0), T2::half_edge(t, 1), T2::half_edge(t, 2)})
      if (h != out) cons_[h] = kNone;
  }
  std::sort(starts.begin(), starts.end());
  for (std::size_t j = 0; j < boundary.size(); ++j) {
    const auto it = std::lower_bound(starts.begin(), starts.end(), std::pair{boundary[j].v, 0u});
    DTLAB_ASSERT(it != starts.end() && it->first == boundary[j].v);
    tri_.link(enters[j], it->second);
  }
  if (split_segment != kNone) {
    std::vector<std::uint32_t> others;
    if (!shared_.empty()) {
      if (const auto it = shared_.find(edge_key(split_u, split_v)); it != shared_.end()) {
        others = std::move(it->second);
        shared_.erase(it);
      }
    }
    for (const std::uint32_t end : {split_u, split_v}) {
      const std::uint32_t h = find_half_edge(x, end);
      set_constraint(h, split_segment);
      for (const std::uint32_t s : others) add_constraint(h, s);
    }
  }
  return x;
}

bool ConstrainedMesh2::flippable(std::uint32_t h) const {
  const std::uint32_t g = tri_.twin(h);
  if (tri_.is_ghost(T2::triangle_of(h)) || tri_.is_ghost(T2::triangle_of(g))) return false;
  const Vec2& c = point(tri_.vertices()[h]);
  const Vec2& d = point(tri_.vertices()[g]);
  const Sign su = orient2d(c, d, point(tri_.origin(h)));
  const Sign sv = orient2d(c, d, point(tri_.destination(h)));
  return su != Sign::Zero && sv != Sign::Zero && su != sv;
}

std::uint32_t ConstrainedMesh2::flip(std::uint32_t h) {
  const std::uint32_t t1 = T2::triangle_of(h), t2 = T2::triangle_of(tri_.twin(h));
  const std::uint32_t d = nav2::flip(
      tri_.mutable_vertices().data(), tri_.mutable_neighbours().data(), h, [&](std::uint32_t e) { return cons_[e]; },
      [&](std::uint32_t e, std::uint32_t segment) { cons_[e] = segment; }, kNone);
  note_written(t1);
  note_written(t2);
  ++flips_;
  return d;
}

bool ConstrainedMesh2::violates_delaunay(std::uint32_t h) const {
  const std::uint32_t g = tri_.twin(h);
  const std::uint32_t t1 = T2::triangle_of(h);
  if (tri_.is_ghost(t1) || tri_.is_ghost(T2::triangle_of(g))) return false;
  return incircle_perturbed(point(tri_.vertex(t1, 0)), point(tri_.vertex(t1, 1)), point(tri_.vertex(t1, 2)),
                            point(tri_.vertices()[g])) == Sign::Positive;
}

void ConstrainedMesh2::lawson(std::vector<std::uint32_t> stack, bool respect_constraints) {
  const double edges = static_cast<double>(tri_.vertices().size()) / 2.0 + 16.0;
  const auto bound = static_cast<std::uint64_t>(std::min(edges * edges, 1e18));
  std::uint64_t done = 0;
  while (!stack.empty()) {
    const std::uint32_t h = stack.back();
    stack.pop_back();
    if (respect_constraints && cons_[h] != kNone) continue;
    if (!violates_delaunay(h)) continue;
    // A vertex strictly inside the (perturbed) circle across the edge makes the quadrilateral
    // strictly convex; the test only guards against a bug.
    if (!flippable(h)) throw InternalError("Lawson flip: non-convex quadrilateral at half-edge " + std::to_string(h));
    if (++done > bound) throw InternalError("Lawson flips exceeded their bound of " + std::to_string(bound));
    const std::uint32_t e = flip(h);
    const std::uint32_t t1 = T2::triangle_of(e), t2 = T2::triangle_of(tri_.twin(e));
    for (std::uint32_t k : {3 * t1, 3 * t1 + 2, 3 * t2, 3 * t2 + 2}) stack.push_back(k);
  }
}

std::vector<std::uint32_t> ConstrainedMesh2::take_changed_edges() {
  // A flag per triangle, not a sort: every flip writes two triangles, so the record is long.
  std::vector<std::uint8_t> written(tri_.triangle_count(), 0);
  std::vector<std::uint32_t> triangles;
  for (const std::uint32_t t : written_)
    if (!written[t]) written[t] = 1, triangles.push_back(t);
  written_.clear();
  std::vector<std::uint32_t> stack;
  stack.reserve(3 * triangles.size());
  for (const std::uint32_t t : triangles)
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = T2::half_edge(t, i), g = tri_.twin(h);
      // Each edge once: from the lower half-edge, or from this one if the twin's triangle was
      // not written.
      if (h < g || !written[T2::triangle_of(g)]) stack.push_back(h);
    }
  std::reverse(stack.begin(), stack.end());
  return stack;
}

void ConstrainedMesh2::lawson_all(bool respect_constraints) {
  std::vector<std::uint32_t> stack;
  const auto size = static_cast<std::uint32_t>(tri_.vertices().size());
  stack.reserve(size / 2);
  for (std::uint32_t h = 0; h < size; ++h)
    if (h < tri_.twin(h)) stack.push_back(h);
  std::reverse(stack.begin(), stack.end());
  lawson(std::move(stack), respect_constraints);
}

}  // namespace dtlab
