// Exact checks of a constrained tetrahedralization (checks_constrained3d.hpp): validity, region
// boundaries, the input triangles' covers in (s, t), the input edges' chains, the Steiner
// records; the report's printers.
#include "verify/checks_constrained3d.hpp"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <optional>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "kernel/predicates.hpp"
#include "kernel/rounding.hpp"
#include "verify/checks3d.hpp"

namespace dtlab {

namespace {

using T3 = Tetrahedralization3;
using Ids3 = std::array<std::uint32_t, 3>;
using St = std::array<Rational, 2>;

std::uint64_t edge_key(std::uint32_t u, std::uint32_t v) noexcept {
  return u < v ? std::uint64_t{u} << 32 | v : std::uint64_t{v} << 32 | u;
}

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

Rational orient_st(const St& p, const St& q, const St& r) {
  return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
}

class Checker {
 public:
  Checker(const ConstrainedInput3& in, const Constrained3dResult& r, const ConstrainedCheckOptions3& o,
          ConstrainedCheckReport3& report)
      : in_(in), r_(r), o_(o), rep_(report) {}

  void run();

 private:
  std::string n(std::uint32_t id) const { return std::to_string(std::uint64_t{id} + o_.first_number); }
  bool check_records();
  bool check_tetrahedralization();
  void check_regions();
  void check_faces();
  void check_constrained_delaunay();
  void check_edges();
  std::optional<St> parameters_in(std::uint32_t f, std::uint32_t v, std::string& why) const;

  const ConstrainedInput3& in_;
  const Constrained3dResult& r_;
  const ConstrainedCheckOptions3& o_;
  ConstrainedCheckReport3& rep_;
  std::unordered_set<Ids3, IdsHash> mesh_faces_;
  std::unordered_set<std::uint64_t> mesh_edges_;
};

// The points, the counts and the Steiner records.
bool Checker::check_records() {
  const auto& v = r_.vertices;
  rep_.points = v.size();
  rep_.steiner_points = r_.steiner.size();
  rep_.tetrahedra = r_.tetrahedra.size();
  const std::size_t ipc = in_.points.size();
  if (r_.input_point_count != ipc || v.size() < ipc || !std::equal(in_.points.begin(), in_.points.end(), v.begin()))
    rep_.add_problem("the input points are not the first points of the result, unchanged");
  if (v.size() != ipc + r_.steiner.size()) {
    rep_.add_problem(std::to_string(v.size()) + " vertices for " + std::to_string(ipc) + " input points and " +
                     std::to_string(r_.steiner.size()) + " Steiner records");
    return false;
  }
  const auto& tp = r_.tetrahedralization.points();
  if (tp.size() != v.size() || !std::equal(tp.begin(), tp.end(), v.begin()))
    rep_.add_problem("the tetrahedralization's points are not the result's vertices");
  if (r_.rounding_checks_failed != 0)
    rep_.add_problem(std::to_string(r_.rounding_checks_failed) + " Steiner points failed the method's rounding check");
  if (r_.triangle_face.size() != r_.triangles.size() || r_.triangle_refs.size() != r_.triangles.size() ||
      r_.triangle_facets.size() != r_.triangles.size() || r_.tetrahedron_regions.size() != r_.tetrahedra.size()) {
    rep_.add_problem("the result's arrays differ in length");
    return false;
  }
  SteinerCounts counts;
  for (std::size_t i = 0; i < r_.steiner.size(); ++i) {
    const SteinerPoint3& s = r_.steiner[i];
    const std::string name = "Steiner point " + n(static_cast<std::uint32_t>(ipc + i));
    if (s.kind == SteinerPoint3::Kind::OnEdge) ++counts.on_edges;
    if (s.kind == SteinerPoint3::Kind::OnFace) ++counts.on_faces;
    if (s.kind == SteinerPoint3::Kind::Interior) {
      ++counts.interior;
      continue;  // no constraint holds it
    }
    const std::size_t used = s.kind == SteinerPoint3::Kind::OnEdge ? 2 : 3;
    bool ids_ok = s.owner < in_.triangles.size();
    for (std::size_t k = 0; k < used; ++k) ids_ok = ids_ok && s.support[k] < ipc;
    if (!ids_ok) {
      rep_.add_problem(name + ": its record names a point or triangle that does not exist");
      continue;
    }
    if (!steiner_point_within_rounding_bound(in_.points, s, v[ipc + i]))
      rep_.add_problem(name + " is not within its rounding bound of the exact point its record names");
  }
  if (counts.on_edges != r_.steiner_points.on_edges || counts.on_faces != r_.steiner_points.on_faces ||
      counts.interior != r_.steiner_points.interior)
    rep_.add_problem("the Steiner counts by kind do not match the records");
  return true;
}

// The whole tetrahedralization: closed, positive, Delaunay where promised.
bool Checker::check_tetrahedralization() {
  const T3& t = r_.tetrahedralization;
  CheckReport3 d;
  if (o_.method == "conforming") {
    d = verify_delaunay3d(r_.vertices, t);
  } else {
    d = check_topology3(t);
    if (d.ok) d.merge(check_orientation3(t));
  }
  for (const std::string& p : d.problems) rep_.add_problem("tetrahedralization (numbered from 0): " + p);
  if (!d.ok) return false;
  for (const auto& rec : t.records()) {
    const auto& x = rec.vertex;
    for (std::uint32_t i = 0; i < 4; ++i) mesh_faces_.insert(sorted(Ids3{x[T3::kFacetVertex[i][0]], x[T3::kFacetVertex[i][1]], x[T3::kFacetVertex[i][2]]}));
    if (x[0] == T3::kInfinite) continue;
    for (std::uint32_t i = 0; i < 4; ++i)
      for (std::uint32_t j = i + 1; j < 4; ++j) mesh_edges_.insert(edge_key(x[i], x[j]));
  }
  return true;
}

// Kept tetrahedra: positive, tetrahedra of the mesh, and regions change only across pieces.
void Checker::check_regions() {
  const T3& t = r_.tetrahedralization;
  const auto& v = r_.vertices;
  std::unordered_map<std::array<std::uint32_t, 4>, std::size_t, IdsHash> kept;
  for (std::size_t k = 0; k < r_.tetrahedra.size(); ++k) {
    const auto& x = r_.tetrahedra[k];
    const bool ids_ok = std::all_of(x.begin(), x.end(), [&](std::uint32_t id) { return id < v.size(); });
    if (!ids_ok || orient3d(v[x[0]], v[x[1]], v[x[2]], v[x[3]]) != Sign::Positive) {
      rep_.add_problem("tetrahedron " + n(static_cast<std::uint32_t>(k)) + " is not positive in doubles");
      continue;
    }
    if (!kept.emplace(sorted(x), k).second) rep_.add_problem("tetrahedron " + n(static_cast<std::uint32_t>(k)) + " is listed twice");
  }
  constexpr int kRemoved = INT_MIN;
  std::vector<int> label(t.tetrahedron_count(), kRemoved);
  std::size_t found = 0;
  for (std::uint32_t k = 0; k < t.tetrahedron_count(); ++k) {
    if (t.is_ghost(k)) continue;
    const auto it = kept.find(sorted(t.records()[k].vertex));
    if (it == kept.end()) continue;
    label[k] = r_.tetrahedron_regions[it->second];
    ++found;
  }
  if (found != kept.size())
    rep_.add_problem(std::to_string(kept.size() - found) + " kept tetrahedra are no tetrahedra of the tetrahedralization");
  if (r_.slot_regions != label) rep_.add_problem("slot_regions are not the kept tetrahedra's regions, slot by slot");
  std::unordered_set<Ids3, IdsHash> pieces;
  for (const auto& p : r_.triangles) pieces.insert(sorted(p));
  std::size_t reported = 0;
  for (std::uint32_t k = 0; k < t.tetrahedron_count(); ++k)
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t u = t.adjacent(k, i);
      if (u < k || label[u] == label[k]) continue;
      if (o_.keep_exterior && (t.is_ghost(u) || t.is_ghost(k))) continue;
      if (pieces.count(sorted(t.facet_vertices(T3::facet(k, i)))) || ++reported > 20) continue;
      const auto f = t.facet_vertices(T3::facet(k, i));
      std::string names;
      for (const std::uint32_t x : f) names += (names.empty() ? "" : ", ") + (x == T3::kInfinite ? "infinite" : n(x));
      rep_.add_problem("the mesh face (" + names + ") separates two regions (or a kept tetrahedron from a removed one) but is no piece of an input triangle");
    }
}

// (s, t) of vertex v in input triangle f, from the Steiner records; nullopt (with why) if v is
// not on f by its record.
std::optional<St> Checker::parameters_in(std::uint32_t f, std::uint32_t v, std::string& why) const {
  static const std::array<std::array<int, 2>, 3> kCorner = {{{0, 0}, {1, 0}, {0, 1}}};
  const Ids3& c = in_.triangles[f];
  for (int k = 0; k < 3; ++k)
    if (v == c[k]) return St{Rational(kCorner[k][0]), Rational(kCorner[k][1])};
  if (v < r_.input_point_count || v >= r_.vertices.size()) {
    why = "vertex " + n(v) + " is no corner of it";
    return std::nullopt;
  }
  const SteinerPoint3& s = r_.steiner[v - r_.input_point_count];
  if (s.kind == SteinerPoint3::Kind::OnFace) {
    if (s.owner == f && s.support == c) return St{Rational(s.parameters[0]), Rational(s.parameters[1])};
    why = "Steiner point " + n(v) + " belongs to another triangle";
    return std::nullopt;
  }
  if (s.kind == SteinerPoint3::Kind::OnEdge) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = c[k], b = c[(k + 1) % 3];
      if (edge_key(a, b) != edge_key(s.support[0], s.support[1])) continue;
      const Rational t = a == s.support[0] ? Rational(s.parameters[0]) : Rational(1) - Rational(s.parameters[0]);
      const auto& p0 = kCorner[k];
      const auto& p1 = kCorner[(k + 1) % 3];
      return St{Rational(p0[0]) + t * Rational(p1[0] - p0[0]), Rational(p0[1]) + t * Rational(p1[1] - p0[1])};
    }
  }
  why = "Steiner point " + n(v) + " is on no edge of it";
  return std::nullopt;
}

// Whether directed (s, t) edge p -> q runs counter-clockwise along a side of the triangle.
bool along_side(const St& p, const St& q) {
  const Rational one(1);
  if (p[1].sign() == Sign::Zero && q[1].sign() == Sign::Zero) return q[0] > p[0];
  if (p[0] + p[1] == one && q[0] + q[1] == one) return q[1] > p[1];
  if (p[0].sign() == Sign::Zero && q[0].sign() == Sign::Zero) return q[1] < p[1];
  return false;
}

void Checker::check_faces() {
  std::vector<std::vector<std::size_t>> by_face(in_.triangles.size());
  for (std::size_t k = 0; k < r_.triangles.size(); ++k) {
    const std::uint32_t f = r_.triangle_face[k];
    const std::string name = "piece " + n(static_cast<std::uint32_t>(k));
    if (f >= in_.triangles.size()) {
      rep_.add_problem(name + " names input triangle " + n(f) + ", which does not exist");
      continue;
    }
    const int ref = in_.triangle_refs.empty() ? 0 : in_.triangle_refs[f];
    if (r_.triangle_refs[k] != ref) rep_.add_problem(name + " does not carry the reference of triangle " + n(f));
    if (!mesh_faces_.count(sorted(r_.triangles[k]))) rep_.add_problem(name + " of triangle " + n(f) + " is no mesh face");
    const std::uint32_t h = r_.triangle_facets[k];
    if (h / 4 >= r_.tetrahedralization.tetrahedron_count() ||
        sorted(r_.tetrahedralization.facet_vertices(h)) != sorted(r_.triangles[k]))
      rep_.add_problem(name + "'s facet handle is not that face");
    by_face[f].push_back(k);
  }
  rep_.pieces = r_.triangles.size();
  for (std::uint32_t f = 0; f < in_.triangles.size(); ++f) {
    ++rep_.input_triangles;
    const std::string name = "triangle " + n(f);
    std::unordered_map<std::uint32_t, St> st;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> net;  // directed edge -> net count
    Rational area;
    bool ok = true;
    for (const std::size_t k : by_face[f]) {
      const auto& p = r_.triangles[k];
      for (const std::uint32_t x : p) {
        if (st.count(x)) continue;
        std::string why;
        const auto q = parameters_in(f, x, why);
        if (!q) {
          rep_.add_problem(name + ": piece " + n(static_cast<std::uint32_t>(k)) + " is not on it: " + why);
          ok = false;
          break;
        }
        st.emplace(x, *q);
      }
      if (!ok) break;
      const Rational doubled = orient_st(st.at(p[0]), st.at(p[1]), st.at(p[2]));
      if (doubled.sign() != Sign::Positive) {
        rep_.add_problem(name + ": piece " + n(static_cast<std::uint32_t>(k)) + " is not positive in its (s, t)");
        ok = false;
        break;
      }
      area += doubled;
      for (int j = 0; j < 3; ++j) {
        const std::uint32_t a = p[j], b = p[(j + 1) % 3];
        if (a < b) ++net[{a, b}];
        else --net[{b, a}];
      }
    }
    if (!ok) continue;
    for (const auto& [e, count] : net) {
      if (count == 0) continue;
      const bool forward = count > 0;
      const St& a = st.at(forward ? e.first : e.second);
      const St& b = st.at(forward ? e.second : e.first);
      if (std::abs(count) != 1 || !along_side(a, b)) {
        rep_.add_problem(name + ": its pieces leave the edge between vertices " + n(e.first) + " and " + n(e.second) +
                         " open");
        ok = false;
        break;
      }
    }
    if (ok && area != Rational(1))
      rep_.add_problem(name + ": its pieces cover " + area.to_string() + " times its area");
  }
}

void Checker::check_edges() {
  struct ChainPoint {
    Rational t;
    std::uint32_t vertex;
  };
  std::unordered_map<std::uint64_t, std::vector<ChainPoint>> chains;
  std::unordered_map<std::uint64_t, std::uint32_t> face_of;
  for (std::uint32_t f = 0; f < in_.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t key = edge_key(in_.triangles[f][k], in_.triangles[f][(k + 1) % 3]);
      if (face_of.emplace(key, f).second) chains[key];
    }
  for (std::size_t i = 0; i < r_.steiner.size(); ++i) {
    const SteinerPoint3& s = r_.steiner[i];
    if (s.kind != SteinerPoint3::Kind::OnEdge) continue;
    const std::uint32_t id = static_cast<std::uint32_t>(r_.input_point_count + i);
    const auto it = chains.find(edge_key(s.support[0], s.support[1]));
    if (it == chains.end()) {
      rep_.add_problem("Steiner point " + n(id) + " is on no input edge");
      continue;
    }
    const bool from_low = s.support[0] < s.support[1];
    it->second.push_back({from_low ? Rational(s.parameters[0]) : Rational(1) - Rational(s.parameters[0]), id});
  }
  for (auto& [key, points] : chains) {
    ++rep_.input_edges;
    const std::uint32_t a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key);
    const std::string name = "the edge between vertices " + n(a) + " and " + n(b) + " (of triangle " + n(face_of.at(key)) + ")";
    std::sort(points.begin(), points.end(), [](const ChainPoint& x, const ChainPoint& y) { return x.t < y.t; });
    std::vector<std::uint32_t> chain{a};
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (points[j].t.sign() != Sign::Positive || points[j].t >= Rational(1) || (j > 0 && points[j].t == points[j - 1].t))
        rep_.add_problem(name + ": Steiner point " + n(points[j].vertex) + " has a parameter outside (0, 1) or repeated");
      chain.push_back(points[j].vertex);
    }
    chain.push_back(b);
    for (std::size_t j = 0; j + 1 < chain.size(); ++j) {
      ++rep_.chain_edges;
      if (!mesh_edges_.count(edge_key(chain[j], chain[j + 1]))) {
        rep_.add_problem(name + ": its piece from vertex " + n(chain[j]) + " to vertex " + n(chain[j + 1]) +
                         " is no mesh edge");
      }
    }
  }
}

// Method "cdt", where it reports a CDT: every facet between two kept tetrahedra that is no
// piece of an input triangle is locally Delaunay (the constrained Delaunay lemma, checks3d.hpp):
// a CDT of the domain the result meshes.
void Checker::check_constrained_delaunay() {
  if (o_.method != "cdt" || !r_.constrained_delaunay) return;
  std::set<Ids3> pieces;
  for (const auto& t : r_.triangles) pieces.insert(sorted(t));
  const CheckReport3 d = check_constrained_delaunay3(r_.vertices, r_.tetrahedra,
                                                     [&](const Ids3& f) { return pieces.count(f) != 0; });
  for (const std::string& p : d.problems) rep_.add_problem(p + " (numbered from 0)");
}

void Checker::run() {
  if (!check_records()) return;
  if (!check_tetrahedralization()) return;
  check_regions();
  check_faces();
  check_edges();
  check_constrained_delaunay();
  check_region_volumes3(in_, r_, o_, rep_);
}

template <class F>
void for_each_count(const ConstrainedCheckReport3& r, F&& f) {
  f("points", r.points);
  f("steiner_points", r.steiner_points);
  f("tetrahedra", r.tetrahedra);
  f("input_triangles", r.input_triangles);
  f("pieces", r.pieces);
  f("input_edges", r.input_edges);
  f("chain_edges", r.chain_edges);
  f("regions", r.regions);
  f("exact_volumes", r.exact_volumes);
}

ReportCounts counts_of(const ConstrainedCheckReport3& r) {
  ReportCounts counts;
  for_each_count(r, [&](const char* key, std::size_t value) { counts.emplace_back(key, value); });
  return counts;
}

}  // namespace

ConstrainedCheckReport3 check_constrained3d(const ConstrainedInput3& input, const Constrained3dResult& result,
                                            const ConstrainedCheckOptions3& options) {
  ConstrainedCheckReport3 report;
  Checker(input, result, options, report).run();
  return report;
}

std::string to_json(const ConstrainedCheckReport3& r) {
  std::string volumes = ",\"region_volume6\":{";
  bool first = true;
  for (const auto& [region, v6] : r.region_volume6) {
    volumes += (first ? "\"" : ",\"") + std::to_string(region) + "\":" + json_string(v6.to_string());
    first = false;
  }
  return report_json(r, counts_of(r), volumes + "}");
}

std::string to_text(const ConstrainedCheckReport3& r) { return report_text(r, counts_of(r)); }

}  // namespace dtlab
