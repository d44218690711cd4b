// The volume check of checks_constrained3d.hpp: per region, the meshed volume against the
// volume the input encloses for it, by the divergence theorem (6 V = sum of det(a, b, c) over
// the region's boundary triangles turned outward), in GMP rationals.
#include <algorithm>
#include <climits>
#include <cmath>
#include <unordered_map>

#include "kernel/rounding.hpp"
#include "verify/checks_constrained3d.hpp"

namespace dtlab {

namespace {

using T3 = Tetrahedralization3;
using Ids3 = std::array<std::uint32_t, 3>;
constexpr int kRemoved = INT_MIN;

struct IdsHash {
  template <std::size_t N>
  std::size_t operator()(const std::array<std::uint32_t, N>& a) const noexcept {
    std::uint64_t h = 0;
    for (const std::uint32_t x : a) h = (h ^ x) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

template <std::size_t N>
std::array<std::uint32_t, N> sorted(std::array<std::uint32_t, N> a) {
  std::sort(a.begin(), a.end());
  return a;
}

Rational det6(const ExactPoint3& a, const ExactPoint3& b, const ExactPoint3& c) {
  return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
}

Rational tetrahedron_volume6(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const ExactPoint3 A = to_exact(a), B = to_exact(b), C = to_exact(c), D = to_exact(d);
  const ExactPoint3 u{B.x - A.x, B.y - A.y, B.z - A.z}, v{C.x - A.x, C.y - A.y, C.z - A.z},
      w{D.x - A.x, D.y - A.y, D.z - A.z};
  return det6(u, v, w);
}

ExactPoint3 exact_point(std::span<const Vec3> p, const SteinerPoint3& s) {
  if (s.kind == SteinerPoint3::Kind::OnEdge)
    return point_on_segment_exact(p[s.support[0]], p[s.support[1]], Rational(s.parameters[0]));
  const ExactPoint3 A = to_exact(p[s.support[0]]), B = to_exact(p[s.support[1]]), C = to_exact(p[s.support[2]]);
  const Rational S(s.parameters[0]), T(s.parameters[1]);
  return {A.x + S * (B.x - A.x) + T * (C.x - A.x), A.y + S * (B.y - A.y) + T * (C.y - A.y),
          A.z + S * (B.z - A.z) + T * (C.z - A.z)};
}

bool same_turn(const Ids3& a, const Ids3& b) {
  return (a[0] == b[0] && a[1] == b[1]) || (a[0] == b[1] && a[1] == b[2]) || (a[0] == b[2] && a[1] == b[0]);
}

}  // namespace

void check_region_volumes3(const ConstrainedInput3& input, const Constrained3dResult& r,
                           const ConstrainedCheckOptions3& options, ConstrainedCheckReport3& report) {
  const T3& t = r.tetrahedralization;
  const auto& v = r.vertices;
  const std::uint32_t ipc = r.input_point_count;
  // Region of every record of the tetrahedralization (kRemoved for ghosts and removed ones).
  std::unordered_map<std::array<std::uint32_t, 4>, int, IdsHash> region_of;
  for (std::size_t k = 0; k < r.tetrahedra.size(); ++k) {
    region_of.emplace(sorted(r.tetrahedra[k]), r.tetrahedron_regions[k]);
    report.region_volume6[r.tetrahedron_regions[k]] +=
        tetrahedron_volume6(v[r.tetrahedra[k][0]], v[r.tetrahedra[k][1]], v[r.tetrahedra[k][2]], v[r.tetrahedra[k][3]]);
  }
  const auto label = [&](std::uint32_t tet) {
    if (t.is_ghost(tet)) return kRemoved;
    const auto it = region_of.find(sorted(t.records()[tet].vertex));
    return it == region_of.end() ? kRemoved : it->second;
  };
  std::unordered_map<Ids3, std::uint32_t, IdsHash> facet_of;
  for (std::uint32_t k = 0; k < t.tetrahedron_count(); ++k)
    for (std::uint32_t i = 0; i < 4; ++i) facet_of.emplace(sorted(t.facet_vertices(T3::facet(k, i))), T3::facet(k, i));

  // The regions in front of (the side the turn points to) and behind each input triangle, and
  // for each region whether its boundary holds a Steiner point moved by rounding, and the bound.
  constexpr std::pair<int, int> kUnknown{kRemoved, INT_MAX};
  std::vector<std::pair<int, int>> sides(input.triangles.size(), kUnknown);
  std::unordered_map<int, bool> exact;
  std::unordered_map<int, double> bound;
  std::vector<signed char> moved(r.steiner.size(), -1);
  const auto is_moved = [&](std::uint32_t x) {
    const std::uint32_t i = x - ipc;
    if (moved[i] < 0) moved[i] = !(to_exact(v[x]) == exact_point(input.points, r.steiner[i]));
    return moved[i] == 1;
  };
  for (std::size_t k = 0; k < r.triangles.size(); ++k) {
    const Ids3& p = r.triangles[k];
    const std::uint32_t f = r.triangle_face[k];
    const auto it = facet_of.find(sorted(p));
    if (it == facet_of.end()) return;  // the face check reported it
    const std::uint32_t h = it->second;
    const bool front_is_h = same_turn(t.facet_vertices(h), p);
    const int a = label(T3::tetrahedron_of(front_is_h ? h : t.twin(h)));
    const int b = label(T3::tetrahedron_of(front_is_h ? t.twin(h) : h));
    if (sides[f] == kUnknown) {
      sides[f] = {a, b};
    } else if (sides[f] != std::pair<int, int>{a, b}) {
      report.add_problem("triangle " + std::to_string(f + options.first_number) +
                         ": its pieces do not all have the same regions on their two sides");
    }
    const Vec3 &x = v[p[0]], &y = v[p[1]], &z = v[p[2]];
    const Vec3 n = cross(y - x, z - x);
    const double area = 0.5 * std::sqrt(dot(n, n));
    for (const std::uint32_t q : p) {
      if (q < ipc || !is_moved(q)) continue;
      const double err = std::hypot(rounding_bound(v[q].x), rounding_bound(v[q].y), rounding_bound(v[q].z));
      for (const int side : {a, b}) {
        exact[side] = false;
        // Moving one vertex of a triangle by err sweeps at most err x its area.
        bound[side] += 6 * 2 * err * area;
      }
    }
  }
  std::map<int, Rational> enclosed6;
  for (std::uint32_t f = 0; f < input.triangles.size(); ++f) {
    const auto [front, back] = sides[f];
    if (front == back || sides[f] == kUnknown) continue;
    const auto& c = input.triangles[f];
    const Rational d = det6(to_exact(input.points[c[0]]), to_exact(input.points[c[1]]), to_exact(input.points[c[2]]));
    if (back != kRemoved) enclosed6[back] += d;
    if (front != kRemoved) enclosed6[front] -= d;
  }
  for (const auto& [region, meshed] : report.region_volume6) {
    if (options.keep_exterior && region == 0) continue;  // unbounded
    ++report.regions;
    const Rational& in = enclosed6[region];
    const std::string name = "region " + std::to_string(region);
    if (!exact.count(region)) {
      ++report.exact_volumes;
      if (meshed != in)
        report.add_problem(name + ": 6 x its meshed volume is " + meshed.to_string() + ", 6 x the volume the input encloses for it " + in.to_string());
    } else {
      const double diff = std::fabs(round_to_double(meshed - in));
      if (!(diff <= bound[region]))
        report.add_problem(name + ": its meshed volume differs from the input's by " + std::to_string(diff / 6) +
                           ", more than the rounding bound " + std::to_string(bound[region] / 6));
    }
  }
}

}  // namespace dtlab
