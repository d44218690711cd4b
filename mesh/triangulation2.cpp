#include "mesh/triangulation2.hpp"

#include <string>

#include "kernel/error.hpp"

namespace dtlab {

namespace {

[[noreturn]] void topology_error(std::uint32_t h, const std::string& what) {
  throw InternalError("Triangulation2::check_topology: half-edge " + std::to_string(h) + " (triangle " +
                      std::to_string(h / 3) + ", edge " + std::to_string(h % 3) + "): " + what);
}

}  // namespace

void Triangulation2::reserve_triangles(std::size_t triangles) {
  const bool fresh = vertices_.capacity() < 3 * triangles;
  vertices_.reserve(3 * triangles);
  neighbours_.reserve(3 * triangles);
  if (fresh) {
    advise_huge_pages(vertices_.data(), vertices_.capacity() * sizeof(std::uint32_t));
    advise_huge_pages(neighbours_.data(), neighbours_.capacity() * sizeof(std::uint32_t));
  }
}

std::size_t Triangulation2::finite_triangle_count() const noexcept {
  std::size_t count = 0;
  for (std::size_t i = 0; i < vertices_.size(); i += 3) count += vertices_[i] != kInfinite;
  return count;
}

std::vector<std::array<std::uint32_t, 3>> Triangulation2::finite_triangles() const {
  std::vector<std::array<std::uint32_t, 3>> out;
  out.reserve(finite_triangle_count());
  for (std::size_t i = 0; i < vertices_.size(); i += 3) {
    if (vertices_[i] == kInfinite) continue;
    out.push_back({vertices_[i], vertices_[i + 1], vertices_[i + 2]});
  }
  return out;
}

std::uint32_t Triangulation2::add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  // Rotations keep the cyclic (counter-clockwise) order.
  if (b == kInfinite) {
    const std::uint32_t x = a;
    a = b, b = c, c = x;
  } else if (c == kInfinite) {
    const std::uint32_t x = c;
    c = b, b = a, a = x;
  }
  const auto t = static_cast<std::uint32_t>(triangle_count());
  vertices_.insert(vertices_.end(), {a, b, c});
  neighbours_.insert(neighbours_.end(), {kNone, kNone, kNone});
  return t;
}

void Triangulation2::check_topology() const {
  if (vertices_.size() % 3 != 0 || neighbours_.size() != vertices_.size())
    throw InternalError("Triangulation2::check_topology: " + std::to_string(vertices_.size()) +
                        " vertex entries and " + std::to_string(neighbours_.size()) +
                        " neighbour entries (want equal multiples of 3)");
  const std::size_t n = points_.size();
  const std::size_t size = vertices_.size();
  for (std::uint32_t h = 0; h < size; ++h) {
    const std::uint32_t v = vertices_[h];
    if (v == kInfinite) {
      if (h % 3 != 0) topology_error(h, "the infinite vertex is not vertex 0 of its triangle");
    } else if (v >= n) {
      topology_error(h, "vertex id " + std::to_string(v) + " out of range (" + std::to_string(n) + " points)");
    }
    if (v == vertices_[next(h)]) topology_error(h, "vertex " + std::to_string(v) + " repeated in its triangle");
    const std::uint32_t g = neighbours_[h];
    if (g >= size) topology_error(h, "no twin (" + std::to_string(g) + ")");
    if (triangle_of(g) == triangle_of(h)) topology_error(h, "twin in the same triangle");
    if (neighbours_[g] != h) topology_error(h, "twin " + std::to_string(g) + " does not point back");
    if (origin(g) != destination(h) || destination(g) != origin(h))
      topology_error(h, "twin " + std::to_string(g) + " does not run between the same vertices reversed");
  }
}

}  // namespace dtlab
