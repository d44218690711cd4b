// The optimization strategy of book §8.6 in 3D: classify the tetrahedra by Q_K, treat the bad
// ones worst first with the operators their pathology calls for (slivers, caps, needles, wedges:
// swaps first, then moving their vertices, then collapsing their shortest edge), then apply each
// operator to the whole mesh (sizes by collapse and split toward a unit mesh, the swap pass,
// relocation sweeps), and repeat while a round still improves the worst or the mean quality. A
// round runs the operators by name from their registry (registry.hpp), in options.sequence.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <limits>
#include <utility>
#include <vector>

#include "algorithms/common/optimize_strategy.hpp"
#include "algorithms/optimize3d/local.hpp"
#include "algorithms/optimize3d/optimize3d.hpp"
#include "algorithms/optimize3d/registry.hpp"
#include "kernel/error.hpp"
#include "kernel/quality.hpp"

namespace dtlab {

using optimize3d_detail::edge_length;
using optimize3d_detail::tetrahedron_quality;

namespace {

bool goal_asked(const Optimize3dOptions& o) {
  return o.goal_worst_quality > 0.0 || o.goal_min_dihedral_deg > 0.0 || o.goal_max_dihedral_deg > 0.0 ||
         o.goal_share_1_2 > 0.0;
}

bool share_short(const QualitySummary3& q, const Optimize3dOptions& o) { return q.share_1_2 < o.goal_share_1_2; }

bool meets_goal(const QualitySummary3& q, const Optimize3dOptions& o) {
  return (o.goal_worst_quality <= 0.0 || q.worst <= o.goal_worst_quality) && q.min_dihedral_deg >= o.goal_min_dihedral_deg &&
         (o.goal_max_dihedral_deg <= 0.0 || q.max_dihedral_deg <= o.goal_max_dihedral_deg) && !share_short(q, o);
}

// Whether a tetrahedron misses the goal: a dihedral angle out of its bounds, Q_K above it (or
// above bad_quality), or, while the share in [1, 2] is short (`share`), Q_K above 2. The bounds
// as cosines, computed once.
class GoalTest {
 public:
  GoalTest(const Optimize3dOptions& o, bool share) {
    constexpr double kRadians = 0.017453292519943295769;  // pi / 180
    cos_min_ = std::cos(o.goal_min_dihedral_deg * kRadians);
    cos_max_ = o.goal_max_dihedral_deg > 0.0 ? std::cos(o.goal_max_dihedral_deg * kRadians) : -2.0;
    worst_ = o.goal_worst_quality > 0.0 ? std::min(o.goal_worst_quality, o.bad_quality) : o.bad_quality;
    if (share) worst_ = std::min(worst_, 2.0);
  }
  // The cosine of the smallest dihedral angle of t when it is below the goal's, else +2: the
  // sort key of the dihedral step.
  double small_angle_cos(const Mesh3& mesh, std::uint32_t t) const {
    const auto v = mesh.tetrahedron(t);
    const auto c = dihedral_cosine_range(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]));
    return c[1] > cos_min_ ? c[1] : 2.0;
  }
  // Whether a tetrahedron with dihedral cosines c (dihedral_cosine_range) and Q_K q misses it.
  bool misses(const std::array<double, 2>& c, double q) const {
    return c[1] > cos_min_ || c[0] < cos_max_ || q > worst_;
  }

 private:
  double cos_min_ = 2.0, cos_max_ = -2.0, worst_ = 0.0;
};

// Per tetrahedron slot of a scan: bit 0, it misses the goal; bit 1, it misses it while the share
// in [1, 2] is short (Q_K > 2 too).
constexpr std::uint8_t kMisses = 1, kMissesShareShort = 2;

// One pass over the domain's tetrahedra for all that a round's end asks: the summary, and with a
// goal, the goal flags by slot (the next round's region and the count of misses read them while
// the mesh is unchanged). Q_K and the dihedral cosines of each tetrahedron computed once.
QualitySummary3 scan_quality(const Mesh3& mesh, const Optimize3dOptions* goal_options, std::vector<std::uint8_t>* flags) {
  std::optional<GoalTest> plain, share;
  if (goal_options) {
    plain.emplace(*goal_options, false);
    share.emplace(*goal_options, true);
    flags->assign(mesh.tetrahedron_capacity(), 0);
  }
  QualitySummary3 s;
  double sum = 0.0;
  std::uint64_t finite = 0;
  double lowest_cosine = 1.0, highest_cosine = -1.0;
  std::uint64_t in_1_2 = 0;
  for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    const double q = tetrahedron_quality(mesh, t);
    const auto v = mesh.tetrahedron(t);
    const auto cosines = dihedral_cosine_range(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]));
    if (goal_options)
      (*flags)[t] = static_cast<std::uint8_t>((plain->misses(cosines, q) ? kMisses : 0) |
                                              (share->misses(cosines, q) ? kMissesShareShort : 0));
    lowest_cosine = std::min(lowest_cosine, cosines[0]);
    highest_cosine = std::max(highest_cosine, cosines[1]);
    ++s.tetrahedra;
    in_1_2 += q <= 2.0;
    s.worst = std::max(s.worst, q);
    if (std::isfinite(q)) {
      sum += q;
      ++finite;
    }
  }
  s.mean = finite > 0 ? sum / static_cast<double>(finite) : 0.0;
  constexpr double kDegrees = 57.295779513082320877;  // 180 / pi
  if (s.tetrahedra > 0) {
    s.share_1_2 = static_cast<double>(in_1_2) / static_cast<double>(s.tetrahedra);
    s.min_dihedral_deg = std::acos(std::clamp(highest_cosine, -1.0, 1.0)) * kDegrees;
    s.max_dihedral_deg = std::acos(std::clamp(lowest_cosine, -1.0, 1.0)) * kDegrees;
  }
  return s;
}

std::uint8_t goal_bit(bool share) { return share ? kMissesShareShort : kMisses; }

std::uint64_t count_goal_misses(std::span<const std::uint8_t> flags, bool share) {
  const std::uint8_t bit = goal_bit(share);
  std::uint64_t n = 0;
  for (const std::uint8_t f : flags) n += (f & bit) != 0;
  return n;
}

// The region of a goal-driven round: the vertices of the tetrahedra that miss the goal (by the
// last scan's flags), then `goal_rings` times every vertex of a tetrahedron that has one.
std::vector<std::uint8_t> goal_region(const Mesh3& mesh, const Optimize3dOptions& o, std::span<const std::uint8_t> flags,
                                      bool share) {
  std::vector<std::uint8_t> active(mesh.vertex_capacity(), 0);
  const std::uint8_t bit = goal_bit(share);
  for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
    if (mesh.in_domain(t) && (flags[t] & bit))
      for (const std::uint32_t w : mesh.tetrahedron(t)) active[w] = 1;
  }
  for (std::uint32_t ring = 0; ring < o.goal_rings; ++ring) {
    const std::vector<std::uint8_t> inner = active;
    for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
      if (!mesh.is_alive(t) || mesh.is_ghost(t)) continue;
      const auto v = mesh.tetrahedron(t);
      if (inner[v[0]] || inner[v[1]] || inner[v[2]] || inner[v[3]])
        for (const std::uint32_t w : v) active[w] = 1;
    }
  }
  return active;
}

// The dihedral goal's last step, after the rounds: the free vertices of the tetrahedra whose
// smallest dihedral angle is below goal_min_dihedral_deg, smallest angle first, moved by
// try_relocate_dihedral3 (their balls' worst Q_K kept at most the mesh's worst, `worst`, or their
// own; the largest angle below the goal's). A few passes while they still move some.
std::uint64_t polish_dihedral_angles(Mesh3& mesh, const Optimize3dOptions& o, const MetricField3& field, double worst) {
  constexpr double kRadians = 0.017453292519943295769;  // pi / 180
  const GoalTest goal(o, false);
  RelocateDihedral3Options r;
  r.quality_limit = worst;
  if (o.goal_max_dihedral_deg > 0.0) r.max_dihedral_cos = std::cos(o.goal_max_dihedral_deg * kRadians);
  std::uint64_t moved = 0;
  std::vector<std::pair<double, std::uint32_t>> small;
  std::vector<std::uint8_t> tried_in;  // per vertex slot: tried in this pass
  for (int pass = 0; pass < 3; ++pass) {
    small.clear();
    for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
      if (!mesh.in_domain(t)) continue;
      const double c = goal.small_angle_cos(mesh, t);
      if (c <= 1.0) small.emplace_back(-c, t);
    }
    std::sort(small.begin(), small.end());
    tried_in.assign(mesh.vertex_capacity(), 0);
    std::uint64_t moved_now = 0;
    for (const auto& [key, t] : small) {
      if (!mesh.in_domain(t)) continue;
      for (const std::uint32_t v : mesh.tetrahedron(t)) {
        if (tried_in[v]) continue;
        tried_in[v] = 1;
        moved_now += try_relocate_dihedral3(mesh, v, field, r) ? 1 : 0;
      }
    }
    moved += moved_now;
    if (moved_now == 0) break;
  }
  return moved;
}

constexpr std::array<std::array<std::uint32_t, 2>, 6> kEdges{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

}  // namespace

OperatorResult optimize3d_detail::treat_bad_tetrahedra(Mesh3& mesh, const Optimize3dOptions& options,
                                                       const MetricField3& field, Optimize3dStats& stats,
                                                       const OperatorScope3&) {
  std::vector<std::uint32_t> shell, ring, ball;  // (the interior-vertex treatment's, below)
  for (const auto& b : optimize_detail::bad_elements(mesh, mesh.tetrahedron_capacity(), options.bad_quality,
                                                     [&](std::uint32_t t) { return tetrahedron_quality(mesh, t); },
                                                     [&](std::uint32_t t) { return mesh.tetrahedron(t); })) {
    if (!mesh.in_domain(b.t) || mesh.tetrahedron(b.t) != b.v) continue;  // changed by an earlier one
    bool done = false;
    if (options.swaps) {
      for (std::uint32_t i = 0; i < 4 && !done; ++i)
        if (try_face_swap(mesh, Mesh3::facet(b.t, i), options.margin)) {
          ++stats.face_swaps;
          done = true;
        }
      for (std::uint32_t k = 0; k < 6 && !done; ++k)
        if (try_shell_transformation(mesh, b.v[kEdges[k][0]], b.v[kEdges[k][1]], options.margin, nullptr, b.t)) {
          ++stats.shell_transformations;
          done = true;
        }
    }
    if (done) continue;
    if (options.relocation) {
      for (const std::uint32_t v : b.v)
        if (!mesh.is_dead_vertex(v) && try_relocate3(mesh, v, field, options.relocate)) {
          ++stats.relocations;
          done = true;
        }
    }
    if (done || !options.collapses) continue;
    // The shortest edge first.
    std::array<std::pair<double, std::uint32_t>, 6> edges;
    for (std::uint32_t k = 0; k < 6; ++k) edges[k] = {edge_length(mesh, b.v[kEdges[k][0]], b.v[kEdges[k][1]]), k};
    std::sort(edges.begin(), edges.end());
    for (const auto& [l, k] : edges) {
      if (try_collapse3(mesh, b.v[kEdges[k][0]], b.v[kEdges[k][1]], options.collapse, Collapse3Criterion::Improve)) {
        ++stats.collapses;
        done = true;
        break;
      }
    }
    // A tetrahedron between four boundary vertices that neither swaps nor moves nor collapses
    // cure (no vertex of it may move off the surface, and none of its faces is the boundary's
    // to flip) gets an interior vertex: an edge of it split, with no length or quality guard,
    // and the new vertex relocated (book §8.3.6 and §8.4: the point goes where its ball is
    // best), judged as one move: kept where the new ball's worst is below the old shell's, else
    // undone by collapsing the new vertex back (which gives the shell back).
    if (done || !options.interior_vertices || !options.relocation || !options.collapses) continue;
    bool inside = true;
    for (const std::uint32_t v : b.v) inside = inside && (mesh.flags(v) & Mesh3::kOnBoundary) != 0;
    if (!inside) continue;
    Split3Options split = options.split;
    split.short_length = 0.0;
    split.quality_limit = std::numeric_limits<double>::infinity();
    Collapse3Options undo = options.collapse;  // back to the shell, whatever it was
    undo.long_length = std::numeric_limits<double>::infinity();
    undo.quality_limit = std::numeric_limits<double>::infinity();
    for (auto it = edges.rbegin(); it != edges.rend() && !done; ++it) {
      const std::uint32_t a = b.v[kEdges[it->second][0]], c = b.v[kEdges[it->second][1]];
      if (!mesh.shell(a, c, shell, &ring) ||
          !std::all_of(shell.begin(), shell.end(), [&](std::uint32_t t) { return mesh.in_domain(t); }))
        continue;  // (not a free edge: try_split3 would refuse it)
      double before = 0.0;
      for (const std::uint32_t t : shell) before = std::max(before, tetrahedron_quality(mesh, t));
      const std::uint32_t m = try_split3(mesh, a, c, field, split);
      if (m == Tetrahedralization3::kNone) continue;
      for (int k = 0; k < 4 && try_relocate3(mesh, m, field, options.relocate); ++k) {
      }
      mesh.ball(m, ball);
      double after = 0.0;
      for (const std::uint32_t t : ball) after = std::max(after, tetrahedron_quality(mesh, t));
      if (after < before * (1.0 - options.margin)) {
        ++stats.splits;
        done = true;
      } else if (!try_collapse3(mesh, m, a, undo, Collapse3Criterion::NotWorse)) {
        // Collapsing m onto a gives back the shell's tetrahedra, positive before: refused only
        // by a broken invariant.
        throw InternalError("optimize3d: an interior vertex that did not help could not be removed again");
      }
    }
  }
  return {};
}

namespace {

// The 3D part of the round loop (algorithms/common/optimize_strategy.hpp): a round's operators,
// the goal, and the dihedral step after the rounds.
struct Rounds3 : optimize_detail::RoundState<Mesh3, Optimize3dOptions, MetricField3, Optimize3dStats> {
  static constexpr const char* kRoundStart = "optimize3d: at the start of a round";
  static constexpr const char* kName = "optimize3d";
  std::vector<Optimize3dOperator> sequence;  // options.sequence's operators
  const Optimize3dOptions* goal_options = goal_asked(options) ? &options : nullptr;
  std::vector<std::uint8_t> flags{};  // the last scan's goal flags, by tetrahedron slot
  std::uint64_t last_misses = std::numeric_limits<std::uint64_t>::max();
  optimize3d_detail::AttemptMemo memo_storage{mesh};
  optimize3d_detail::AttemptMemo* memo = options.remember_failures ? &memo_storage : nullptr;

  QualitySummary3 scan() { return scan_quality(mesh, goal_options, &flags); }

  optimize_detail::RoundGoal goal(const QualitySummary3& now) {
    if (!goal_options) return {};
    // A round that leaves a tenth fewer tetrahedra missing the goal improved too: rounds
    // restricted to their region hardly move the mean.
    const std::uint64_t misses = count_goal_misses(flags, share_short(now, options));
    const bool gained = 10 * misses < 9 * last_misses;
    last_misses = misses;
    return {gained, options.stop_at_goal && meets_goal(now, options)};
  }

  void finish(const QualitySummary3& before, QualitySummary3& last) {
    if (options.dihedral_step && options.goal_min_dihedral_deg > 0.0 &&
        last.min_dihedral_deg < options.goal_min_dihedral_deg && options.relocation) {
      stats.relocations += polish_dihedral_angles(mesh, options, field, last.worst);
      last = scan_quality(mesh, nullptr, nullptr);
    }
    stats.tetrahedra_before = before.tetrahedra;
    stats.tetrahedra_after = last.tetrahedra;
  }

  optimize_detail::RoundResult round(std::uint32_t index, const QualitySummary3& last) {
    // After the first round, with a goal and goal_rings: only around what misses it.
    std::vector<std::uint8_t> region_storage;
    if (index > 0 && options.goal_rings > 0 && goal_options)
      region_storage = goal_region(mesh, options, flags, share_short(last, options));
    const optimize3d_detail::Region region = region_storage;
    std::vector<std::uint32_t> seeds;
    if (!region.empty()) {
      for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
        if (!mesh.in_domain(t)) continue;
        const auto v = mesh.tetrahedron(t);
        if (region[v[0]] || region[v[1]] || region[v[2]] || region[v[3]]) seeds.push_back(t);
      }
    }
    const OperatorScope3 scope{region, seeds, memo};
    const OperatorResult r = optimize_detail::run_operators<Optimize3dOperator>(
        sequence, options.interrupt, "optimize3d",
        [&](const Optimize3dOperator& op) { return op.pass(mesh, options, field, stats, scope); });
    // A few collapses and splits that undo each other around a locked feature do not make a round
    // worth another: under one change per thousand vertices counts as none.
    return {r.size_changes * 1000 > mesh.live_vertex_count(), r.limit};
  }
};

}  // namespace

QualitySummary3 summarize_quality(const Mesh3& mesh) { return scan_quality(mesh, nullptr, nullptr); }

Optimize3dOptions optimize3d_effort(const std::string& level) {
  Optimize3dOptions o;
  if (level == "light") {
    o.max_rounds = 1;
    o.relocation_sweeps = 1;
  } else if (level == "standard") {
    o.swap_threshold = 2.0;
    o.region_swap_threshold = 1.5;
    o.relocation_sweeps = 1;
    o.goal_rings = 3;
    o.goal_worst_quality = 3.0;
    o.goal_share_1_2 = 0.97;
    o.goal_min_dihedral_deg = 20.0;
    o.goal_max_dihedral_deg = 150.0;
  } else if (level == "thorough") {
    o.goal_min_dihedral_deg = 25.0;
    o.goal_max_dihedral_deg = 150.0;
    o.stop_at_goal = false;
  } else {
    throw InputError("unknown optimization effort '" + level + "' (light, standard, thorough)");
  }
  return o;
}

Optimize3dStats optimize3d(Mesh3& mesh, const Optimize3dOptions& options, const MetricField3& field) {
  const auto& operators = options.operators ? *options.operators : optimize3d_operators();
  auto sequence = optimize_detail::operator_sequence(operators, options.sequence);
  return optimize_detail::optimize_rounds(Rounds3{{mesh, options, field}, std::move(sequence)});
}

}  // namespace dtlab
