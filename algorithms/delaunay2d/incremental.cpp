// Variant "incremental": the reduced incremental method, George & Borouchaki §2.4 and §2.6.2.
// Each point P goes in by the Delaunay kernel T_{i+1} = T_i - C_P + B_P: a visibility walk from
// the last insertion finds a base (a triangle in conflict with P), the cavity C_P grows from it by
// adjacency, and the ball B_P joins P to the cavity's boundary. Insertion order: BRIO rounds, each
// in Hilbert order (Amenta, Choi, Rote, SoCG 2003). The walk cannot cycle on a Delaunay
// triangulation (Edelsbrunner 1990: the in-front relation is acyclic); a step bound backs that up.
#include <algorithm>
#include <string>
#include <vector>

#include "algorithms/delaunay2d/prepare.hpp"
#include "algorithms/spatial_sort.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/memory_hints.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

namespace {

constexpr std::uint32_t kInf = Triangulation2::kInfinite;
constexpr std::uint32_t kNext[3] = {1, 2, 0};
constexpr std::uint32_t kPrev[3] = {2, 0, 1};

constexpr std::size_t kGrowthChunk = 4096;  // triangles

enum Mark : std::uint8_t { kUnmarked = 0, kInCavity = 1, kOutside = 2 };

// The insertion engine, working on raw views of the triangulation's arrays (reserved once for
// the final 2m - 2 triangles, so nothing reallocates) and on the points in insertion order: vertex
// ids are insertion ranks while it runs, which keeps consecutive insertions close in memory.
class Inserter {
 public:
  // The triangle arrays must be empty with room reserved for `capacity` triangles.
  Inserter(const Vec2* points, std::vector<std::uint32_t>& vertices, std::vector<std::uint32_t>& neighbours,
           std::size_t capacity)
      : p_(points),
        vertices_(vertices),
        neighbours_(neighbours),
        v_(vertices.data()),
        n_(neighbours.data()),
        mark_(capacity, kUnmarked),
        capacity_(capacity) {
    DTLAB_ASSERT(vertices.empty() && neighbours.empty());
    DTLAB_ASSERT(vertices.capacity() >= 3 * capacity && neighbours.capacity() >= 3 * capacity);
    cavity_.reserve(64);
    outside_.reserve(64);
    boundary_.reserve(64);
  }

  // The first triangle (a, b, c), counter-clockwise, and its three ghosts.
  void start(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const std::uint32_t v[3] = {a, b, c};
    vertices_.resize(12);
    neighbours_.resize(12);
    set_triangle(0, a, b, c);
    for (std::uint32_t i = 0; i < 3; ++i) {
      // Ghost 1 + i lies across edge i (v[i+1] -> v[i+2]) of triangle 0.
      set_triangle(1 + i, kInf, v[kPrev[i]], v[kNext[i]]);
      link(i, 3 * (1 + i));
    }
    // Edge 1 of ghost 1+i runs v[i+1] -> inf; edge 2 of ghost 1+j runs inf -> v[j+2].
    for (std::uint32_t i = 0; i < 3; ++i) link(3 * (1 + i) + 1, 3 * (1 + kPrev[i]) + 2);
    count_ = 4;
    last_ = 0;
  }

  void insert(std::uint32_t p) {
    const std::uint32_t base = locate(p);
    grow_cavity(base, p);
    fill_ball(p);
  }

  std::size_t triangle_count() const noexcept { return count_; }

 private:
  void set_triangle(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c) noexcept {
    v_[3 * t] = a, v_[3 * t + 1] = b, v_[3 * t + 2] = c;
  }
  void link(std::uint32_t g, std::uint32_t h) noexcept { n_[g] = h, n_[h] = g; }

  // p on the line through a and b: is it strictly between them?
  static bool strictly_between(const Vec2& a, const Vec2& b, const Vec2& p) noexcept {
    if (a.x != b.x) return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
    return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
  }

  // Ghost (inf, a, b): p is beyond hull edge b -> a, or on it.
  bool ghost_conflicts(const std::uint32_t* v, const Vec2& p) const noexcept {
    const Vec2& a = p_[v[1]];
    const Vec2& b = p_[v[2]];
    const Sign s = orient2d(a, b, p);
    return s == Sign::Positive || (s == Sign::Zero && strictly_between(a, b, p));
  }

  bool conflicts(std::uint32_t t, const Vec2& p) const noexcept {
    const std::uint32_t* v = v_ + 3 * t;
    if (v[0] == kInf) return ghost_conflicts(v, p);
    return incircle_perturbed(p_[v[0]], p_[v[1]], p_[v[2]], p) == Sign::Positive;
  }

  // Visibility walk from the last insertion's triangle to a triangle in conflict with p: a
  // finite triangle whose closed region holds p, or a ghost whose hull edge p is beyond.
  std::uint32_t locate(std::uint32_t pid) const {
    const Vec2& p = p_[pid];
    std::uint32_t t = last_;
    std::uint32_t entered = 3;  // the edge of t the walk came in through (3: none)
    for (std::size_t steps = 0; steps <= count_; ++steps) {
      const std::uint32_t* v = v_ + 3 * t;
      if (v[0] == kInf) {
        if (ghost_conflicts(v, p)) return t;
        const std::uint32_t h = n_[3 * t];  // p is on the inner side: step inside the hull
        t = h / 3, entered = h % 3;
        continue;
      }
      std::uint32_t i = entered == 3 ? 0 : kNext[entered];
      bool moved = false;
      for (int k = 0; k < 3; ++k, i = kNext[i]) {
        if (i == entered) continue;
        if (orient2d(p_[v[kNext[i]]], p_[v[kPrev[i]]], p) == Sign::Negative) {
          const std::uint32_t h = n_[3 * t + i];
          t = h / 3, entered = h % 3;
          if (v_[3 * t] == kInf) return t;  // p strictly beyond this hull edge
          moved = true;
          break;
        }
      }
      if (!moved) return t;
    }
    throw InternalError("incremental Delaunay: the walk to point (rank " + std::to_string(pid) +
                        ") exceeded its bound of " + std::to_string(count_) + " steps");
  }

  // C_P by breadth-first search from the base over adjacency (the cavity is connected). Every
  // edge of a cavity triangle is looked at once, so the boundary edges come out on the way.
  void grow_cavity(std::uint32_t base, std::uint32_t pid) {
    const Vec2& p = p_[pid];
    cavity_.clear();
    outside_.clear();
    boundary_.clear();
    mark_[base] = kInCavity;
    cavity_.push_back(base);
    for (std::size_t k = 0; k < cavity_.size(); ++k) {
      const std::uint32_t t = cavity_[k];
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t outer = n_[3 * t + i];
        const std::uint32_t u = outer / 3;
        if (mark_[u] == kUnmarked) {
          if (conflicts(u, p)) {
            mark_[u] = kInCavity;
            cavity_.push_back(u);
            continue;
          }
          mark_[u] = kOutside;
          outside_.push_back(u);
        } else if (mark_[u] == kInCavity) {
          continue;
        }
        boundary_.push_back({v_[3 * t + kNext[i]], v_[3 * t + kPrev[i]], outer, 0});
      }
    }
    // A cavity is a triangulated polygon without interior vertex: k edges, k - 2 triangles.
    DTLAB_ASSERT(boundary_.size() == cavity_.size() + 2);
  }

  // For each boundary edge u -> v, the boundary edge that starts at v: the boundary is one cycle,
  // so each vertex starts exactly one edge. Small cavities (nearly all) search a short array.
  void chain_boundary() {
    const std::size_t k = boundary_.size();
    origins_.resize(k);
    for (std::size_t j = 0; j < k; ++j) origins_[j] = boundary_[j].u;
    if (k <= 32) {
      for (BoundaryEdge& e : boundary_) {
        const auto it = std::find(origins_.begin(), origins_.end(), e.v);
        DTLAB_ASSERT(it != origins_.end());
        e.next = static_cast<std::uint32_t>(it - origins_.begin());
      }
      return;
    }
    by_origin_.resize(k);
    for (std::size_t j = 0; j < k; ++j) by_origin_[j] = static_cast<std::uint32_t>(j);
    std::sort(by_origin_.begin(), by_origin_.end(),
              [this](std::uint32_t a, std::uint32_t b) { return origins_[a] < origins_[b]; });
    for (BoundaryEdge& e : boundary_) {
      const auto it = std::lower_bound(by_origin_.begin(), by_origin_.end(), e.v,
                                       [this](std::uint32_t j, std::uint32_t v) { return origins_[j] < v; });
      DTLAB_ASSERT(it != by_origin_.end() && origins_[*it] == e.v);
      e.next = *it;
    }
  }

  // B_P: one triangle (p, u, v) per boundary edge u -> v, in the cavity's slots and two new ones.
  void fill_ball(std::uint32_t p) {
    chain_boundary();
    const std::size_t k = boundary_.size();
    DTLAB_ASSERT(count_ + 2 <= capacity_);
    cavity_.push_back(static_cast<std::uint32_t>(count_));
    cavity_.push_back(static_cast<std::uint32_t>(count_ + 1));
    count_ += 2;
    if (3 * count_ > vertices_.size()) {
      // Grow in chunks within the reserved capacity (v_ and n_ stay valid): the zeroing then
      // lands on memory about to be written, and costs one call per chunk, not per point. Its
      // pages are faulted in by one call each first, not one fault a page (a virtual machine's
      // page faults are dear: see populate_for_writing).
      const std::size_t size = 3 * std::min(capacity_, count_ + kGrowthChunk);
      populate_for_writing(vertices_.data() + vertices_.size(), vertices_.data() + size);
      populate_for_writing(neighbours_.data() + neighbours_.size(), neighbours_.data() + size);
      vertices_.resize(size);
      neighbours_.resize(size);
    }
    for (std::size_t j = 0; j < k; ++j) {
      const std::uint32_t t = cavity_[j];
      BoundaryEdge& e = boundary_[j];
      // Positions of p, u, v in t: ghosts keep kInfinite at index 0.
      std::uint32_t ip, iu, iv;
      if (e.u == kInf) {
        set_triangle(t, kInf, e.v, p), ip = 2, iu = 0, iv = 1;
      } else if (e.v == kInf) {
        set_triangle(t, kInf, p, e.u), ip = 1, iu = 2, iv = 0;
      } else {
        set_triangle(t, p, e.u, e.v), ip = 0, iu = 1, iv = 2;
      }
      link(3 * t + ip, e.outer);
      // Keep the half-edges p -> u (opposite v) and v -> p (opposite u) for the links inside B_P.
      e.u = 3 * t + iv;
      e.v = 3 * t + iu;
      mark_[t] = kUnmarked;
    }
    for (const BoundaryEdge& e : boundary_) link(e.v, boundary_[e.next].u);
    for (const std::uint32_t t : outside_) mark_[t] = kUnmarked;
    last_ = cavity_[0];
  }

  struct BoundaryEdge {
    std::uint32_t u, v, outer;  // u -> v, and its twin outside the cavity
    std::uint32_t next;         // the boundary edge that starts at v
  };

  const Vec2* p_;
  std::vector<std::uint32_t>& vertices_;
  std::vector<std::uint32_t>& neighbours_;
  std::uint32_t* v_;
  std::uint32_t* n_;
  std::vector<std::uint8_t> mark_;
  std::size_t capacity_;
  std::size_t count_ = 0;
  std::uint32_t last_ = 0;
  std::vector<std::uint32_t> cavity_, outside_;
  std::vector<BoundaryEdge> boundary_;
  std::vector<std::uint32_t> origins_, by_origin_;
};

}  // namespace

void delaunay2d_incremental(const PreparedPoints2& input, Triangulation2& triangulation) {
  std::vector<Vec2>& points = triangulation.mutable_points();
  DTLAB_ASSERT(points.size() == input.points.size());
  DTLAB_ASSERT(input.distinct.size() >= 3);
  std::vector<std::uint32_t> order = brio_order_of_sorted(input.distinct, input.seed);
  const std::size_t m = order.size();
  for (std::size_t r = 0; r < m; ++r) points[r] = input.points[order[r]];

  // The first triangle: the first two points and the first one off their line.
  std::size_t third = 2;
  Sign turn = Sign::Zero;
  for (; third < m; ++third)
    if ((turn = orient2d(points[0], points[1], points[third])) != Sign::Zero) break;
  DTLAB_ASSERT(turn != Sign::Zero);
  std::swap(order[2], order[third]);
  std::swap(points[2], points[third]);

  const std::size_t capacity = 2 * m - 2;  // triangles of the final triangulation, ghosts included
  std::vector<std::uint32_t>& vertices = triangulation.mutable_vertices();
  std::vector<std::uint32_t>& neighbours = triangulation.mutable_neighbours();
  triangulation.clear_triangles();
  triangulation.reserve_triangles(capacity);

  Inserter inserter(points.data(), vertices, neighbours, capacity);
  if (turn == Sign::Positive) {
    inserter.start(0, 1, 2);
  } else {
    inserter.start(0, 2, 1);
  }
  for (std::size_t r = 3; r < m; ++r) inserter.insert(static_cast<std::uint32_t>(r));
  DTLAB_ASSERT(inserter.triangle_count() == capacity && vertices.size() == 3 * capacity);

  // Back to input ids and input order.
  for (std::uint32_t& v : vertices)
    if (v != kInf) v = order[v];
  std::copy(input.points.begin(), input.points.end(), points.begin());
}

}  // namespace dtlab
