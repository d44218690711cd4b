// The lexicographic fan sweep (George & Borouchaki §2, the "any triangulation" of Theorem 2.2):
// the lexicographically last point so far is a strict extreme point of the hull, so the next
// point sees one of the two hull edges at it, and the hull edges it sees form one chain there.
// Joining the point to that chain turns the chain's ghosts into triangles and adds two ghosts.
#include "algorithms/delaunay2d/flip_sweep.hpp"

#include <string>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

namespace {

constexpr std::uint32_t kInf = Triangulation2::kInfinite;
constexpr std::uint32_t kNone = Triangulation2::kNone;

class FanSweep {
 public:
  FanSweep(const Vec2* points, std::size_t m, std::uint32_t* vertices, std::uint32_t* neighbours)
      : p_(points), m_(m), v_(vertices), n_(neighbours) {}

  void run() {
    // The initial collinear run 0 .. apex-1 (at least two points), then the first point off it.
    std::size_t apex = 2;
    Sign turn = Sign::Zero;
    for (; apex < m_; ++apex)
      if ((turn = orient2d(p_[0], p_[1], p_[apex])) != Sign::Zero) break;
    DTLAB_ASSERT(turn != Sign::Zero);
    const auto a = static_cast<std::uint32_t>(apex);
    if (turn == Sign::Positive) {
      start(0, 1, a);
    } else {
      start(0, a, 1);
    }
    // The rest of the run, fanned from the apex: each run point lies beyond the last one on the
    // run's line, so it sees the hull edge between the last one and the apex, and it becomes a
    // hull vertex (the run's edges stay on the hull).
    Ghosts at = ghosts_at(1);
    for (std::uint32_t r = 2; r < a; ++r) at = insert(r, at);
    at = ghosts_at(a);
    for (std::size_t r = apex + 1; r < m_; ++r) at = insert(static_cast<std::uint32_t>(r), at);
    DTLAB_ASSERT(count_ == 2 * m_ - 2);
  }

 private:
  // The two ghosts at a hull vertex x: across the hull edge u -> x (inf, x, u) and across
  // x -> w (inf, w, x); the second follows the first counter-clockwise around the hull.
  struct Ghosts {
    std::uint32_t in, out;
  };

  void set_triangle(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c) noexcept {
    v_[3 * t] = a, v_[3 * t + 1] = b, v_[3 * t + 2] = c;
  }
  void link(std::uint32_t g, std::uint32_t h) noexcept { n_[g] = h, n_[h] = g; }

  // Triangle (a, b, c), counter-clockwise, and the ghost across each of its edges.
  void start(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const std::uint32_t v[3] = {a, b, c};
    set_triangle(0, a, b, c);
    for (std::uint32_t i = 0; i < 3; ++i) {
      // Edge i of triangle 0 runs v[i+1] -> v[i+2]; its ghost is (inf, v[i+2], v[i+1]).
      set_triangle(1 + i, kInf, v[(i + 2) % 3], v[(i + 1) % 3]);
      link(i, 3 * (1 + i));
    }
    // Edge 1 of ghost 1+i runs v[i+1] -> inf; edge 2 of ghost 1+j runs inf -> v[j+2].
    for (std::uint32_t i = 0; i < 3; ++i) link(3 * (1 + i) + 1, 3 * (1 + (i + 2) % 3) + 2);
    count_ = 4;
  }

  // Found by a scan: used twice, on a structure of O(run length) triangles.
  Ghosts ghosts_at(std::uint32_t x) const {
    Ghosts g{kNone, kNone};
    for (std::uint32_t t = 0; t < count_; ++t) {
      if (v_[3 * t] != kInf) continue;
      if (v_[3 * t + 1] == x) g.in = t;
      if (v_[3 * t + 2] == x) g.out = t;
    }
    DTLAB_ASSERT(g.in != kNone && g.out != kNone);
    return g;
  }

  // Hull edge b -> a of ghost (inf, a, b) seen from p: p strictly on its outer side. p is never
  // strictly between a and b (it comes after both lexicographically, or beyond the run's end).
  bool sees(std::uint32_t ghost, const Vec2& p) const noexcept {
    return orient2d(p_[v_[3 * ghost + 1]], p_[v_[3 * ghost + 2]], p) == Sign::Positive;
  }

  // Joins p to the chain of hull edges it sees, found by walking from the ghosts at the
  // previous point; returns the ghosts at p.
  Ghosts insert(std::uint32_t pid, Ghosts at) {
    const Vec2& p = p_[pid];
    const std::size_t bound = count_;  // more steps than ghosts would mean the walk wrapped
    std::size_t steps = 0;
    // Edge 1 of a ghost leads to the ghost of the previous hull edge, edge 2 to the next one.
    std::uint32_t first = at.in, last = at.out;
    if (sees(at.in, p)) {
      for (std::uint32_t g = n_[3 * first + 1] / 3; sees(g, p); g = n_[3 * first + 1] / 3) {
        first = g;
        if (++steps > bound) throw_wrapped(pid);
      }
    } else {
      first = at.out;
    }
    if (sees(at.out, p)) {
      for (std::uint32_t g = n_[3 * last + 2] / 3; sees(g, p); g = n_[3 * last + 2] / 3) {
        last = g;
        if (++steps > bound) throw_wrapped(pid);
      }
    } else {
      last = at.in;
    }
    DTLAB_ASSERT(sees(first, p) && sees(last, p));

    // The chain u0 -> u1 -> ... -> uk: its ghosts (inf, u_{j+1}, u_j) become (p, u_{j+1}, u_j),
    // counter-clockwise since p sees u_j -> u_{j+1}; the links between them stay right.
    const std::uint32_t u0 = v_[3 * first + 2];
    const std::uint32_t uk = v_[3 * last + 1];
    const std::uint32_t before = n_[3 * first + 1];  // inf -> u0, in the ghost before the chain
    const std::uint32_t after = n_[3 * last + 2];    // uk -> inf, in the ghost after it
    for (std::uint32_t g = first;; g = n_[3 * g + 2] / 3) {
      v_[3 * g] = pid;
      if (g == last) break;
      if (++steps > 2 * bound) throw_wrapped(pid);
    }
    // The new hull edges u0 -> p and p -> uk, with their ghosts.
    DTLAB_ASSERT(count_ + 2 <= 2 * m_ - 2);
    const auto g0 = static_cast<std::uint32_t>(count_), g1 = g0 + 1;
    count_ += 2;
    set_triangle(g0, kInf, pid, u0);
    set_triangle(g1, kInf, uk, pid);
    link(3 * g0, 3 * first + 1);  // p -> u0 against u0 -> p
    link(3 * g0 + 1, before);     // u0 -> inf
    link(3 * g0 + 2, 3 * g1 + 1);  // inf -> p against p -> inf
    link(3 * g1, 3 * last + 2);   // uk -> p against p -> uk
    link(3 * g1 + 2, after);      // inf -> uk
    return {g0, g1};
  }

  [[noreturn]] static void throw_wrapped(std::uint32_t pid) {
    throw InternalError("flip sweep: the walk along the hull from point (rank " + std::to_string(pid) +
                        ") went all the way round");
  }

  const Vec2* p_;
  std::size_t m_;
  std::uint32_t* v_;
  std::uint32_t* n_;
  std::size_t count_ = 0;
};

}  // namespace

void sweep_triangulate2(const Vec2* points, std::size_t m, std::uint32_t* vertices, std::uint32_t* neighbours) {
  DTLAB_ASSERT(m >= 3);
  FanSweep(points, m, vertices, neighbours).run();
}

}  // namespace dtlab
