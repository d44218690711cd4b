#include "algorithms/constrained3d/plc/plc_checks.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/intersections.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

namespace {

struct Box {
  Vec3 lo, hi;
};

Box face_box(std::span<const Vec3> points, const Face3& f) {
  Box b{points[f[0]], points[f[0]]};
  for (int k = 1; k < 3; ++k) {
    const Vec3& p = points[f[k]];
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  return b;
}

bool boxes_overlap(const Box& a, const Box& b) noexcept {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}

// A uniform grid over the faces' bounding boxes, stored as sorted (cell, face) pairs: only the
// occupied cells cost memory. The cell size is the mean box extent, so that a typical face
// lies in a few cells and a cell holds a few faces; faces spanning many cells (much larger than
// the mean) are kept aside and tested against every box.
class FaceGrid {
 public:
  FaceGrid(const std::vector<Box>& boxes) : boxes_(boxes) {
    Box all = boxes.front();
    double extent = 0.0;
    for (const Box& b : boxes) {
      all.lo = {std::min(all.lo.x, b.lo.x), std::min(all.lo.y, b.lo.y), std::min(all.lo.z, b.lo.z)};
      all.hi = {std::max(all.hi.x, b.hi.x), std::max(all.hi.y, b.hi.y), std::max(all.hi.z, b.hi.z)};
      extent += std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z});
    }
    lo_ = all.lo;
    const double span = std::max({all.hi.x - all.lo.x, all.hi.y - all.lo.y, all.hi.z - all.lo.z});
    double cell = extent / static_cast<double>(boxes.size());
    if (!(cell > 0.0) || !std::isfinite(cell)) cell = span > 0.0 ? span : 1.0;
    cell = std::max(cell, span / static_cast<double>(kMaxCellsPerAxis - 1));
    inverse_ = span > 0.0 ? 1.0 / cell : 0.0;
    for (std::uint32_t f = 0; f < boxes.size(); ++f) {
      const auto lo = cell_of(boxes[f].lo), hi = cell_of(boxes[f].hi);
      const std::uint64_t cells = std::uint64_t{hi[0] - lo[0] + 1} * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
      if (cells > kMaxCellsPerFace) {
        large_.push_back(f);
        continue;
      }
      for (std::uint32_t z = lo[2]; z <= hi[2]; ++z)
        for (std::uint32_t y = lo[1]; y <= hi[1]; ++y)
          for (std::uint32_t x = lo[0]; x <= hi[0]; ++x) entries_.push_back({key(x, y, z), f});
    }
    std::sort(entries_.begin(), entries_.end(),
              [](const Entry& a, const Entry& b) { return a.cell != b.cell ? a.cell < b.cell : a.face < b.face; });
  }

  // Calls visit(f, g) once for every pair f < g of faces whose boxes overlap.
  template <class Visit>
  void for_each_overlapping_pair(Visit&& visit) const {
    for (std::size_t begin = 0; begin < entries_.size();) {
      std::size_t end = begin + 1;
      while (end < entries_.size() && entries_[end].cell == entries_[begin].cell) ++end;
      for (std::size_t i = begin; i < end; ++i)
        for (std::size_t j = i + 1; j < end; ++j) {
          const std::uint32_t f = entries_[i].face, g = entries_[j].face;
          if (!boxes_overlap(boxes_[f], boxes_[g])) continue;
          // Each pair shares several cells; it is visited in the one holding the lower corner
          // of the boxes' intersection.
          const Box& a = boxes_[f];
          const Box& b = boxes_[g];
          const auto c = cell_of({std::max(a.lo.x, b.lo.x), std::max(a.lo.y, b.lo.y), std::max(a.lo.z, b.lo.z)});
          if (key(c[0], c[1], c[2]) != entries_[begin].cell) continue;
          visit(f, g);
        }
      begin = end;
    }
    std::vector<bool> is_large(boxes_.size(), false);
    for (const std::uint32_t f : large_) is_large[f] = true;
    for (const std::uint32_t f : large_)
      for (std::uint32_t g = 0; g < boxes_.size(); ++g) {
        if (g == f || (is_large[g] && g < f)) continue;  // large pairs once
        if (boxes_overlap(boxes_[f], boxes_[g])) visit(std::min(f, g), std::max(f, g));
      }
  }

 private:
  static constexpr std::uint32_t kMaxCellsPerAxis = 1u << 20;
  static constexpr std::uint64_t kMaxCellsPerFace = 64;
  struct Entry {
    std::uint64_t cell;
    std::uint32_t face;
  };

  std::array<std::uint32_t, 3> cell_of(const Vec3& p) const noexcept {
    auto axis = [&](double v, double lo) {
      const double c = std::floor((v - lo) * inverse_);
      return static_cast<std::uint32_t>(std::clamp(c, 0.0, static_cast<double>(kMaxCellsPerAxis - 1)));
    };
    return {axis(p.x, lo_.x), axis(p.y, lo_.y), axis(p.z, lo_.z)};
  }
  static std::uint64_t key(std::uint64_t x, std::uint64_t y, std::uint64_t z) noexcept {
    return (z << 40) | (y << 20) | x;
  }

  const std::vector<Box>& boxes_;
  Vec3 lo_;
  double inverse_ = 0.0;
  std::vector<Entry> entries_;
  std::vector<std::uint32_t> large_;
};

template <class T, class Show>
std::string list_items(const std::vector<T>& items, Show show) {
  std::ostringstream s;
  for (std::size_t i = 0; i < items.size() && i < 10; ++i) s << (i ? ", " : "") << show(items[i]);
  if (items.size() > 10) s << ", ... (" << items.size() << " in all)";
  return s.str();
}

// Coplanar faces a and b (projected: A, B), sharing at most one vertex: true when the line of an
// edge of a holds every shared vertex and has b's other vertices strictly on its outer side, so
// that a and b meet at most at the shared vertex (most coplanar neighbours on a flat face are
// told apart so, with three orient2d per edge, before the segment tests).
bool separated_by_an_edge2(const std::array<Vec2, 3>& A, const std::array<Vec2, 3>& B, const Face3& a,
                           const Face3& b) noexcept {
  const Sign inner = orient2d(A[0], A[1], A[2]);
  for (int k = 0; k < 3; ++k) {
    bool separates = true;
    for (int j = 0; j < 3 && separates; ++j) {
      if (b[j] == a[k] || b[j] == a[(k + 1) % 3]) continue;  // shared, on this edge's line
      if (b[j] == a[(k + 2) % 3]) {
        separates = false;  // shared, off this edge's line
        continue;
      }
      const Sign s = orient2d(A[k], A[(k + 1) % 3], B[j]);
      separates = s != Sign::Zero && s != inner;
    }
    if (separates) return true;
  }
  return false;
}

}  // namespace

bool faces_intersect_improperly(std::span<const Vec3> P, const Face3& f, const Face3& g) noexcept {
  int shared = 0;
  for (const std::uint32_t v : f) shared += std::count(g.begin(), g.end(), v) > 0;
  if (shared == 3) return true;
  if (shared == 2) {
    // Along a common edge (u, v), faces (u, v, a) and (u, v, b) overlap only when they are
    // coplanar and a, b lie on the same side of the edge.
    std::uint32_t u = 0, v = 0, a = 0, b = 0;
    int k = 0;
    for (const std::uint32_t x : f) {
      if (std::count(g.begin(), g.end(), x) > 0)
        (k++ == 0 ? u : v) = x;
      else
        a = x;
    }
    for (const std::uint32_t x : g)
      if (x != u && x != v) b = x;
    if (orient3d(P[u], P[v], P[a], P[b]) != Sign::Zero) return false;
    const int axis = projection_axis(P[u], P[v], P[a]);
    return orient2d(project(P[u], axis), project(P[v], axis), project(P[a], axis)) ==
           orient2d(project(P[u], axis), project(P[v], axis), project(P[b], axis));
  }
  // The vertices of g not on f against f's plane: strictly on one side, g meets f at most at
  // their shared vertex; all on it, the faces are coplanar and the question is a 2D one in a
  // projection that keeps f (and so g) a triangle; else f's vertices against g's plane.
  Sign side = Sign::Zero;
  bool mixed = false, coplanar = true;
  for (const std::uint32_t x : g) {
    if (x == f[0] || x == f[1] || x == f[2]) continue;
    const Sign s = orient3d(P[f[0]], P[f[1]], P[f[2]], P[x]);
    coplanar = coplanar && s == Sign::Zero;
    if (s == Sign::Zero || (side != Sign::Zero && s != side)) mixed = true;
    if (s != Sign::Zero) side = s;
  }
  if (!mixed) return false;
  if (coplanar) {
    const int axis = projection_axis(P[f[0]], P[f[1]], P[f[2]]);
    std::array<Vec2, 3> F, G;
    for (int k = 0; k < 3; ++k) F[k] = project(P[f[k]], axis), G[k] = project(P[g[k]], axis);
    if (separated_by_an_edge2(F, G, f, g) || separated_by_an_edge2(G, F, g, f)) return false;
    // An edge of one (the one opposite the shared vertex, if any) meets the other.
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t p = f[k], q = f[(k + 1) % 3];
      if (shared == 1 && (std::count(g.begin(), g.end(), p) || std::count(g.begin(), g.end(), q))) continue;
      if (segment_meets_triangle2(F[k], F[(k + 1) % 3], G[0], G[1], G[2])) return true;
    }
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t p = g[k], q = g[(k + 1) % 3];
      if (shared == 1 && (std::count(f.begin(), f.end(), p) || std::count(f.begin(), f.end(), q))) continue;
      if (segment_meets_triangle2(G[k], G[(k + 1) % 3], F[0], F[1], F[2])) return true;
    }
    return false;
  }
  {
    Sign other = Sign::Zero;
    bool separated = true;
    for (const std::uint32_t x : f) {
      if (x == g[0] || x == g[1] || x == g[2]) continue;
      const Sign s = orient3d(P[g[0]], P[g[1]], P[g[2]], P[x]);
      if (s == Sign::Zero || (other != Sign::Zero && s != other)) separated = false;
      other = s;
    }
    if (separated) return false;
  }
  const auto edge_meets = [&](std::uint32_t p, std::uint32_t q, const Face3& t) {
    return segment_meets_triangle3(P[p], P[q], P[t[0]], P[t[1]], P[t[2]]);
  };
  if (shared == 1) {
    // With a common vertex v, f and g meet elsewhere iff the edge of one opposite v meets the
    // other: the intersection is convex and contains v, and its point farthest from v along
    // any ray lies where the ray leaves f (through f's edge opposite v) or g.
    std::uint32_t common = 0;
    for (const std::uint32_t x : f)
      if (std::count(g.begin(), g.end(), x) > 0) common = x;
    std::array<std::uint32_t, 2> fo{}, go{};
    int i = 0, j = 0;
    for (const std::uint32_t x : f)
      if (x != common) fo[i++] = x;
    for (const std::uint32_t x : g)
      if (x != common) go[j++] = x;
    return edge_meets(fo[0], fo[1], g) || edge_meets(go[0], go[1], f);
  }
  // Disjoint vertex sets: closed triangles meet iff an edge of one meets the other.
  for (int k = 0; k < 3; ++k) {
    if (edge_meets(f[k], f[(k + 1) % 3], g)) return true;
    if (edge_meets(g[k], g[(k + 1) % 3], f)) return true;
  }
  return false;
}

PlcReport inspect_plc(std::span<const Vec3> points, std::span<const Face3> faces) {
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (const std::uint32_t v : faces[i])
      if (v >= points.size())
        throw InputError("face " + std::to_string(i + 1) + " refers to vertex " + std::to_string(std::uint64_t{v} + 1) +
                             " but there are " + std::to_string(points.size()) + " vertices",
                         {i});
  check_coordinates(points, "vertex");

  PlcReport report;
  // 2. Duplicate vertices among those the faces use.
  std::vector<std::uint32_t> used;
  used.reserve(3 * faces.size());
  for (const Face3& f : faces) used.insert(used.end(), f.begin(), f.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::stable_sort(used.begin(), used.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return points[a] < points[b]; });
  for (std::size_t k = 1; k < used.size(); ++k)
    if (points[used[k]] == points[used[k - 1]]) {
      std::size_t first = k - 1;
      while (first > 0 && points[used[first - 1]] == points[used[k]]) --first;
      report.duplicate_vertices.push_back({std::min(used[first], used[k]), std::max(used[first], used[k])});
    }
  std::sort(report.duplicate_vertices.begin(), report.duplicate_vertices.end());

  // 3. Degenerate faces; 4. duplicate faces.
  std::vector<std::pair<Face3, std::uint32_t>> sorted_faces;
  sorted_faces.reserve(faces.size());
  for (std::uint32_t i = 0; i < faces.size(); ++i) {
    const Face3& f = faces[i];
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2] || collinear3(points[f[0]], points[f[1]], points[f[2]])) {
      report.degenerate_faces.push_back(i);
    }
    Face3 s = f;
    std::sort(s.begin(), s.end());
    sorted_faces.push_back({s, i});
  }
  std::sort(sorted_faces.begin(), sorted_faces.end());
  for (std::size_t k = 1; k < sorted_faces.size(); ++k)
    if (sorted_faces[k].first == sorted_faces[k - 1].first) {
      std::size_t first = k - 1;
      while (first > 0 && sorted_faces[first - 1].first == sorted_faces[k].first) --first;
      report.duplicate_faces.push_back({sorted_faces[first].second, sorted_faces[k].second});
    }
  std::sort(report.duplicate_faces.begin(), report.duplicate_faces.end());

  // 5. Edges by the number of faces on them.
  std::vector<std::array<std::uint32_t, 2>> edges;
  edges.reserve(3 * faces.size());
  for (const Face3& f : faces)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = f[k], b = f[(k + 1) % 3];
      if (a != b) edges.push_back({std::min(a, b), std::max(a, b)});
    }
  std::sort(edges.begin(), edges.end());
  for (std::size_t begin = 0; begin < edges.size();) {
    std::size_t end = begin + 1;
    while (end < edges.size() && edges[end] == edges[begin]) ++end;
    if (end - begin == 1) report.free_edges.push_back(edges[begin]);
    if (end - begin >= 3) report.nonmanifold_edges.push_back(edges[begin]);
    begin = end;
  }

  // 6. Self-intersections, on proper faces only.
  if (faces.empty() || !report.duplicate_vertices.empty() || !report.degenerate_faces.empty() ||
      !report.duplicate_faces.empty())
    return report;
  std::vector<Box> boxes;
  boxes.reserve(faces.size());
  for (const Face3& f : faces) boxes.push_back(face_box(points, f));
  FaceGrid grid(boxes);
  grid.for_each_overlapping_pair([&](std::uint32_t f, std::uint32_t g) {
    if (faces_intersect_improperly(points, faces[f], faces[g])) report.intersecting_faces.push_back({f, g});
  });
  std::sort(report.intersecting_faces.begin(), report.intersecting_faces.end());
  return report;
}

void check_plc(std::span<const Vec3> points, std::span<const Face3> faces, const FaceNamer& face_name) {
  const PlcReport r = inspect_plc(points, faces);
  const auto number = [](std::uint64_t i) { return std::to_string(i + 1); };
  // With names, each face is its name alone ("face 2", "quadrilateral 3 (triangle 1 of 2)").
  const auto face = [&](std::uint64_t i) { return face_name ? face_name(static_cast<std::uint32_t>(i)) : number(i); };
  const std::string faces_word = face_name ? "" : "faces ", face_word = face_name ? "" : "face(s) ";
  const auto pair = [&](const auto& p) { return number(p.first) + " and " + number(p.second); };
  const auto face_pair = [&](const auto& p) { return face(p.first) + " and " + face(p.second); };
  const auto edge = [&](const std::array<std::uint32_t, 2>& e) { return number(e[0]) + "-" + number(e[1]); };
  if (!r.duplicate_vertices.empty()) {
    std::vector<std::uint64_t> items;
    for (const auto& p : r.duplicate_vertices) items.insert(items.end(), {p.first, p.second});
    throw InputError(std::to_string(r.duplicate_vertices.size()) +
                         " duplicate vertex pair(s) (same coordinates): vertices " + list_items(r.duplicate_vertices, pair),
                     items);
  }
  if (!r.degenerate_faces.empty())
    throw InputError(std::to_string(r.degenerate_faces.size()) +
                         " degenerate face(s) (zero area: repeated or collinear vertices): " + face_word +
                         list_items(r.degenerate_faces, face),
                     {r.degenerate_faces.begin(), r.degenerate_faces.end()});
  if (!r.duplicate_faces.empty()) {
    std::vector<std::uint64_t> items;
    for (const auto& p : r.duplicate_faces) items.insert(items.end(), {p.first, p.second});
    throw InputError(std::to_string(r.duplicate_faces.size()) + " duplicate face pair(s): " + faces_word +
                         list_items(r.duplicate_faces, face_pair),
                     items);
  }
  if (!r.free_edges.empty()) {
    std::vector<std::uint64_t> items;
    for (const auto& e : r.free_edges) items.insert(items.end(), {e[0], e[1]});
    throw InputError("the surface is open: " + std::to_string(r.free_edges.size()) +
                         " free edge(s) (on one face only), between vertices " + list_items(r.free_edges, edge),
                     items);
  }
  if (!r.intersecting_faces.empty()) {
    std::vector<std::uint64_t> items;
    for (const auto& p : r.intersecting_faces) items.insert(items.end(), {p.first, p.second});
    throw InputError("the surface intersects itself: " + std::to_string(r.intersecting_faces.size()) +
                         " pair(s) of faces meet other than along a shared edge or vertex: " + faces_word +
                         list_items(r.intersecting_faces, face_pair),
                     items);
  }
}

}  // namespace dtlab
