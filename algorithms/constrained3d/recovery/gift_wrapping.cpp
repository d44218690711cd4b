// Gift-wrapping of a cavity (gift_wrapping.hpp).
#include "algorithms/constrained3d/recovery/gift_wrapping.hpp"

#include <algorithm>
#include <set>

#include "algorithms/constrained3d/plc/plc_checks.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "kernel/predicates/perturbation.hpp"

namespace dtlab {

namespace {

using Face = std::array<std::uint32_t, 3>;

// The same oriented triangle has one name: rotated so that its smallest vertex comes first.
Face oriented(Face f) {
  while (f[0] > f[1] || f[0] > f[2]) f = {f[1], f[2], f[0]};
  return f;
}
Face reversed(const Face& f) { return oriented({f[0], f[2], f[1]}); }

struct Box {
  Vec3 lo, hi;
  void add(const Vec3& p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  bool overlaps(const Box& b) const {
    return lo.x <= b.hi.x && b.lo.x <= hi.x && lo.y <= b.hi.y && b.lo.y <= hi.y && lo.z <= b.hi.z && b.lo.z <= hi.z;
  }
};

class Wrapper {
 public:
  Wrapper(std::span<const Vec3> points, std::span<const std::uint32_t> vertices) : P_(points), vertices_(vertices) {}

  std::vector<std::array<std::uint32_t, 4>> run(std::span<const Face> front, std::string& why) {
    for (const Face& f : front)
      if (!front_.insert(oriented(f)).second) {
        why = "a cavity triangle is listed twice on one side";
        return {};
      }
    std::vector<Face> stack(front_.begin(), front_.end());
    const std::size_t limit = vertices_.size() * vertices_.size() + front.size() + 16;
    std::vector<std::uint32_t> candidates;
    while (!stack.empty()) {
      const Face f = stack.back();
      stack.pop_back();
      if (!front_.count(f)) continue;  // closed since
      if (tets_.size() >= limit) throw InternalError("gift wrapping: more tetrahedra than a cavity can hold");
      const auto [a, b, c] = f;
      candidates.clear();
      for (const std::uint32_t p : vertices_)
        if (p != a && p != b && p != c && orient3d(P_[a], P_[b], P_[c], P_[p]) == Sign::Positive) candidates.push_back(p);
      std::uint32_t chosen = kNone;
      while (!candidates.empty() && chosen == kNone) {
        // The candidate whose sphere through a, b, c holds no other candidate.
        std::size_t best = 0;
        for (std::size_t k = 1; k < candidates.size(); ++k)
          if (insphere_perturbed(P_[a], P_[b], P_[c], P_[candidates[best]], P_[candidates[k]]) == Sign::Positive) best = k;
        if (is_free(f, candidates[best]))
          chosen = candidates[best];
        else
          candidates.erase(candidates.begin() + static_cast<std::ptrdiff_t>(best));
      }
      if (chosen == kNone) {
        why = "no vertex of the cavity is free for its triangle (" + std::to_string(a + 1) + ", " + std::to_string(b + 1) +
              ", " + std::to_string(c + 1) + ")";
        return {};
      }
      const std::uint32_t p = chosen;
      tets_.push_back({a, b, c, p});
      // The four faces as seen from inside the new tetrahedron: each closes a front triangle
      // or becomes one, facing out.
      for (const Face& g : {Face{a, b, c}, Face{b, p, c}, Face{a, c, p}, Face{a, p, b}}) {
        const Face k = oriented(g);
        if (front_.erase(k)) continue;
        const Face out = reversed(g);
        front_.insert(out);
        stack.push_back(out);
      }
    }
    std::set<std::uint32_t> used;
    for (const auto& t : tets_) used.insert(t.begin(), t.end());
    for (const std::uint32_t v : vertices_)
      if (!used.count(v)) {
        why = "vertex " + std::to_string(v + 1) + " inside the cavity is left out by its wrapping";
        return {};
      }
    return std::move(tets_);
  }

 private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  Box box_of(std::initializer_list<std::uint32_t> ids) const {
    Box b{P_[*ids.begin()], P_[*ids.begin()]};
    for (const std::uint32_t v : ids) b.add(P_[v]);
    return b;
  }

  // Tetrahedron (a, b, c, p) lies in the unfilled region: none of its new faces meets a front
  // triangle other than along shared edges and vertices (a new face that is itself a front
  // triangle facing into it closes that triangle; facing away, the tetrahedron overlaps what is
  // filled), and no other cavity vertex lies in it (closed).
  bool is_free(const Face& f, std::uint32_t p) const {
    const auto [a, b, c] = f;
    const std::array<Face, 3> sides = {Face{b, p, c}, Face{a, c, p}, Face{a, p, b}};
    std::array<bool, 3> closes{};
    for (int k = 0; k < 3; ++k) {
      closes[k] = front_.count(oriented(sides[k])) != 0;
      if (!closes[k] && front_.count(reversed(sides[k]))) return false;
    }
    for (const std::uint32_t q : vertices_) {
      if (q == a || q == b || q == c || q == p) continue;
      if (orient3d(P_[b], P_[p], P_[c], P_[q]) != Sign::Negative &&
          orient3d(P_[a], P_[c], P_[p], P_[q]) != Sign::Negative &&
          orient3d(P_[a], P_[p], P_[b], P_[q]) != Sign::Negative &&
          orient3d(P_[a], P_[b], P_[c], P_[q]) != Sign::Negative)
        return false;
    }
    const Box tet = box_of({a, b, c, p});
    for (const Face& h : front_) {
      if (!tet.overlaps(box_of({h[0], h[1], h[2]}))) continue;
      for (int k = 0; k < 3; ++k) {
        if (closes[k]) continue;
        const Face s = oriented(sides[k]);
        if (h == s || h == reversed(sides[k])) continue;
        if (faces_intersect_improperly(P_, sides[k], h)) return false;
      }
    }
    return true;
  }

  std::span<const Vec3> P_;
  std::span<const std::uint32_t> vertices_;
  std::set<Face> front_;
  std::vector<std::array<std::uint32_t, 4>> tets_;
};

}  // namespace

std::vector<std::array<std::uint32_t, 4>> gift_wrap_cavity(std::span<const Vec3> points, std::span<const Face> front,
                                                           std::span<const std::uint32_t> vertices, std::string& why) {
  return Wrapper(points, vertices).run(front, why);
}

}  // namespace dtlab
