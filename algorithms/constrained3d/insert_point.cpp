// Bowyer-Watson insertion into a Delaunay tetrahedralization (insert_point.hpp).
#include "algorithms/constrained3d/insert_point.hpp"

#include <algorithm>
#include <functional>
#include <string>
#include <unordered_map>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

namespace {
using T3 = Tetrahedralization3;
constexpr std::uint32_t kInf = T3::kInfinite;
constexpr auto kFacet = T3::kFacetVertex;
}  // namespace

DelaunayInserter::DelaunayInserter(Tetrahedralization3& tet) : tet_(tet) {
  DTLAB_ASSERT(tet.finite_tetrahedron_count() > 0);
  while (tet.is_ghost(last_)) ++last_;
}

bool DelaunayInserter::conflicts(std::uint32_t t, const Vec3& p) const {
  const auto& v = tet_.records()[t].vertex;
  const auto pts = tet_.points();
  if (v[0] != kInf) return insphere_perturbed(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]], p) == Sign::Positive;
  const Sign side = orient3d(p, pts[v[1]], pts[v[2]], pts[v[3]]);
  if (side != Sign::Zero) return side == Sign::Positive;
  const auto& w = tet_.records()[tet_.adjacent(t, 0)].vertex;
  return insphere_perturbed(pts[w[0]], pts[w[1]], pts[w[2]], pts[w[3]], p) == Sign::Positive;
}

// Visibility walk: a finite tetrahedron whose closed region holds p, or a ghost whose hull
// facet p is strictly beyond. It cannot cycle on a Delaunay tetrahedralization (Edelsbrunner
// 1990); the bound backs that up.
std::uint32_t DelaunayInserter::locate(const Vec3& p) const {
  const auto pts = tet_.points();
  std::uint32_t t = last_ < tet_.tetrahedron_count() ? last_ : 0;
  if (tet_.is_ghost(t)) t = tet_.adjacent(t, 0);
  std::uint32_t entered = 4;
  for (std::size_t steps = 0; steps <= tet_.tetrahedron_count(); ++steps) {
    const auto& v = tet_.records()[t].vertex;
    if (v[0] == kInf) return t;
    std::uint32_t next = T3::kNone;
    for (std::uint32_t k = 1; k <= 4 && next == T3::kNone; ++k) {
      const std::uint32_t i = (entered + k) & 3u;
      if (i == entered) continue;
      const auto& f = kFacet[i];
      if (orient3d(pts[v[f[0]]], pts[v[f[1]]], pts[v[f[2]]], p) == Sign::Negative) next = tet_.twin(T3::facet(t, i));
    }
    if (next == T3::kNone) return t;
    t = T3::tetrahedron_of(next), entered = T3::index_in_tetrahedron(next);
  }
  throw InternalError("Delaunay insertion: the walk exceeded its bound");
}

// Moves the last record into slot t (dead), relinking its neighbours, and drops the last slot.
void DelaunayInserter::remove_slot(std::uint32_t t) {
  auto& records = tet_.mutable_records();
  const std::uint32_t last = static_cast<std::uint32_t>(records.size() - 1);
  if (t != last) {
    records[t] = records[last];
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = records[t].neighbour[i];
      // A neighbour that is the moved record itself cannot occur (no tetrahedron is its own
      // neighbour); dead neighbours are relinked by the caller before removal.
      records[h >> 2].neighbour[h & 3u] = T3::facet(t, i);
    }
  }
  records.pop_back();
}

std::uint32_t DelaunayInserter::insert(const Vec3& p) {
  const std::uint32_t base = locate(p);
  for (const std::uint32_t v : tet_.records()[base].vertex)
    if (v != kInf && tet_.points()[v] == p)
      throw InputError("Delaunay insertion: the new point equals vertex " + std::to_string(v), {v});
  DTLAB_ASSERT(conflicts(base, p));
  tet_.mutable_points().push_back(p);
  const std::uint32_t pid = static_cast<std::uint32_t>(tet_.point_count() - 1);

  // The cavity by breadth-first search over adjacency; marks by stamp.
  if (++stamp_ == 0) std::fill(mark_.begin(), mark_.end(), 0), stamp_ = 1;
  mark_.resize(tet_.tetrahedron_count(), 0);
  const std::uint32_t in_cavity = stamp_;
  cavity_.assign(1, base);
  mark_[base] = in_cavity;
  struct Boundary {
    std::array<std::uint32_t, 3> v;
    std::uint32_t outer;
  };
  std::vector<Boundary> boundary;
  for (std::size_t k = 0; k < cavity_.size(); ++k) {
    const std::uint32_t t = cavity_[k];
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = tet_.twin(T3::facet(t, i));
      const std::uint32_t u = T3::tetrahedron_of(h);
      if (mark_[u] == in_cavity) continue;
      if (conflicts(u, p)) {  // a tetrahedron outside may be tested again: same answer
        mark_[u] = in_cavity;
        cavity_.push_back(u);
        continue;
      }
      boundary.push_back({tet_.facet_vertices(T3::facet(t, i)), h});
    }
  }

  // The ball: one new tetrahedron (facet, p) per boundary facet, into the cavity's slots first.
  auto& records = tet_.mutable_records();
  new_.clear();
  for (std::size_t j = 0; j < boundary.size(); ++j) {
    std::uint32_t t;
    if (j < cavity_.size()) {
      t = cavity_[j];
    } else {
      t = static_cast<std::uint32_t>(records.size());
      records.push_back({});
      mark_.push_back(0);
    }
    auto f = boundary[j].v;
    // Even permutation (a 3-cycle of the facet) putting the infinite vertex first.
    while (f[1] == kInf || f[2] == kInf) std::rotate(f.begin(), f.begin() + 1, f.end());
    records[t].vertex = {f[0], f[1], f[2], pid};
    records[t].neighbour = {T3::kNone, T3::kNone, T3::kNone, boundary[j].outer};
    const std::uint32_t outer = boundary[j].outer;
    records[outer >> 2].neighbour[outer & 3u] = T3::facet(t, 3);
    mark_[t] = 0;
    new_.push_back(t);
  }
  // Facets through p: keyed by their two other vertices in the cyclic order that follows p.
  std::unordered_map<std::uint64_t, std::uint32_t> open;
  open.reserve(3 * new_.size());
  for (const std::uint32_t t : new_) {
    for (std::uint32_t i = 0; i < 3; ++i) {
      auto f = tet_.facet_vertices(T3::facet(t, i));
      while (f[0] != pid) std::rotate(f.begin(), f.begin() + 1, f.end());
      const std::uint64_t key = std::uint64_t{f[1]} << 32 | f[2];
      const std::uint64_t twin_key = std::uint64_t{f[2]} << 32 | f[1];
      if (const auto it = open.find(twin_key); it != open.end()) {
        tet_.link(T3::facet(t, i), it->second);
        open.erase(it);
      } else {
        open.emplace(key, T3::facet(t, i));
      }
    }
  }
  DTLAB_ASSERT(open.empty());
  // Unused cavity slots: remove from the highest, so that each move takes a live record.
  if (cavity_.size() > boundary.size()) {
    std::vector<std::uint32_t> spare(cavity_.begin() + static_cast<std::ptrdiff_t>(boundary.size()), cavity_.end());
    for (const std::uint32_t s : spare) records[s].vertex[0] = T3::kNone;
    std::sort(spare.begin(), spare.end(), std::greater<>());
    for (const std::uint32_t s : spare) {
      // The last record may itself be spare: then just drop it.
      while (!records.empty() && records.back().vertex[0] == T3::kNone &&
             static_cast<std::uint32_t>(records.size() - 1) > s)
        records.pop_back();
      if (s < records.size()) remove_slot(s);
    }
    mark_.resize(records.size());
  }
  last_ = new_.front() < records.size() ? new_.front() : 0;
  return pid;
}

}  // namespace dtlab
