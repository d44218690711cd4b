#include "algorithms/surface/surface_support3.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>

#include "kernel/error.hpp"

namespace dtlab {

namespace {

Vec3 unit(const Vec3& v) {
  const double n = norm(v);
  return n > 0.0 ? (1.0 / n) * v : v;
}

double angle_between(const Vec3& a, const Vec3& b) {
  const double na = norm(a), nb = norm(b);
  if (!(na > 0.0) || !(nb > 0.0)) return 0.0;
  return std::atan2(norm(cross(a, b)), dot(a, b));
}

std::string edge_name(std::uint32_t a, std::uint32_t b) { return std::to_string(a + 1) + "-" + std::to_string(b + 1); }

// The tangent at m of the circle through p, m, q, pointing from p towards q: |m - p|^2 (q - m) +
// |q - m|^2 (m - p) (the chords weighted by each other's squared length; the chord pq's direction
// when the two are equal). Collinear points give the line.
Vec3 middle_circle_tangent(const Vec3& p, const Vec3& m, const Vec3& q) {
  const Vec3 u = m - p, w = q - m;
  return unit(dot(u, u) * w + dot(w, w) * u);
}

}  // namespace

TrianglePoint nearest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {a, {1, 0, 0}};
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return {b, {0, 1, 0}};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return {a + v * ab, {1 - v, v, 0}};
  }
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return {c, {0, 0, 1}};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return {a + w * ac, {1 - w, 0, w}};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + w * (c - b), {0, 1 - w, w}};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {a + v * ab + w * ac, {1 - v - w, v, w}};
}

SurfaceSupport3::SurfaceSupport3(std::span<const Vec3> points, std::span<const std::array<std::uint32_t, 3>> triangles,
                                 std::span<const int> triangle_refs, const SurfaceSupportOptions& options)
    : points_(points.begin(), points.end()), triangles_(triangles.begin(), triangles.end()) {
  if (triangles_.empty()) throw InputError("surface support: no triangles");
  if (!triangle_refs.empty() && triangle_refs.size() != triangles_.size())
    throw InputError("surface support: " + std::to_string(triangle_refs.size()) + " references for " +
                     std::to_string(triangles_.size()) + " triangles");
  if (!(options.ridge_angle_degrees >= 0.0 && options.ridge_angle_degrees <= 180.0))
    throw InputError("surface support: the ridge angle must lie in [0, 180] degrees");
  refs_ = triangle_refs.empty() ? std::vector<int>(triangles_.size(), 0)
                                : std::vector<int>(triangle_refs.begin(), triangle_refs.end());
  for (std::size_t v = 0; v < points_.size(); ++v) {
    const Vec3& p = points_[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError("surface support: point " + std::to_string(v + 1) + " is not finite", {v});
  }
  const auto n = static_cast<std::uint32_t>(triangles_.size());
  face_normals_.resize(n);
  for (std::uint32_t t = 0; t < n; ++t) {
    const auto& v = triangles_[t];
    for (const std::uint32_t x : v)
      if (x >= points_.size())
        throw InputError("surface support: triangle " + std::to_string(t + 1) + " has vertex " + std::to_string(x + 1) +
                             ", past the " + std::to_string(points_.size()) + " points",
                         {t});
    const Vec3 normal = cross(points_[v[1]] - points_[v[0]], points_[v[2]] - points_[v[0]]);
    if (!(norm(normal) > 0.0))
      throw InputError("surface support: triangle " + std::to_string(t + 1) + " has zero area", {t});
    face_normals_[t] = unit(normal);
  }
  // Edges: (lower vertex, higher vertex, half-edge), sorted, so each edge's triangles are adjacent.
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> halves;
  halves.reserve(3 * n);
  for (std::uint32_t t = 0; t < n; ++t)
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t a = triangles_[t][i], b = triangles_[t][(i + 1) % 3];
      halves.emplace_back(std::min(a, b), std::max(a, b), 3 * t + i);
    }
  std::sort(halves.begin(), halves.end());
  neighbours_.assign(3 * n, kNone);
  edge_.assign(3 * n, kNone);
  for (std::size_t k = 0; k < halves.size();) {
    std::size_t end = k + 1;
    while (end < halves.size() && std::get<0>(halves[end]) == std::get<0>(halves[k]) &&
           std::get<1>(halves[end]) == std::get<1>(halves[k]))
      ++end;
    const auto [a, b, h] = halves[k];
    if (end - k > 2 && !options.non_manifold_ridges)
      throw InputError("surface support: edge " + edge_name(a, b) + " is in " + std::to_string(end - k) +
                           " triangles (a manifold surface has at most two)",
                       {a, b});
    const auto e = static_cast<std::uint32_t>(edge_vertices_.size());
    edge_vertices_.push_back({a, b});
    edge_halves_.push_back(h);
    for (std::size_t j = k; j < end; ++j) edge_[std::get<2>(halves[j])] = e;
    if (end - k == 2) {
      const std::uint32_t g = std::get<2>(halves[k + 1]);
      const bool flipped = triangles_[h / 3][h % 3] == triangles_[g / 3][g % 3];
      if (flipped && !options.non_manifold_ridges)
        throw InputError("surface support: triangles " + std::to_string(h / 3 + 1) + " and " + std::to_string(g / 3 + 1) +
                             " are oriented differently across edge " + edge_name(a, b),
                         {h / 3, g / 3});
      if (!flipped) neighbours_[h] = g / 3, neighbours_[g] = h / 3;
    }
    k = end;
  }
  build_features(options.ridge_angle_degrees);
  build_sectors();
  build_edge_curves();
  grid_ = ElementGrid<Vec3>(std::span<const Vec3>(points_), std::span<const std::array<std::uint32_t, 3>>(triangles_));
}

void SurfaceSupport3::build_features(double ridge_angle_degrees) {
  const double limit = ridge_angle_degrees * std::numbers::pi / 180.0;
  const auto n = static_cast<std::uint32_t>(triangles_.size());
  ridge_.assign(3 * n, 0);
  ridge_neighbours_.assign(points_.size(), {kNone, kNone});
  std::vector<std::uint32_t> degree(points_.size(), 0);
  for (std::uint32_t t = 0; t < n; ++t)
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t u = neighbours_[3 * t + i];
      const bool ridge = u == kNone || refs_[u] != refs_[t] || angle_between(face_normals_[t], face_normals_[u]) > limit;
      ridge_[3 * t + i] = ridge ? 1 : 0;
    }
  for (std::uint32_t e = 0; e < edge_vertices_.size(); ++e) {
    if (!ridge_[edge_halves_[e]]) continue;
    ++ridge_edges_;
    const auto [a, b] = edge_vertices_[e];
    for (const auto& [x, y] : {std::pair{a, b}, std::pair{b, a}}) {
      if (degree[x] < 2) ridge_neighbours_[x][degree[x]] = y;
      ++degree[x];
    }
  }
  corner_.assign(points_.size(), 0);
  for (std::uint32_t v = 0; v < points_.size(); ++v) {
    if (degree[v] == 0) continue;
    bool corner = degree[v] != 2;
    if (!corner) {
      const Vec3& p = points_[ridge_neighbours_[v][0]];
      const Vec3& q = points_[ridge_neighbours_[v][1]];
      corner = angle_between(points_[v] - p, q - points_[v]) > limit;
    }
    corner_[v] = corner ? 1 : 0;
    corners_ += corner ? 1 : 0;
  }
}

void SurfaceSupport3::build_sectors() {
  const auto n = static_cast<std::uint32_t>(triangles_.size());
  sector_.assign(3 * n, kNone);
  std::vector<std::uint32_t> fan;
  for (std::uint32_t c0 = 0; c0 < 3 * n; ++c0) {
    if (sector_[c0] != kNone) continue;
    const std::uint32_t v = triangles_[c0 / 3][c0 % 3];
    // Walk around v both ways from corner c0, across edges that are no ridges: at corner i of t
    // the edges are i (to vertex i + 1) and i + 2 (from vertex i + 2).
    fan.assign(1, c0);
    bool closed = false;
    for (const std::uint32_t side : {0u, 2u}) {
      std::uint32_t c = c0;
      for (std::uint32_t step = 0;; ++step) {
        if (step > n) throw InternalError("surface support: the triangles around vertex " + std::to_string(v + 1) + " do not close");
        const std::uint32_t t = c / 3, i = c % 3;
        const std::uint32_t e = 3 * t + (i + side) % 3;
        if (ridge_[e]) break;
        const std::uint32_t u = neighbours_[e];
        const auto& tu = triangles_[u];
        const std::uint32_t j = tu[0] == v ? 0 : tu[1] == v ? 1 : 2;
        c = 3 * u + j;
        if (c == c0) {  // the fan closed: no ridge at v
          closed = true;
          break;
        }
        fan.push_back(c);
      }
      if (closed) break;
    }
    Vec3 sum{};
    for (const std::uint32_t c : fan) {
      const auto& tv = triangles_[c / 3];
      const std::uint32_t i = c % 3;
      const Vec3& p = points_[tv[i]];
      const Vec3 e1 = points_[tv[(i + 1) % 3]] - p, e2 = points_[tv[(i + 2) % 3]] - p;
      sum = sum + (1.0 / (dot(e1, e1) * dot(e2, e2))) * cross(e1, e2);
    }
    const auto s = static_cast<std::uint32_t>(sector_normals_.size());
    sector_normals_.push_back(norm(sum) > 0.0 ? unit(sum) : face_normals_[c0 / 3]);
    for (const std::uint32_t c : fan) sector_[c] = s;
  }
}

Vec3 SurfaceSupport3::ridge_tangent(std::uint32_t v, std::uint32_t towards) const {
  const auto& rv = ridge_neighbours_[v];
  if (!corner_[v]) return middle_circle_tangent(points_[rv[0] == towards ? rv[1] : rv[0]], points_[v], points_[towards]);
  // At a corner, one-sided: the circle through v, `towards` and the ridge vertex after it,
  // mirrored from `towards` across the chord's perpendicular bisector.
  const auto& rw = ridge_neighbours_[towards];
  const Vec3 u = unit(points_[towards] - points_[v]);
  if (corner_[towards]) return u;
  const std::uint32_t after = rw[0] == v ? rw[1] : rw[0];
  const Vec3 t1 = middle_circle_tangent(points_[v], points_[towards], points_[after]);
  return unit(2.0 * dot(t1, u) * u - t1);
}

void SurfaceSupport3::build_edge_curves() {
  edge_controls_.resize(edge_vertices_.size());
  std::vector<std::uint8_t> done(edge_vertices_.size(), 0);
  const auto n = static_cast<std::uint32_t>(triangles_.size());
  for (std::uint32_t h = 0; h < 3 * n; ++h) {
    const std::uint32_t e = edge_[h];
    if (done[e]) continue;
    done[e] = 1;
    const auto [a, b] = edge_vertices_[e];
    const std::uint32_t t = h / 3, i = h % 3;
    // The tangent leaving x towards y, x at corner k of t.
    auto leaving = [&](std::uint32_t x, std::uint32_t y, std::uint32_t k) {
      if (ridge_[h]) return ridge_tangent(x, y);
      const Vec3 d = points_[y] - points_[x];
      const Vec3& normal = sector_normals_[sector_[3 * t + k]];
      const Vec3 in_plane = d - dot(d, normal) * normal;
      return norm(in_plane) > 0.0 ? unit(in_plane) : unit(d);
    };
    const std::uint32_t ka = triangles_[t][i] == a ? i : (i + 1) % 3;
    const std::uint32_t kb = ka == i ? (i + 1) % 3 : i;
    const Vec3 ta = leaving(a, b, ka), tb = leaving(b, a, kb);
    const double theta = angle_between(ta, -1.0 * tb);
    const double c = std::cos(std::min(theta, std::numbers::pi) / 4.0);
    const double length = norm(points_[b] - points_[a]) / (3.0 * c * c);
    edge_controls_[e] = {points_[a] + length * ta, points_[b] + length * tb};
  }
  centres_.resize(n);
  for (std::uint32_t t = 0; t < n; ++t) {
    Vec3 edges{}, corners{};
    for (std::uint32_t i = 0; i < 3; ++i) {
      const auto& ctrl = edge_controls_[edge_of(t, i)];
      edges = edges + ctrl[0] + ctrl[1];
      corners = corners + points_[triangles_[t][i]];
    }
    const Vec3 mean_edges = (1.0 / 6.0) * edges, mean_corners = (1.0 / 3.0) * corners;
    centres_[t] = mean_edges + 0.5 * (mean_edges - mean_corners);
  }
}

Vec3 SurfaceSupport3::edge_point(std::uint32_t t, std::uint32_t i, double s) const {
  const std::uint32_t e = edge_of(t, i);
  return edge_curve(e, triangles_[t][i] == edge_vertices_[e][0] ? s : 1.0 - s);
}

Vec3 SurfaceSupport3::edge_curve(std::uint32_t e, double r) const {
  const auto [lo, hi] = edge_vertices_[e];
  const double q = 1.0 - r;
  const auto& ctrl = edge_controls_[e];
  const Vec3& origin = points_[lo];
  // Relative to the first control point (the Bernstein weights sum to 1): a curve in a plane
  // x = c keeps x = c exactly.
  return origin + ((3.0 * q * q * r) * (ctrl[0] - origin) + (3.0 * q * r * r) * (ctrl[1] - origin) +
                   (r * r * r) * (points_[hi] - origin));
}

Vec3 SurfaceSupport3::surface_point(std::uint32_t t, std::array<double, 3> w) const {
  for (double& x : w) x = std::max(x, 0.0);
  const double sum = w[0] + w[1] + w[2];
  if (!(sum > 0.0)) throw InputError("surface support: barycentric weights with no positive one");
  for (double& x : w) x /= sum;
  const auto& v = triangles_[t];
  for (std::uint32_t i = 0; i < 3; ++i) {
    const std::uint32_t j = (i + 1) % 3, k = (i + 2) % 3;
    if (w[j] == 0.0 && w[k] == 0.0) return points_[v[i]];
    if (w[k] == 0.0) {
      // On edge i: the parameter from its lower vertex, from the weights alone (the same bits
      // from either triangle).
      return edge_curve(edge_of(t, i), (v[i] < v[j] ? w[j] : w[i]) / (w[i] + w[j]));
    }
  }
  // Cubic Bézier triangle: b_ijk weighted by 3! / (i! j! k!) u^i v^j x^k.
  const double u = w[0], vv = w[1], x = w[2];
  auto control = [&](std::uint32_t edge, std::uint32_t near) {  // the inner control point of edge `edge` near its vertex `near`
    const std::uint32_t e = edge_of(t, edge);
    return edge_controls_[e][v[near] == edge_vertices_[e][0] ? 0 : 1];
  };
  const Vec3& o = points_[v[0]];  // relative to it, as edge_curve
  return o + ((vv * vv * vv) * (points_[v[1]] - o) + (x * x * x) * (points_[v[2]] - o) +
              (3.0 * u * u * vv) * (control(0, 0) - o) + (3.0 * u * vv * vv) * (control(0, 1) - o) +
              (3.0 * vv * vv * x) * (control(1, 1) - o) + (3.0 * vv * x * x) * (control(1, 2) - o) +
              (3.0 * x * x * u) * (control(2, 2) - o) + (3.0 * x * u * u) * (control(2, 0) - o) +
              (6.0 * u * vv * x) * (centres_[t] - o));
}

SurfaceSupport3::Foot SurfaceSupport3::project(const Vec3& p) const {
  const std::uint32_t t = grid_.nearest(p, [&](std::uint32_t e) {
    const auto& v = triangles_[e];
    return norm(p - nearest_on_triangle(p, points_[v[0]], points_[v[1]], points_[v[2]]).point);
  });
  const auto& v = triangles_[t];
  const TrianglePoint near = nearest_on_triangle(p, points_[v[0]], points_[v[1]], points_[v[2]]);
  return {t, near.weights, near.point, surface_point(t, near.weights)};
}

}  // namespace dtlab
