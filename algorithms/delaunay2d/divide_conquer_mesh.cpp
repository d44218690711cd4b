#include "algorithms/delaunay2d/divide_conquer_mesh.hpp"

#include <string>
#include <vector>

#include "kernel/error.hpp"

namespace dtlab::dc {

EdgeMesh::EdgeMesh(std::uint32_t points) {
  // At most 3n - 6 edges in a planar straight-line graph on n >= 3 points.
  capacity_ = 3 * static_cast<std::size_t>(points) + 3;
  DTLAB_ASSERT(2 * capacity_ < kNone);
  h_ = std::make_unique_for_overwrite<HalfEdge[]>(2 * capacity_);
  advise_huge_pages(h_.get(), 2 * capacity_ * sizeof(HalfEdge));
}

std::uint32_t EdgeMesh::make_edge(std::uint32_t a, std::uint32_t b) {
  std::uint32_t e;
  if (free_ != kNone) {
    e = free_;
    free_ = h_[2 * e].onext;
  } else {
    if (used_ >= capacity_)
      throw InternalError("divide-conquer Delaunay: more edges than a planar graph on " +
                          std::to_string(capacity_ / 3 - 1) + " points can have");
    e = used_++;
  }
  const std::uint32_t h = 2 * e;
  h_[h] = {a, h, h};
  h_[h + 1] = {b, h + 1, h + 1};
  return h;
}

void EdgeMesh::insert_after(std::uint32_t x, std::uint32_t h) noexcept {
  const std::uint32_t y = h_[x].onext;
  h_[x].onext = h;
  h_[h].oprev = x;
  h_[h].onext = y;
  h_[y].oprev = h;
}

std::uint32_t EdgeMesh::connect(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t h = make_edge(dest(a), org(b));
  insert_after(lnext(a), h);
  insert_after(b, sym(h));
  return h;
}

void EdgeMesh::unlink(std::uint32_t h) noexcept {
  const std::uint32_t n = h_[h].onext, p = h_[h].oprev;
  h_[p].onext = n;
  h_[n].oprev = p;
}

void EdgeMesh::delete_edge(std::uint32_t h) noexcept {
  const std::uint32_t even = h & ~1u;
  unlink(even);
  unlink(even + 1);
  h_[even] = {kNone, free_, kNone};
  h_[even + 1] = {kNone, kNone, kNone};
  free_ = even / 2;
}

void EdgeMesh::to_triangulation(std::uint32_t outer, std::span<const std::uint32_t> ids, Triangulation2& out) {
  constexpr std::uint32_t kInf = Triangulation2::kInfinite;
  const std::size_t m = ids.size();
  const std::size_t triangles = 2 * m - 2;
  const std::uint32_t slots = 2 * used_;
  // Each live half-edge's handle in the output, kept in onext (lnext reads only oprev).
  for (std::uint32_t h = 0; h < slots; ++h) h_[h].onext = kNone;
  const auto handle = [this](std::uint32_t h) -> std::uint32_t& { return h_[h].onext; };
  const auto alive = [this](std::uint32_t h) { return h_[h].org != kNone; };
  std::vector<std::uint32_t>& V = out.mutable_vertices();
  std::vector<std::uint32_t>& N = out.mutable_neighbours();
  out.reserve_triangles(triangles);
  V.assign(3 * triangles, Triangulation2::kNone);
  N.assign(3 * triangles, Triangulation2::kNone);

  // Ghosts, in order around the outer face: ghost t = (inf, org g, dest g) holds g as edge 0,
  // and its edge 1 (dest g -> inf) is the twin of the next ghost's edge 2 (inf -> dest g).
  std::uint32_t t = 0;
  std::uint32_t g = outer;
  do {
    if (t >= triangles) throw InternalError("divide-conquer Delaunay: outer face longer than the point count allows");
    V[3 * t] = kInf, V[3 * t + 1] = ids[org(g)], V[3 * t + 2] = ids[dest(g)];
    handle(g) = 3 * t;
    if (t > 0) out.link(3 * (t - 1) + 1, 3 * t + 2);
    ++t;
    g = lnext(g);
  } while (g != outer);
  out.link(3 * (t - 1) + 1, 2);

  // Finite triangles: h, lnext(h), lnext^2(h) run v0 -> v1, v1 -> v2, v2 -> v0, which are edges
  // 2, 0 and 1 of (v0, v1, v2).
  for (std::uint32_t h = 0; h < slots; ++h) {
    if (!alive(h) || handle(h) != kNone) continue;
    const std::uint32_t h1 = lnext(h), h2 = lnext(h1);
    if (lnext(h2) != h || handle(h1) != kNone || handle(h2) != kNone)
      throw InternalError("divide-conquer Delaunay: a face at half-edge " + std::to_string(h) + " is not a triangle");
    if (t >= triangles) throw InternalError("divide-conquer Delaunay: more triangles than 2m - 2");
    V[3 * t] = ids[org(h)], V[3 * t + 1] = ids[org(h1)], V[3 * t + 2] = ids[org(h2)];
    handle(h) = 3 * t + 2, handle(h1) = 3 * t, handle(h2) = 3 * t + 1;
    ++t;
  }
  if (t != triangles)
    throw InternalError("divide-conquer Delaunay: " + std::to_string(t) + " triangles instead of " +
                        std::to_string(triangles));
  for (std::uint32_t h = 0; h < slots; ++h)
    if (alive(h)) N[handle(h)] = handle(sym(h));
}

}  // namespace dtlab::dc
