// Lawson's flip algorithm (Lawson 1977; George & Borouchaki §2, Theorem 2.2) on the flat arrays
// of mesh/triangulation2.hpp. Why it ends at the perturbed Delaunay triangulation: a flip
// replaces an edge whose quadrilateral has its lifted points (|p|^2 plus the symbolic
// perturbation) folded upward by the lower diagonal, so the lifted surface only goes down, an
// edge flipped away never returns, and where no edge is left to flip the surface is locally
// convex, hence the lower hull. A non-locally-Delaunay quadrilateral is strictly convex (a
// vertex inside or on the other three's triangle would make the edge locally Delaunay), so every
// flip is valid.
#include "algorithms/delaunay2d/flip_lawson.hpp"

#include <string>
#include <vector>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

namespace {

thread_local LawsonFlipStats tls_last_stats;

constexpr std::uint32_t kInf = Triangulation2::kInfinite;
constexpr std::uint32_t kNext[3] = {1, 2, 0};
constexpr std::uint32_t kPrev[3] = {2, 0, 1};

// A stack of half-edges to test. A half-edge slot is on it at most once (queued_), and an edge
// is pushed only when neither of its two slots is queued: the stack never outgrows the number
// of slots, so it is sized once. A queued slot whose contents a flip changed is simply tested
// with its new contents when it comes up: what matters is that every edge that may have become
// non-locally-Delaunay has a queued slot.
class Flipper {
 public:
  Flipper(const Vec2* points, std::uint32_t* vertices, std::uint32_t* neighbours, std::size_t triangles)
      : p_(points), v_(vertices), n_(neighbours), queued_(3 * triangles, 0) {
    stack_.reserve(3 * triangles);
  }

  LawsonFlipStats run(std::uint64_t max_flips) {
    const auto slots = static_cast<std::uint32_t>(queued_.size());
    // Pushed in decreasing order so that the stack comes up in storage order.
    for (std::uint32_t h = slots; h-- > 0;)
      if (h < n_[h] && !ghost(h / 3) && !ghost(n_[h] / 3)) push(h);
    LawsonFlipStats stats;
    while (!stack_.empty()) {
      const std::uint32_t h = stack_.back();
      stack_.pop_back();
      queued_[h] = 0;
      const std::uint32_t g = n_[h];
      const std::uint32_t t1 = h / 3, t2 = g / 3;
      if (ghost(t1) || ghost(t2)) continue;  // a hull edge, or an edge at the infinite vertex
      const std::uint32_t i = h % 3, j = g % 3;
      // t1 = (p, u, w) and t2 = (q, w, u) around the edge u -> w, counter-clockwise.
      const std::uint32_t p = v_[h], u = v_[3 * t1 + kNext[i]], w = v_[3 * t1 + kPrev[i]], q = v_[g];
      ++stats.edge_tests;
      if (incircle_perturbed(p_[p], p_[u], p_[w], p_[q]) != Sign::Positive) continue;
      if (++stats.flips > max_flips)
        throw InternalError("Lawson flip: more than " + std::to_string(max_flips) +
                            " flips (an edge came back: the lifting argument is broken)");
      flip(t1, i, t2, j, p, u, w, q);
    }
    return stats;
  }

 private:
  bool ghost(std::uint32_t t) const noexcept { return v_[3 * t] == kInf; }
  void link(std::uint32_t g, std::uint32_t h) noexcept { n_[g] = h, n_[h] = g; }
  void push(std::uint32_t h) {
    if (queued_[h] || queued_[n_[h]]) return;
    queued_[h] = 1;
    stack_.push_back(h);
  }

  // The quadrilateral p, u, q, w (counter-clockwise) gets the diagonal p - q: t1 = (p, u, q),
  // t2 = (q, w, p); then its four sides are queued, their opposite vertex having changed.
  void flip(std::uint32_t t1, std::uint32_t i, std::uint32_t t2, std::uint32_t j, std::uint32_t p,
            std::uint32_t u, std::uint32_t w, std::uint32_t q) {
    const std::uint32_t wp = n_[3 * t1 + kNext[i]];  // twin of w -> p
    const std::uint32_t pu = n_[3 * t1 + kPrev[i]];  // twin of p -> u
    const std::uint32_t uq = n_[3 * t2 + kNext[j]];  // twin of u -> q
    const std::uint32_t qw = n_[3 * t2 + kPrev[j]];  // twin of q -> w
    v_[3 * t1] = p, v_[3 * t1 + 1] = u, v_[3 * t1 + 2] = q;
    v_[3 * t2] = q, v_[3 * t2 + 1] = w, v_[3 * t2 + 2] = p;
    link(3 * t1, uq);
    link(3 * t1 + 1, 3 * t2 + 1);  // q -> p against p -> q
    link(3 * t1 + 2, pu);
    link(3 * t2, wp);
    link(3 * t2 + 2, qw);
    push(3 * t1);
    push(3 * t1 + 2);
    push(3 * t2);
    push(3 * t2 + 2);
  }

  const Vec2* p_;
  std::uint32_t* v_;
  std::uint32_t* n_;
  std::vector<std::uint8_t> queued_;
  std::vector<std::uint32_t> stack_;
};

}  // namespace

LawsonFlipStats lawson_flip2(const Vec2* points, std::size_t m, std::uint32_t* vertices,
                             std::uint32_t* neighbours, std::size_t triangles) {
  const std::uint64_t max_flips = static_cast<std::uint64_t>(m) * (m > 0 ? m - 1 : 0) / 2;
  tls_last_stats = Flipper(points, vertices, neighbours, triangles).run(max_flips);
  return tls_last_stats;
}

LawsonFlipStats last_lawson_flip2_stats() noexcept { return tls_last_stats; }

}  // namespace dtlab
