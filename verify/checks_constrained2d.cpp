// The checks of checks_constrained2d.hpp: validity in doubles, constraint chains with the
// rounding bounds of Steiner points (ROADMAP.md, "Steiner points and rounding"), and the local
// Delaunay property with or without constrained edges (book §3.4, Definition 3.6).
#include "verify/checks_constrained2d.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <utility>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "kernel/predicates/perturbation.hpp"
#include "kernel/rounding.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab {

namespace {

using T2 = Triangulation2;
using Report = ConstrainedCheckReport2;

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

// Point, segment and edge names in the report's numbering.
struct Namer {
  std::uint32_t first;
  std::string point(std::uint64_t v) const { return "point " + std::to_string(v + first); }
  std::string segment(std::uint64_t k) const { return "segment " + std::to_string(k + first); }
  std::string edge(std::uint32_t a, std::uint32_t b) const {
    return "edge " + std::to_string(a + first) + "-" + std::to_string(b + first);
  }
  std::string triangle(const TriangleIds& t) const {
    return "triangle (" + std::to_string(t[0] + first) + "," + std::to_string(t[1] + first) + "," +
           std::to_string(t[2] + first) + ")";
  }
};

std::string coordinates(const Vec2& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
  return buf;
}

TriangleIds canonical(TriangleIds t) {
  while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  return t;
}

// Sorted keys of the edges between finite vertices of `tri`.
std::vector<std::uint64_t> mesh_edge_keys(const Triangulation2& tri) {
  std::vector<std::uint64_t> keys;
  const auto size = static_cast<std::uint32_t>(tri.vertices().size());
  keys.reserve(size / 2);
  for (std::uint32_t h = 0; h < size; ++h) {
    const std::uint32_t a = tri.origin(h), b = tri.destination(h);
    if (a != T2::kInfinite && b != T2::kInfinite && a < b) keys.push_back(edge_key(a, b));
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

std::vector<std::uint64_t> constrained_keys(const Constrained2dResult& result) {
  std::vector<std::uint64_t> keys;
  keys.reserve(result.constrained_edges.size());
  for (const ConstrainedEdge2& e : result.constrained_edges) keys.push_back(edge_key(e.a, e.b));
  std::sort(keys.begin(), keys.end());
  return keys;
}

bool contains(const std::vector<std::uint64_t>& sorted, std::uint64_t key) {
  return std::binary_search(sorted.begin(), sorted.end(), key);
}

// p on the line AB: strictly between A and B.
bool strictly_between(const Vec2& a, const Vec2& b, const Vec2& p) {
  if (a.x != b.x) return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
  return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
}

// The sign of (d - c) . (b - a), exactly. The rounded differences have the right signs, so do
// their products; only products of opposite signs need rationals.
Sign progress(const Vec2& c, const Vec2& d, const Vec2& a, const Vec2& b) {
  const double p1 = (d.x - c.x) * (b.x - a.x), p2 = (d.y - c.y) * (b.y - a.y);
  if (p1 >= 0 && p2 >= 0) return p1 > 0 || p2 > 0 ? Sign::Positive : Sign::Zero;
  if (p1 <= 0 && p2 <= 0) return Sign::Negative;
  const Rational dot = (Rational(d.x) - Rational(c.x)) * (Rational(b.x) - Rational(a.x)) +
                       (Rational(d.y) - Rational(c.y)) * (Rational(b.y) - Rational(a.y));
  return dot.sign();
}
bool forward(const Vec2& c, const Vec2& d, const Vec2& a, const Vec2& b) {
  return progress(c, d, a, b) == Sign::Positive;
}

// p within its rounding bound of an exact point of the closed segment AB (kernel/rounding.hpp).
bool within_rounding_bound_of_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  return rounding_box_meets_segment(p, a, b);
}

// Exactly inside the open segment AB, for x on its line.
bool strictly_inside(const ExactPoint2& x, const Vec2& a, const Vec2& b) {
  if (a.x != b.x) return Rational(std::min(a.x, b.x)) < x.x && x.x < Rational(std::max(a.x, b.x));
  return Rational(std::min(a.y, b.y)) < x.y && x.y < Rational(std::max(a.y, b.y));
}

// For each input point, the point that carries it: itself if some triangle uses it, else the
// first used point with the same coordinates (the kept copy of a duplicate), or itself.
std::vector<std::uint32_t> carriers(const ConstrainedInput2& input, const Triangulation2& tri) {
  const std::size_t n = input.points.size();
  std::vector<std::uint8_t> used(tri.point_count(), 0);
  for (const std::uint32_t v : tri.vertices())
    if (v < used.size()) used[v] = 1;
  std::vector<std::uint32_t> carrier(n);
  std::map<std::pair<double, double>, std::uint32_t> wanted;
  for (std::uint32_t i = 0; i < n; ++i) {
    carrier[i] = i;
    if (i < used.size() && !used[i]) wanted.emplace(std::pair{input.points[i].x, input.points[i].y}, i);
  }
  if (wanted.empty()) return carrier;
  std::map<std::pair<double, double>, std::uint32_t> found;
  for (std::uint32_t i = 0; i < n && i < used.size(); ++i) {
    const std::pair key{input.points[i].x, input.points[i].y};
    if (used[i] && wanted.count(key)) found.emplace(key, i);
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    if (i >= used.size() || used[i]) continue;
    const auto it = found.find({input.points[i].x, input.points[i].y});
    if (it != found.end()) carrier[i] = it->second;
  }
  return carrier;
}

template <class F>
void for_each_count(const Report& r, F&& f) {
  f("points", r.points);
  f("steiner_points", r.steiner_points);
  f("segments", r.segments);
  f("chain_edges", r.chain_edges);
  f("constrained_edges", r.constrained_edges);
  f("triangles", r.triangles);
  f("domain_triangles", r.domain_triangles);
  f("incircle_tests", r.incircle_tests);
  f("rounding_checks", r.rounding_checks);
}

void check_degenerate(const ConstrainedInput2& input, const Constrained2dResult& result, Report& r) {
  if (!result.triangles.empty()) r.add_problem("domain: triangles listed, yet the triangulation has none");
  // No triangles: the points must be collinear (or fewer than three distinct).
  const auto P = input.points;
  std::size_t second = 1;
  while (second < P.size() && P[second] == P[0]) ++second;
  for (std::size_t i = second + 1; i < P.size(); ++i)
    if (orient2d(P[0], P[second], P[i]) != Sign::Zero) {
      r.add_problem("degenerate: no triangles, yet the input points are not collinear");
      return;
    }
}

ReportCounts counts_of(const ConstrainedCheckReport2& r) {
  ReportCounts counts;
  for_each_count(r, [&](const char* key, std::size_t value) { counts.emplace_back(key, value); });
  return counts;
}

}  // namespace

void ConstrainedCheckReport2::merge(const CheckReport2& other) {
  add_problems(other, " (numbered from 0)");
}

ConstrainedCheckReport2 check_constrained_validity2(const ConstrainedInput2& input, const Constrained2dResult& result,
                                                   const ConstrainedCheckOptions2& options) {
  Report r;
  const Namer name{options.first_number};
  const Triangulation2& tri = result.triangulation;
  const auto P = tri.points();
  const std::size_t n = input.points.size();
  r.points = P.size();
  r.constrained_edges = result.constrained_edges.size();
  r.domain_triangles = result.triangles.size();
  if (P.size() < n) {
    r.add_problem("points: the result has " + std::to_string(P.size()) + " points, the input " + std::to_string(n));
    return r;
  }
  r.steiner_points = P.size() - n;
  for (std::size_t i = 0; i < n; ++i)
    if (!(P[i] == input.points[i])) r.add_problem("points: input " + name.point(i) + " moved to " + coordinates(P[i]));
  for (std::size_t i = n; i < P.size(); ++i)
    if (!coordinate_in_range(P[i].x) || !coordinate_in_range(P[i].y))
      r.add_problem("points: Steiner " + name.point(i) + " " + coordinates(P[i]) + " is outside the supported range");
  if (r.steiner_points != std::size_t{result.crossing_steiner_points} + result.split_steiner_points)
    r.add_problem("points: " + std::to_string(r.steiner_points) + " Steiner points, the result counts " +
                  std::to_string(result.crossing_steiner_points) + " crossing and " +
                  std::to_string(result.split_steiner_points) + " split points");
  if (result.rounding_checks_failed != 0)
    r.add_problem("rounding: the algorithm counted " + std::to_string(result.rounding_checks_failed) +
                  " Steiner points outside their rounding bound");
  if (result.triangle_region.size() != result.triangles.size())
    r.add_problem("domain: " + std::to_string(result.triangle_region.size()) + " region attributes for " +
                  std::to_string(result.triangles.size()) + " triangles");
  if (!r.ok) return r;

  try {
    tri.check_topology();
  } catch (const Error& e) {
    r.add_problem(std::string("structure: ") + e.what());
    return r;
  }
  const std::vector<TriangleIds> all = tri.finite_triangles();
  r.triangles = all.size();
  if (all.empty()) {
    check_degenerate(input, result, r);
    return r;
  }
  CheckReport2 base = check_orientation2(P, all);
  base.merge(check_topology2(P, all));
  base.merge(check_hull_coverage2(P, all));
  std::vector<std::uint8_t> used(P.size(), 0);
  for (const TriangleIds& t : all)
    for (const std::uint32_t v : t) used[v] = 1;
  std::vector<std::uint32_t> duplicates;
  for (std::uint32_t i = 0; i < n; ++i)
    if (!used[i]) duplicates.push_back(i);
  base.merge(check_unreferenced(P, all, duplicates));
  r.merge(base);
  if (!r.ok) return r;
  // The domain slot by slot (what Mesh2 takes): the listed triangles and regions, in slot order.
  std::size_t listed = 0;
  bool slots_ok = result.slot_regions.size() == tri.triangle_count();
  for (std::uint32_t t = 0; slots_ok && t < tri.triangle_count(); ++t) {
    if (result.slot_regions[t] == Mesh2::kExterior) continue;
    slots_ok = listed < result.triangles.size() && result.triangle_region[listed] == result.slot_regions[t] &&
               result.triangles[listed] == std::array{tri.vertex(t, 0), tri.vertex(t, 1), tri.vertex(t, 2)};
    ++listed;
  }
  if (!slots_ok || listed != result.triangles.size())
    r.add_problem("domain: slot_regions are not the listed triangles' regions, slot by slot");

  // Constrained edges: mesh edges, once each, from a valid segment with its marker.
  const std::vector<std::uint64_t> mesh_edges = mesh_edge_keys(tri);
  std::vector<std::uint64_t> seen;
  for (const ConstrainedEdge2& e : result.constrained_edges) {
    if (e.a >= e.b || e.b >= P.size()) {
      r.add_problem("constrained edges: " + name.edge(e.a, e.b) + " is not an ordered pair of point ids");
      continue;
    }
    if (!contains(mesh_edges, edge_key(e.a, e.b)))
      r.add_problem("constrained edges: " + name.edge(e.a, e.b) + " is not an edge of the triangulation");
    else if (const std::uint32_t h = e.half_edge;
             h >= tri.vertices().size() || edge_key(tri.origin(h), tri.destination(h)) != edge_key(e.a, e.b))
      r.add_problem("constrained edges: " + name.edge(e.a, e.b) + " has a half-edge elsewhere");
    seen.push_back(edge_key(e.a, e.b));
    if (e.segment >= input.segments.size()) {
      r.add_problem("constrained edges: " + name.edge(e.a, e.b) + " comes from " + name.segment(e.segment) +
                    ", which does not exist");
      continue;
    }
    const int marker = input.segment_markers.empty() ? 0 : input.segment_markers[e.segment];
    if (e.marker != marker)
      r.add_problem("constrained edges: " + name.edge(e.a, e.b) + " has marker " + std::to_string(e.marker) + ", its " +
                    name.segment(e.segment) + " has " + std::to_string(marker));
  }
  std::sort(seen.begin(), seen.end());
  for (std::size_t i = 1; i < seen.size(); ++i)
    if (seen[i] == seen[i - 1])
      r.add_problem("constrained edges: " + name.edge(std::uint32_t(seen[i] >> 32), std::uint32_t(seen[i])) +
                    " is listed twice");
  // Shared edges: constrained edges, each further segment valid, higher than the edge's own.
  std::map<std::uint64_t, std::uint32_t> own;
  for (const ConstrainedEdge2& e : result.constrained_edges) own.emplace(edge_key(e.a, e.b), e.segment);
  for (const ConstrainedEdge2& e : result.shared_edges) {
    const auto it = e.a < e.b ? own.find(edge_key(e.a, e.b)) : own.end();
    if (it == own.end()) {
      r.add_problem("shared edges: " + name.edge(e.a, e.b) + " is not a constrained edge");
      continue;
    }
    if (e.segment >= input.segments.size() || e.segment <= it->second) {
      r.add_problem("shared edges: " + name.edge(e.a, e.b) + " names " + name.segment(e.segment) +
                    ", not a segment numbered above its own " + name.segment(it->second));
      continue;
    }
    const int marker = input.segment_markers.empty() ? 0 : input.segment_markers[e.segment];
    if (e.marker != marker)
      r.add_problem("shared edges: " + name.edge(e.a, e.b) + " has marker " + std::to_string(e.marker) + ", its " +
                    name.segment(e.segment) + " has " + std::to_string(marker));
  }

  // The domain: some of the triangles, each once, bounded by constrained (or kept hull) edges.
  std::vector<TriangleIds> domain;
  domain.reserve(result.triangles.size());
  for (const TriangleIds& t : result.triangles) domain.push_back(canonical(t));
  std::sort(domain.begin(), domain.end());
  for (std::size_t i = 1; i < domain.size(); ++i)
    if (domain[i] == domain[i - 1]) r.add_problem("domain: " + name.triangle(domain[i]) + " is listed twice");
  const auto count = static_cast<std::uint32_t>(tri.triangle_count());
  std::vector<std::uint8_t> in_domain(count, 0);
  std::size_t matched = 0;
  for (std::uint32_t t = 0; t < count; ++t) {
    if (tri.is_ghost(t)) continue;
    const TriangleIds c = canonical({tri.vertex(t, 0), tri.vertex(t, 1), tri.vertex(t, 2)});
    in_domain[t] = std::binary_search(domain.begin(), domain.end(), c);
    matched += in_domain[t];
  }
  if (matched != domain.size())
    r.add_problem("domain: " + std::to_string(domain.size() - matched) +
                  " listed triangles are not triangles of the triangulation");
  const std::vector<std::uint64_t> cons = constrained_keys(result);
  const bool hull_must_be_constrained = !options.keep_exterior && !input.segments.empty();
  for (std::uint32_t t = 0; t < count; ++t) {
    if (!in_domain[t]) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = T2::half_edge(t, i);
      const std::uint32_t u = T2::triangle_of(tri.twin(h));
      const bool hull = tri.is_ghost(u);
      if ((hull && !hull_must_be_constrained) || (!hull && in_domain[u])) continue;
      const std::uint32_t a = tri.origin(h), b = tri.destination(h);
      if (!contains(cons, edge_key(a, b)))
        r.add_problem("domain: its boundary " + name.edge(a, b) + (hull ? " (on the convex hull)" : "") +
                      " is not a constrained edge");
    }
  }
  return r;
}

ConstrainedCheckReport2 check_constrained_chains2(const ConstrainedInput2& input, const Constrained2dResult& result,
                                                 const ConstrainedCheckOptions2& options) {
  Report r;
  const Namer name{options.first_number};
  const Triangulation2& tri = result.triangulation;
  const auto P = tri.points();
  const std::size_t n = input.points.size();
  if (tri.finite_triangle_count() == 0 || P.size() < n) return r;
  const std::vector<std::uint32_t> carrier = carriers(input, tri);

  // Adjacency of the constrained edges (compressed rows): neighbour and segment id.
  std::vector<std::uint32_t> first(P.size() + 1, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> next;
  // Shared edges once per further segment.
  for (const auto* edges : {&result.constrained_edges, &result.shared_edges})
    for (const ConstrainedEdge2& e : *edges)
      if (e.a < P.size() && e.b < P.size()) ++first[e.a + 1], ++first[e.b + 1];
  for (std::size_t v = 0; v < P.size(); ++v) first[v + 1] += first[v];
  next.resize(first.back());
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (const auto* edges : {&result.constrained_edges, &result.shared_edges})
      for (const ConstrainedEdge2& e : *edges)
        if (e.a < P.size() && e.b < P.size()) next[fill[e.a]++] = {e.b, e.segment}, next[fill[e.b]++] = {e.a, e.segment};
  }

  std::vector<std::pair<std::uint32_t, std::uint32_t>> steiner_on;  // (Steiner vertex, segment)
  std::vector<std::pair<std::uint32_t, std::uint32_t>> on_chain;    // (any chain vertex, segment)
  std::vector<std::uint32_t> stamp(P.size(), 0), parent(P.size(), T2::kNone), stack, chain;
  const std::size_t crossing_end = n + result.crossing_steiner_points;  // crossings come first
  for (std::size_t k = 0; k < input.segments.size(); ++k) {
    const auto [a0, b0] = input.segments[k];
    if (a0 >= n || b0 >= n) {
      r.add_problem(name.segment(k) + ": an endpoint is out of range");
      continue;
    }
    const std::uint32_t a = carrier[a0], b = carrier[b0];
    if (P[a] == P[b]) continue;  // zero length: refused by constrained2d
    ++r.segments;
    const Vec2 A = P[a], B = P[b];
    const auto mark = static_cast<std::uint32_t>(k + 1);
    // A step onto d along an edge of segment `label`. Input vertices: exactly on AB, or within
    // their rounding bound of it (a crossing of AB with another segment whose exact point
    // rounds onto an input vertex: the chain bends there, as at a rounded Steiner point).
    // Steiner vertices: on an edge of this segment or of one collinear with it (overlaps keep
    // the lowest-numbered segment), or within their rounding bound of AB (crossings); their
    // bound is checked below, once the chain is known.
    // Or, reached along another segment's edge (a piece of this one that ran exactly through d
    // and was split there, the edge shared and labelled with the lower segment): within its
    // rounding bound of the chord from c to a forward neighbour along this segment's own edges.
    const auto on_own_chord = [&](std::uint32_t c, std::uint32_t d) {
      for (std::uint32_t j = first[d]; j < first[d + 1]; ++j) {
        const auto [e, label] = next[j];
        if (label == k && e != c && forward(P[d], P[e], A, B) && within_rounding_bound_of_segment(P[d], P[c], P[e]))
          return true;
      }
      return false;
    };
    const auto admissible = [&](std::uint32_t c, std::uint32_t d, std::uint32_t label) {
      if (d < n)
        return label == k || (orient2d(A, B, P[d]) == Sign::Zero && strictly_between(A, B, P[d])) ||
               within_rounding_bound_of_segment(P[d], A, B) || on_own_chord(c, d);
      if (label == k) return true;
      if (label < input.segments.size()) {
        const auto& o = input.segments[label];
        if (o[0] < n && o[1] < n && orient2d(A, B, P[carrier[o[0]]]) == Sign::Zero &&
            orient2d(A, B, P[carrier[o[1]]]) == Sign::Zero)
          return true;
      }
      return within_rounding_bound_of_segment(P[d], A, B) || on_own_chord(c, d);
    };
    // Depth-first, no step backwards (a step across AB is allowed: two stops at the same place
    // along AB, a hot point and a vertex whose rounding boxes both meet it), first along this segment's own edges alone (where
    // segments share pieces or run a hair apart, a search free to change label may take a
    // neighbour's chain and leave this one's Steiner points off every chain found), then, if that
    // finds no chain (a piece shared with a lower-numbered segment carries that one's label),
    // along any admissible edge, this segment's own tried first.
    bool found = false;
    for (const bool own_only : {true, false}) {
      const std::uint32_t search_mark = 2 * mark + (own_only ? 0u : 1u);
      stack.assign(1, a);
      stamp[a] = search_mark;
      while (!stack.empty() && !found) {
        const std::uint32_t c = stack.back();
        stack.pop_back();
        // Other segments' edges pushed first, this one's last: popped first.
        for (const bool own_edges : {false, true}) {
          if (own_only && !own_edges) continue;
          for (std::uint32_t j = first[c]; j < first[c + 1] && !found; ++j) {
            const auto [d, label] = next[j];
            if ((label == k) != own_edges || stamp[d] == search_mark ||
                progress(P[c], P[d], A, B) == Sign::Negative)
              continue;
            if (d == b) {
              parent[b] = c;
              found = true;
              break;
            }
            if (!admissible(c, d, label)) continue;
            stamp[d] = search_mark;
            parent[d] = c;
            stack.push_back(d);
          }
        }
      }
      if (found) break;
    }
    if (!found) {
      r.add_problem(name.segment(k) + ": no chain of constrained edges from " + name.point(a) + " to " +
                    name.point(b) + " through points on it");
      continue;
    }
    chain.clear();
    for (std::uint32_t v = b; v != a; v = parent[v]) chain.push_back(v);
    chain.push_back(a);
    r.chain_edges += chain.size() - 1;
    for (const std::uint32_t v : chain) on_chain.push_back({v, static_cast<std::uint32_t>(k)});
    // Each Steiner vertex within its rounding bound of an exact point of AB, or of the piece it
    // split when it was inserted: a piece between two older vertices of the chain, one on each
    // side (vertex ids grow with insertion). Later vertices only split pieces further, but an
    // older vertex found exactly on a later piece joins the chain there, so the piece's ends are
    // among the nearest few older vertices on each side, not always the nearest, or are newer
    // (an input vertex, or a crossing point, that a piece between later split points ran exactly
    // through: the walk split the piece there). Either way the chain stays within rounding
    // bounds of chords between its vertices, and so near AB.
    constexpr std::size_t kTried = 4;
    for (std::size_t i = 1; i + 1 < chain.size(); ++i) {
      const std::uint32_t v = chain[i];
      if (v >= n) steiner_on.push_back({v, static_cast<std::uint32_t>(k)});
      if (within_rounding_bound_of_segment(P[v], A, B)) continue;
      const auto within_a_chord = [&](bool older_only, std::uint32_t& nearest_before, std::uint32_t& nearest_after) {
        std::vector<std::uint32_t> before, after;
        for (std::size_t j = i + 1; j < chain.size() && before.size() < kTried; ++j)
          if (chain[j] < v || !older_only) before.push_back(chain[j]);
        for (std::size_t j = i; j-- > 0 && after.size() < kTried;)
          if (chain[j] < v || !older_only) after.push_back(chain[j]);
        nearest_before = before.front(), nearest_after = after.front();
        for (const std::uint32_t x : before)
          for (const std::uint32_t y : after)
            if (within_rounding_bound_of_segment(P[v], P[x], P[y])) return true;
        return false;
      };
      std::uint32_t x = 0, y = 0;
      const bool within = (v >= n && within_a_chord(true, x, y)) || within_a_chord(false, x, y);
      if (!within)
        r.add_problem((v < n ? "input " : "Steiner ") + name.point(v) + " " + coordinates(P[v]) + " on the chain of " +
                      name.segment(k) + " is not within its rounding bound of the segment nor of a piece between " +
                      "points of the chain around it (nearest: " + name.edge(x, y) + ")");
    }
  }

  // Steiner points: on some chain. The crossing points (numbered first among the Steiner
  // points: segments are resolved before any method splits them) on the chains of two crossing
  // segments: within the rounding bound of the exact intersection of some such pair. (A split
  // point may lie on two chains too, where a later piece of another segment runs exactly
  // through it; its bound is the piece's, checked above.)
  std::sort(steiner_on.begin(), steiner_on.end());
  std::sort(on_chain.begin(), on_chain.end());
  std::size_t i = 0;
  for (std::uint32_t v = static_cast<std::uint32_t>(n); v < P.size(); ++v) {
    const std::size_t begin = i;
    while (i < steiner_on.size() && steiner_on[i].first == v) ++i;
    if (begin == i) {
      r.add_problem("Steiner " + name.point(v) + " " + coordinates(P[v]) + " lies on no segment's chain");
      continue;
    }
    if (v >= crossing_end) continue;
    const std::size_t end = std::min(i, begin + 16);  // pairs among the first 16 segments through it
    bool crossing = false, within = false;
    std::string pair;
    for (std::size_t x = begin; x < end && !within; ++x)
      for (std::size_t y = x + 1; y < end && !within; ++y) {
        const auto& s = input.segments[steiner_on[x].second];
        const auto& t = input.segments[steiner_on[y].second];
        const Vec2 sa = P[carrier[s[0]]], sb = P[carrier[s[1]]], ta = P[carrier[t[0]]], tb = P[carrier[t[1]]];
        const std::optional<ExactPoint2> exact = line_intersection_exact(sa, sb, ta, tb);
        if (!exact || !strictly_inside(*exact, sa, sb) || !strictly_inside(*exact, ta, tb)) continue;
        crossing = true;
        ++r.rounding_checks;
        within = within_rounding_bound(*exact, P[v]);
        if (!within) pair = name.segment(steiner_on[x].second) + " and " + name.segment(steiner_on[y].second);
      }
    if (crossing && !within) {
      // The chains found are one choice where chains share edges (snap rounding routes every
      // segment through the crossings whose rounding box it meets): any two segments meeting
      // v's box whose exact crossing v rounds will do.
      std::vector<std::uint32_t> near;
      for (std::size_t k = 0; k < input.segments.size() && near.size() < 64; ++k) {
        const auto& s = input.segments[k];
        if (s[0] < n && s[1] < n && within_rounding_bound_of_segment(P[v], P[carrier[s[0]]], P[carrier[s[1]]]))
          near.push_back(static_cast<std::uint32_t>(k));
      }
      for (std::size_t x = 0; x < near.size() && !within; ++x)
        for (std::size_t y = x + 1; y < near.size() && !within; ++y) {
          const auto& s = input.segments[near[x]];
          const auto& t = input.segments[near[y]];
          const Vec2 sa = P[carrier[s[0]]], sb = P[carrier[s[1]]], ta = P[carrier[t[0]]], tb = P[carrier[t[1]]];
          const std::optional<ExactPoint2> exact = line_intersection_exact(sa, sb, ta, tb);
          if (!exact || !strictly_inside(*exact, sa, sb) || !strictly_inside(*exact, ta, tb)) continue;
          ++r.rounding_checks;
          within = within_rounding_bound(*exact, P[v]);
        }
    }
    if (crossing && !within) {
      // Or a crossing of two chains bent by rounding (BentCrossing2): within its rounding bound of
      // the exact intersection of the recorded pieces' lines, the ends of each piece vertices of
      // its segment's chain (which the chain check above holds near the segment; where chains
      // share edges the one found may go round them) or within their rounding bound of it.
      const auto record = std::find_if(result.bent_crossings.begin(), result.bent_crossings.end(),
                                       [&](const BentCrossing2& b) { return b.vertex == v; });
      if (record != result.bent_crossings.end()) {
        const auto& q = record->pieces;
        bool on_chains = true;
        for (int k = 0; k < 4 && on_chains; ++k) {  // the pieces' four ends
          const std::uint32_t seg = record->segments[k / 2];
          on_chains = q[k] < P.size() && seg < input.segments.size();
          if (!on_chains) break;
          const auto& [sa, sb] = input.segments[seg];
          on_chains = std::binary_search(on_chain.begin(), on_chain.end(), std::pair{q[k], seg}) ||
                      (sa < n && sb < n && within_rounding_bound_of_segment(P[q[k]], P[carrier[sa]], P[carrier[sb]]));
        }
        if (on_chains) {
          const std::optional<ExactPoint2> exact = line_intersection_exact(P[q[0]], P[q[1]], P[q[2]], P[q[3]]);
          ++r.rounding_checks;
          within = exact && within_rounding_bound(*exact, P[v]);
        }
      }
    }
    if (crossing && !within)
      r.add_problem("Steiner " + name.point(v) + " " + coordinates(P[v]) + " on the chains of " + pair +
                    " is not within its rounding bound of their exact intersection");
  }
  return r;
}

ConstrainedCheckReport2 check_locally_delaunay2(const Constrained2dResult& result, bool skip_constrained,
                                               const ConstrainedCheckOptions2& options) {
  Report r;
  const Namer name{options.first_number};
  const Triangulation2& tri = result.triangulation;
  const auto P = tri.points();
  const std::vector<std::uint64_t> cons = constrained_keys(result);
  const auto size = static_cast<std::uint32_t>(tri.vertices().size());
  for (std::uint32_t h = 0; h < size; ++h) {
    const std::uint32_t g = tri.twin(h), t = T2::triangle_of(h);
    if (h > g || tri.is_ghost(t) || tri.is_ghost(T2::triangle_of(g))) continue;
    const std::uint32_t a = tri.origin(h), b = tri.destination(h);
    if (skip_constrained && contains(cons, edge_key(a, b))) continue;
    ++r.incircle_tests;
    const TriangleIds abc = {tri.vertex(t, 0), tri.vertex(t, 1), tri.vertex(t, 2)};
    const std::uint32_t d = tri.vertices()[g];
    if (incircle_perturbed(P[abc[0]], P[abc[1]], P[abc[2]], P[d]) == Sign::Positive)
      r.add_problem((skip_constrained ? "constrained Delaunay: " : "Delaunay: ") + name.edge(a, b) +
                    (contains(cons, edge_key(a, b)) ? " (constrained)" : "") + " is not locally Delaunay: " +
                    name.point(d) + " is inside the circle of " + name.triangle(abc));
  }
  return r;
}

ConstrainedCheckReport2 verify_constrained2d(const ConstrainedInput2& input, const Constrained2dResult& result,
                                            const ConstrainedCheckOptions2& options) {
  Report r = check_constrained_validity2(input, result, options);
  if (!r.ok || r.triangles == 0) return r;
  const auto take = [&r](const Report& other) {
    r.ok = r.ok && other.ok;
    r.problem_count += other.problem_count;
    for (const std::string& p : other.problems)
      if (r.problems.size() < Report::kMaxStoredProblems) r.problems.push_back(p);
    r.segments += other.segments;
    r.chain_edges += other.chain_edges;
    r.incircle_tests += other.incircle_tests;
    r.rounding_checks += other.rounding_checks;
  };
  take(check_constrained_chains2(input, result, options));
  if (options.method == "cdt") take(check_locally_delaunay2(result, true, options));
  if (options.method == "conforming") take(check_locally_delaunay2(result, false, options));
  return r;
}

std::string to_json(const ConstrainedCheckReport2& r) { return report_json(r, counts_of(r)); }

std::string to_text(const ConstrainedCheckReport2& r) { return report_text(r, counts_of(r)); }

}  // namespace dtlab
