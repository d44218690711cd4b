// The mesh statistics of book §7.13 / §8.7 (Tables 7.1-8.3) and the UGAWG unit-mesh measures:
// one pass over the elements (orientation decided exactly, Q_K, angles, mean ratio, measure),
// one over the mesh's unique edges (sorted, so that the sums and the report are the same bytes
// on every run), and the two printers.
#include "mesh/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>
#include <vector>

#include "kernel/constructions.hpp"
#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quality.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kUnitLengthMin = 0.70710678118654752440;  // 1 / sqrt(2)
constexpr double kUnitLengthMax = 1.41421356237309504880;  // sqrt(2)
constexpr double kDegreesPerRadian = 57.295779513082320876798;

// Neumaier's compensated sum: a mean over millions of elements that does not drift with n.
class Sum {
 public:
  void add(double v) noexcept {
    const double t = s_ + v;
    c_ += std::fabs(s_) >= std::fabs(v) ? (s_ - t) + v : (v - t) + s_;
    s_ = t;
  }
  double value() const noexcept { return s_ + c_; }

 private:
  double s_ = 0.0;
  double c_ = 0.0;
};

struct Range {
  double min = kInfinity;
  double max = -kInfinity;
  void add(double v) noexcept {
    min = std::min(min, v);
    max = std::max(max, v);
  }
};

// --- the per-dimension pieces: overloads on the element's points ---

Sign orientation(const std::array<Vec2, 3>& p) noexcept { return orient2d(p[0], p[1], p[2]); }
Sign orientation(const std::array<Vec3, 4>& p) noexcept { return orient3d(p[0], p[1], p[2], p[3]); }

double quality(const std::array<Vec2, 3>& p) noexcept { return shape_quality(p[0], p[1], p[2]); }
double quality(const std::array<Vec3, 4>& p) noexcept { return shape_quality(p[0], p[1], p[2], p[3]); }
double quality(const std::array<Vec2, 3>& p, const std::array<Metric2, 3>& m) noexcept {
  return shape_quality(p[0], p[1], p[2], m[0], m[1], m[2]);
}
double quality(const std::array<Vec3, 4>& p, const std::array<Metric3, 4>& m) noexcept {
  return shape_quality(p[0], p[1], p[2], p[3], m[0], m[1], m[2], m[3]);
}

double mean_ratio_in(const std::array<Vec2, 3>& p, const Metric2& m) noexcept { return mean_ratio(p[0], p[1], p[2], m); }
double mean_ratio_in(const std::array<Vec3, 4>& p, const Metric3& m) noexcept {
  return mean_ratio(p[0], p[1], p[2], p[3], m);
}

double signed_measure(const std::array<Vec2, 3>& p) noexcept { return signed_area(p[0], p[1], p[2]); }
double signed_measure(const std::array<Vec3, 4>& p) noexcept { return signed_volume(p[0], p[1], p[2], p[3]); }

// The angle between u and v in [0, pi]; atan2 keeps small and near-straight angles accurate,
// where acos of the normalised dot product loses half the digits.
double angle_between(const Vec2& u, const Vec2& v) noexcept { return std::atan2(std::fabs(cross(u, v)), dot(u, v)); }
double angle_between(const Vec3& u, const Vec3& v) noexcept { return std::atan2(norm(cross(u, v)), dot(u, v)); }

// The smallest and the largest of the angles between pairs (u, v), each measured by
// angle_between only when it can be one of them: its cosine from the normalised dot product
// (within a few 1e-16 of the true cosine where the squared norms are normal numbers) comes within
// 1e-9 of the largest or the smallest such cosine seen so far. The extreme angles are always among
// those measured, so the range is the one measuring every angle gives, bit for bit, for a few
// atan2 calls instead of six per tetrahedron.
class AngleRange {
 public:
  template <class V>
  void add(const V& u, const V& v) noexcept {
    const double uu = dot(u, u), vv = dot(v, v);
    const double product = uu * vv;
    const bool usable = uu > 1e-290 && vv > 1e-290 && product > 1e-290 && product < 1e290;
    const double c = usable ? dot(u, v) / std::sqrt(product) : 0.0;
    if (usable && c < max_cosine_ - kMargin && c > min_cosine_ + kMargin) return;
    if (usable) {
      max_cosine_ = std::max(max_cosine_, c);
      min_cosine_ = std::min(min_cosine_, c);
    }
    range_.add(angle_between(u, v));
  }
  const Range& range() const noexcept { return range_; }

 private:
  static constexpr double kMargin = 1e-9;
  Range range_;
  double max_cosine_ = -kInfinity, min_cosine_ = kInfinity;
};

// The three angles of a triangle.
void add_angles(const std::array<Vec2, 3>& p, AngleRange& angles) noexcept {
  for (int i = 0; i < 3; ++i) angles.add(p[(i + 1) % 3] - p[i], p[(i + 2) % 3] - p[i]);
}

// The six dihedral angles of a tetrahedron: along edge ij, the angle between e x (pk - pi) and
// e x (pl - pi), e = pj - pi: both normals are the projections of pk and pl on the plane normal
// to e turned by the same quarter turn, so their angle is the interior dihedral angle.
void add_angles(const std::array<Vec3, 4>& p, AngleRange& angles) noexcept {
  static constexpr int kEdgeAndOthers[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                               {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  for (const auto& q : kEdgeAndOthers) {
    const Vec3 e = p[q[1]] - p[q[0]];
    angles.add(cross(e, p[q[2]] - p[q[0]]), cross(e, p[q[3]] - p[q[0]]));
  }
}

template <std::size_t N>
constexpr std::size_t kEdgesPerElement = N * (N - 1) / 2;

const char* element_noun(std::size_t n) { return n == 3 ? "triangle" : "tetrahedron"; }

std::array<double, 2> coordinates(const Vec2& p) noexcept { return {p.x, p.y}; }
std::array<double, 3> coordinates(const Vec3& p) noexcept { return {p.x, p.y, p.z}; }

// Throws InputError naming vertex v and its first coordinate outside the exact predicates' range.
template <class Point>
void check_vertex(const Point& p, std::size_t v) {
  static constexpr const char* kNames[3] = {"x", "y", "z"};
  const auto c = coordinates(p);
  for (std::size_t k = 0; k < c.size(); ++k)
    if (!coordinate_in_range(c[k]))
      throw InputError("vertex " + std::to_string(v) + ": coordinate " + kNames[k] + " is " +
                           coordinate_problem(c[k]),
                       {v});
}

// Refuses what the measures cannot be trusted on: a vertex out of range, a used vertex with a
// coordinate the exact predicates do not support, a used vertex's metric that is not SPD.
// Returns which points the elements use.
template <class Point, class Metric, std::size_t N>
std::vector<char> check_input(std::span<const Point> points, std::span<const std::array<std::uint32_t, N>> cells,
                              std::span<const Metric> metrics) {
  if (!metrics.empty() && metrics.size() != points.size())
    throw InputError(std::to_string(metrics.size()) + " metrics for " + std::to_string(points.size()) +
                     " points: give one per point, or none");
  std::vector<char> used(points.size(), 0);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    for (std::uint32_t v : cells[i]) {
      if (v >= points.size())
        throw InputError(std::string(element_noun(N)) + " " + std::to_string(i) + ": vertex " + std::to_string(v) +
                             " out of range (" + std::to_string(points.size()) + " points)",
                         {i});
      used[v] = 1;
    }
  }
  for (std::size_t v = 0; v < points.size(); ++v) {
    if (!used[v]) continue;
    check_vertex(points[v], v);
    if (!metrics.empty() && !metrics[v].is_positive_definite())
      throw InputError("the metric at vertex " + std::to_string(v) + " is not positive definite", {v});
  }
  return used;
}

// Each edge once, as (smaller index << 32 | larger index), sorted: the elements' edges bucketed
// by their smaller end (a counting sort), each bucket's larger ends deduplicated by a stamp and
// sorted. The list sorting all the keys and dropping repeats gives, in two linear passes.
template <std::size_t N>
std::vector<std::uint64_t> unique_edges(std::span<const std::array<std::uint32_t, N>> cells, std::size_t point_count) {
  std::vector<std::size_t> start(point_count + 1, 0);
  for (const auto& c : cells)
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = i + 1; j < N; ++j) ++start[std::min(c[i], c[j]) + 1];
  for (std::size_t v = 0; v < point_count; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> upper(start[point_count]);
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (const auto& c : cells)
      for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = i + 1; j < N; ++j) upper[next[std::min(c[i], c[j])]++] = std::max(c[i], c[j]);
  }
  constexpr std::uint32_t kNone = 0xffffffffu;
  std::vector<std::uint32_t> stamp(point_count, kNone);
  std::vector<std::uint64_t> edges;
  edges.reserve(upper.size() / 4);
  for (std::size_t lo = 0; lo < point_count; ++lo) {
    const std::size_t first = edges.size();
    for (std::size_t k = start[lo]; k < start[lo + 1]; ++k) {
      const std::uint32_t hi = upper[k];
      if (stamp[hi] == lo) continue;
      stamp[hi] = static_cast<std::uint32_t>(lo);
      edges.push_back(static_cast<std::uint64_t>(lo) << 32 | hi);
    }
    std::sort(edges.begin() + static_cast<std::ptrdiff_t>(first), edges.end());
  }
  return edges;
}

std::size_t bin_of(double q) noexcept {
  for (std::size_t b = 0; b < QualityReport::kBinUpperBounds.size(); ++b)
    if (q <= QualityReport::kBinUpperBounds[b]) return b;
  return QualityReport::kBinUpperBounds.size();
}

template <class Point, class Metric, std::size_t N>
QualityReport measure(std::span<const Point> points, std::span<const std::array<std::uint32_t, N>> cells,
                      std::span<const Metric> metrics) {
  const std::vector<char> used = check_input(points, cells, metrics);
  const bool with_metric = !metrics.empty();

  QualityReport r;
  r.dimension = N == 3 ? 2 : 3;
  r.has_metric = with_metric;
  r.points = points.size();
  r.vertices = static_cast<std::uint64_t>(std::count(used.begin(), used.end(), char{1}));
  r.elements = cells.size();

  Sum quality_sum, mean_ratio_sum, measure_sum;
  std::uint64_t finite_quality = 0;
  double worst = -kInfinity, worst_ratio = kInfinity;
  AngleRange angles;
  for (const auto& c : cells) {
    std::array<Point, N> p;
    std::array<Metric, N> m;
    for (std::size_t i = 0; i < N; ++i) {
      p[i] = points[c[i]];
      if (with_metric) m[i] = metrics[c[i]];
    }
    const Sign s = orientation(p);
    if (s == Sign::Negative) ++r.inverted;
    if (s == Sign::Zero) ++r.flat;

    double q = with_metric ? quality(p, m) : quality(p);
    if (std::isnan(q)) q = kInfinity;  // not measurable: the worst there is
    worst = std::max(worst, q);
    if (q != kInfinity) {
      quality_sum.add(q);
      ++finite_quality;
    }
    ++r.quality_bins[bin_of(q)];

    add_angles(p, angles);

    // The strictest vertex metric (largest determinant; the first of equals, for determinism).
    std::size_t strictest = 0;
    if (with_metric)
      for (std::size_t i = 1; i < N; ++i)
        if (m[i].determinant() > m[strictest].determinant()) strictest = i;
    const double ratio = s == Sign::Zero ? 0.0 : mean_ratio_in(p, with_metric ? m[strictest] : Metric{});
    worst_ratio = std::min(worst_ratio, ratio);
    mean_ratio_sum.add(ratio);

    measure_sum.add(signed_measure(p));
  }
  r.measure = measure_sum.value();
  if (!cells.empty()) {
    const double n = static_cast<double>(cells.size());
    r.quality_worst = worst;
    if (finite_quality > 0) r.quality_mean = quality_sum.value() / static_cast<double>(finite_quality);
    for (std::size_t b = 0; b < r.quality_bins.size(); ++b)
      r.quality_shares[b] = static_cast<double>(r.quality_bins[b]) / n;
    r.angle_min = angles.range().min * kDegreesPerRadian;
    r.angle_max = angles.range().max * kDegreesPerRadian;
    r.mean_ratio_worst = worst_ratio;
    r.mean_ratio_mean = mean_ratio_sum.value() / n;
  }

  const std::vector<std::uint64_t> edges = unique_edges(cells, points.size());
  r.edges = edges.size();
  if (!edges.empty()) {
    Range euclidean, metric_range;
    Sum euclidean_sum, metric_sum;
    for (const std::uint64_t e : edges) {
      const auto a = static_cast<std::uint32_t>(e >> 32), b = static_cast<std::uint32_t>(e);
      const double l = norm(points[b] - points[a]);
      euclidean.add(l);
      euclidean_sum.add(l);
      if (!with_metric) continue;
      const double lm = edge_length(points[a], metrics[a], points[b], metrics[b]);
      metric_range.add(lm);
      metric_sum.add(lm);
      if (lm >= kUnitLengthMin && lm <= kUnitLengthMax) ++r.unit_edges;
    }
    const double n = static_cast<double>(edges.size());
    r.edge_length_min = euclidean.min;
    r.edge_length_max = euclidean.max;
    r.edge_length_mean = euclidean_sum.value() / n;
    if (with_metric) {
      r.metric_length_min = metric_range.min;
      r.metric_length_max = metric_range.max;
      r.metric_length_mean = metric_sum.value() / n;
      r.unit_edge_share = static_cast<double>(r.unit_edges) / n;
    }
  }
  return r;
}

// --- printing ---

void append_json_real(std::string& out, double v) {
  if (std::isfinite(v))
    io::append_real(out, v);
  else
    out += "null";
}

class JsonObject {
 public:
  void key(const char* name) {
    out_ += out_.empty() ? "{\"" : ",\"";
    out_ += name;
    out_ += "\":";
  }
  void integer(const char* name, std::uint64_t v) {
    key(name);
    out_ += std::to_string(v);
  }
  void real(const char* name, double v) {
    key(name);
    append_json_real(out_, v);
  }
  void boolean(const char* name, bool v) {
    key(name);
    out_ += v ? "true" : "false";
  }
  std::string close() { return out_ + "}"; }

 private:
  std::string out_;
};

std::string text_real(double v) {
  if (std::isnan(v)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string text_percent(double share) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f%%", 100.0 * share);
  return buf;
}

void line(std::string& out, const char* label, const std::string& value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "  %-22s ", label);
  out += buf;
  out += value;
  out += '\n';
}

}  // namespace

QualityReport measure_quality(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 3>> triangles,
                              std::span<const Metric2> metrics) {
  return measure<Vec2, Metric2, 3>(points, triangles, metrics);
}

QualityReport measure_quality(std::span<const Vec3> points, std::span<const std::array<std::uint32_t, 4>> tetrahedra,
                              std::span<const Metric3> metrics) {
  return measure<Vec3, Metric3, 4>(points, tetrahedra, metrics);
}

std::string quality_json(const QualityReport& r) {
  const bool planar = r.dimension == 2;
  const bool m = r.has_metric;
  const double undefined = QualityReport::kUndefined;
  JsonObject j;
  j.integer("dimension", static_cast<std::uint64_t>(r.dimension));
  j.boolean("metric", m);
  j.integer("points", r.points);
  j.integer("vertices", r.vertices);
  j.integer("elements", r.elements);
  j.real("quality_worst", r.quality_worst);
  j.real("quality_mean", r.quality_mean);
  static constexpr const char* kBinKeys[4] = {"quality_1_2", "quality_2_3", "quality_3_10", "quality_over_10"};
  static constexpr const char* kShareKeys[4] = {"share_1_2", "share_2_3", "share_3_10", "share_over_10"};
  for (std::size_t b = 0; b < 4; ++b) j.integer(kBinKeys[b], r.quality_bins[b]);
  for (std::size_t b = 0; b < 4; ++b) j.real(kShareKeys[b], r.quality_shares[b]);
  j.real(planar ? "min_angle_deg" : "min_dihedral_deg", r.angle_min);
  j.real(planar ? "max_angle_deg" : "max_dihedral_deg", r.angle_max);
  j.integer("edges", r.edges);
  j.real("edge_length_min", r.edge_length_min);
  j.real("edge_length_max", r.edge_length_max);
  j.real("edge_length_mean", r.edge_length_mean);
  j.real("metric_length_min", m ? r.metric_length_min : undefined);
  j.real("metric_length_max", m ? r.metric_length_max : undefined);
  j.real("metric_length_mean", m ? r.metric_length_mean : undefined);
  if (m)
    j.integer("unit_edges", r.unit_edges);
  else
    j.real("unit_edges", undefined);
  j.real("unit_edge_share", m ? r.unit_edge_share : undefined);
  j.real("mean_ratio_worst", r.mean_ratio_worst);
  j.real("mean_ratio_mean", r.mean_ratio_mean);
  j.real(planar ? "area" : "volume", r.measure);
  j.integer("inverted", r.inverted);
  j.integer("flat", r.flat);
  return j.close();
}

std::string quality_table(const QualityReport& r) {
  const bool planar = r.dimension == 2;
  std::string out = planar ? "2D mesh quality" : "3D mesh quality";
  out += r.has_metric ? " (Q_K, lengths and mean ratio in the vertex metrics)\n" : " (Euclidean)\n";
  std::string vertices = std::to_string(r.vertices);
  if (r.points != r.vertices) vertices += " (of " + std::to_string(r.points) + " points)";
  line(out, "vertices (np)", vertices);
  line(out, "elements (ne)", std::to_string(r.elements));
  line(out, "Q_M (worst Q_K)", text_real(r.quality_worst));
  line(out, "mean Q_K", text_real(r.quality_mean));
  static constexpr const char* kBinLabels[4] = {"Q in [1,2]", "Q in ]2,3]", "Q in ]3,10]", "Q > 10"};
  for (std::size_t b = 0; b < 4; ++b)
    line(out, kBinLabels[b], std::to_string(r.quality_bins[b]) + " (" + text_percent(r.quality_shares[b]) + ")");
  line(out, planar ? "angles (deg)" : "dihedral angles (deg)",
       "min " + text_real(r.angle_min) + "  max " + text_real(r.angle_max));
  line(out, "edges", std::to_string(r.edges));
  line(out, "edge length", "min " + text_real(r.edge_length_min) + "  max " + text_real(r.edge_length_max) +
                               "  mean " + text_real(r.edge_length_mean));
  if (r.has_metric) {
    line(out, "metric edge length", "min " + text_real(r.metric_length_min) + "  max " +
                                        text_real(r.metric_length_max) + "  mean " + text_real(r.metric_length_mean));
    line(out, "unit edges",
         std::to_string(r.unit_edges) + " (" + (r.edges ? text_percent(r.unit_edge_share) : std::string("-")) +
             ") with length in [1/sqrt2, sqrt2]");
  }
  line(out, "mean ratio", "worst " + text_real(r.mean_ratio_worst) + "  mean " + text_real(r.mean_ratio_mean));
  line(out, planar ? "area" : "volume", text_real(r.measure));
  line(out, "inverted / flat", std::to_string(r.inverted) + " / " + std::to_string(r.flat));
  return out;
}

namespace {

template <class Mesh, class Metric>
QualityReport domain_quality_of(const Mesh& mesh) {
  std::vector<std::uint32_t> ids;
  const auto data = mesh.domain(&ids);
  std::vector<Metric> metrics;
  metrics.reserve(ids.size());
  for (const std::uint32_t v : ids) metrics.push_back(mesh.metric(v));
  if constexpr (std::is_same_v<Metric, Metric2>)
    return measure_quality(data.vertices, data.triangles, metrics);
  else
    return measure_quality(data.vertices, data.tetrahedra, metrics);
}

}  // namespace

QualityReport domain_quality(const Mesh2& mesh) { return domain_quality_of<Mesh2, Metric2>(mesh); }
QualityReport domain_quality(const Mesh3& mesh) { return domain_quality_of<Mesh3, Metric3>(mesh); }

}  // namespace dtlab
