// libFuzzer target: bytes -> a small planar straight line graph (points, a segment soup with
// crossings, overlaps, segments through vertices, duplicates and zero-length segments, markers,
// a hole) -> every registered constrained method. Each result must pass verify_constrained2d
// (validity in doubles, every segment a chain within the rounding bounds, the method's
// Delaunay property). InputError (a zero-length segment, a conforming piece with no double
// point inside) is an accepted answer; any other exception, or a failed check, prints the input
// (hex floats) and traps.
//
// Input layout: byte 0 picks how points are read, byte 1 their count n (1..64, 0 means 64),
// byte 2 flags (bit 0: keep the exterior; bit 1: a hole at the first point of a triangle given
// by the next point), then n points, then segments as pairs of bytes (indices mod n) to the end
// (at most 64):
//   mode 0  one byte per point: a 16 x 16 lattice (low and high nibble), full of collinear
//           triples, overlaps and crossings at non-double points;
//   mode 1  raw doubles, 8 bytes per coordinate (gen::coordinate_from_bits: every binade of the
//           supported range);
//   mode 2  two bytes per coordinate, k and s: k / 2 moved by s % 4 ulps (gen::nudge), lattice
//           configurations a few ulps off degenerate.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "algorithms/constrained2d/constrained2d.hpp"
#include "algorithms/constrained2d/registry.hpp"
#include "kernel/error.hpp"
#include "verify/checks_constrained2d.hpp"
#include "verify/generators/near_degenerate.hpp"

namespace {

using dtlab::Vec2;
using Segment = std::array<std::uint32_t, 2>;

constexpr std::size_t kMaxPoints = 64;
constexpr std::size_t kMaxSegments = 64;

class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::size_t left() const { return size_ - pos_; }
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= std::uint64_t{byte()} << (8 * i);
    return v;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

struct Graph {
  std::vector<Vec2> points;
  std::vector<Segment> segments;
  std::vector<int> markers;
  std::vector<Vec2> holes;
  bool keep_exterior = false;
};

Graph decode(const std::uint8_t* data, std::size_t size) {
  Reader in(data, size);
  const int mode = in.byte() % 3;
  std::size_t n = in.byte() % kMaxPoints;
  if (n == 0) n = kMaxPoints;
  const std::uint8_t flags = in.byte();
  Graph g;
  g.keep_exterior = (flags & 1) != 0;
  for (std::size_t i = 0; i < n && in.left() > 0; ++i) {
    Vec2 p;
    switch (mode) {
      case 0: {
        const std::uint8_t b = in.byte();
        p = {static_cast<double>(b & 15), static_cast<double>(b >> 4)};
        break;
      }
      case 1: p = {dtlab::gen::coordinate_from_bits(in.u64()), dtlab::gen::coordinate_from_bits(in.u64())}; break;
      default: {
        double c[2];
        for (double& x : c) {
          const double k = static_cast<std::int8_t>(in.byte()) / 2.0;
          x = dtlab::gen::nudge(k, static_cast<std::int8_t>(in.byte()) % 4);
        }
        p = {c[0], c[1]};
      }
    }
    g.points.push_back(p);
  }
  if (g.points.empty()) return g;
  if ((flags & 2) && g.points.size() >= 3) {
    // The centroid of the first three points, where a hole removes whatever region holds it.
    const Vec2 a = g.points[0], b = g.points[1], c = g.points[2];
    g.holes.push_back({a.x / 3 + b.x / 3 + c.x / 3, a.y / 3 + b.y / 3 + c.y / 3});
  }
  const auto m = static_cast<std::uint32_t>(g.points.size());
  while (in.left() >= 2 && g.segments.size() < kMaxSegments) {
    const std::uint32_t a = in.byte() % m, b = in.byte() % m;
    g.segments.push_back({a, b});
    g.markers.push_back(static_cast<int>(g.segments.size() % 5));
  }
  return g;
}

[[noreturn]] void fail(const Graph& g, const std::string& what) {
  std::fprintf(stderr, "constrained2d_fuzz: %s\n%zu points:\n", what.c_str(), g.points.size());
  for (const Vec2& p : g.points) std::fprintf(stderr, "  %a %a\n", p.x, p.y);
  std::fprintf(stderr, "%zu segments:", g.segments.size());
  for (const Segment& s : g.segments) std::fprintf(stderr, " %u-%u", s[0], s[1]);
  std::fprintf(stderr, "\nholes: %zu, keep exterior: %d\n", g.holes.size(), int(g.keep_exterior));
  std::fflush(stderr);
  __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Graph g = decode(data, size);
  const dtlab::ConstrainedInput2 input{
      .points = g.points, .segments = g.segments, .segment_markers = g.markers, .holes = g.holes, .regions = {}};
  for (const dtlab::Constrained2dMethod& m : dtlab::constrained2d_methods()) {
    const std::string method(m.name);
    dtlab::Constrained2dResult result;
    try {
      result = dtlab::constrained2d(input, {.method = method, .keep_exterior = g.keep_exterior});
    } catch (const dtlab::InputError&) {
      continue;
    } catch (const std::exception& e) {
      fail(g, method + " threw: " + e.what());
    }
    const dtlab::ConstrainedCheckOptions2 options{.method = method, .keep_exterior = g.keep_exterior};
    const dtlab::ConstrainedCheckReport2 report = dtlab::verify_constrained2d(input, result, options);
    if (!report.ok) fail(g, method + ": verify_constrained2d: " + dtlab::to_text(report));
  }
  return 0;
}
