// libFuzzer target: every predicate and every stage against the exact reference
// (verify/exact_reference.hpp, GMP rationals), plus the symbolic perturbation and antisymmetry.
// Any disagreement prints the points and traps.
//
// Input layout: byte 0 picks how the rest becomes 15 coordinates (x, y, z of five points; the
// 2D predicates use the first eight as x, y of four points), byte 1 an optional scaling and
// translation, byte 2 a transposition to test antisymmetry with; then the payload:
//   mode 0  raw doubles, 8 bytes each, mapped into the supported range (coordinate_from_bits);
//   mode 1  signed bytes: small integers, full of collinear, cocircular and repeated points;
//   mode 2  signed 16-bit integers: larger lattices, still exact, and their degeneracies;
//   mode 3  two signed bytes per coordinate, k and s: k / 2 moved by s nextafter steps, exactly
//           degenerate half-integer configurations a few ulps off, whose coordinate differences
//           round (Kettner et al.'s setting: 0.5 + i ulp against 12 and 24).
// Missing bytes read as zero. Every coordinate ends in the supported range.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <tuple>
#include <utility>

#include "kernel/coordinate_range.hpp"
#include "kernel/predicates.hpp"
#include "verify/exact_reference.hpp"
#include "verify/generators/near_degenerate.hpp"

namespace {

using dtlab::FilteredSign;
using dtlab::Sign;
using dtlab::Vec2;
using dtlab::Vec3;
namespace gen = dtlab::gen;
namespace ref = dtlab::reference;
namespace stage = dtlab::stage;

constexpr int kCoordinates = 15;

class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= std::uint64_t{byte()} << (8 * i);
    return v;
  }
  std::int16_t i16() {
    const auto lo = byte();
    return static_cast<std::int16_t>(lo | (byte() << 8));
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

std::array<double, kCoordinates> decode(Reader& in, int mode) {
  std::array<double, kCoordinates> v{};
  switch (mode) {
    case 0:
      for (double& x : v) x = gen::coordinate_from_bits(in.u64());
      break;
    case 1:
      for (double& x : v) x = static_cast<std::int8_t>(in.byte());
      break;
    case 2:
      for (double& x : v) x = in.i16();
      break;
    default:
      for (double& x : v) {
        const double k = static_cast<std::int8_t>(in.byte()) / 2.0;
        x = gen::nudge(k, static_cast<std::int8_t>(in.byte()));
      }
  }
  return v;
}

// Byte 1: bit 0 scales by 2^e (e from bits 2..7, spread over [-142, 126]); bit 1 translates by
// 1e9 in every coordinate. Integer modes stay exact under both.
void transform(std::array<double, kCoordinates>& v, std::uint8_t t) {
  if (t & 1) {
    const int e = -142 + ((t >> 2) * 268) / 63;
    for (double& x : v) x = gen::clamp_to_range(std::ldexp(x, e));
  }
  if (t & 2)
    for (double& x : v) x = gen::clamp_to_range(x + gen::kFarOffset);
}

std::string describe(std::span<const double> v) {
  std::string out;
  char buf[40];
  for (double x : v) {
    std::snprintf(buf, sizeof buf, "%s%a", out.empty() ? "" : ", ", x);
    out += buf;
  }
  return out;
}

[[noreturn]] void fail(const char* predicate, const char* what, Sign got, Sign want,
                       std::span<const double> coordinates) {
  std::fprintf(stderr, "%s: %s says %s, reference %s, coordinates {%s}\n", predicate, what,
               dtlab::to_string(got), dtlab::to_string(want), describe(coordinates).c_str());
  __builtin_trap();
}

// Checks every stage of one predicate on `p` (points as a tuple) and on p with two points
// exchanged (the sign must flip).
template <class Tuple, class Filtered, class Uncounted, class Semi, class Adaptive, class Exact, class Reference>
void check(const char* name, const Tuple& p, std::pair<int, int> swap, Filtered filtered, Uncounted uncounted,
           Semi semistatic, Adaptive adaptive, Exact exact, Reference reference,
           std::span<const double> coordinates) {
  const auto call = [&](auto f, const Tuple& q) { return std::apply(f, q); };
  const Sign want = call(reference, p);
  if (const FilteredSign s = call(semistatic, p); s && *s != want) fail(name, "semistatic", *s, want, coordinates);
  if (const FilteredSign s = call(adaptive, p); s && *s != want) fail(name, "adaptive", *s, want, coordinates);
  if (const Sign s = call(exact, p); s != want) fail(name, "exact", s, want, coordinates);
  if (const Sign s = call(filtered, p); s != want) fail(name, "filtered", s, want, coordinates);
  if (const Sign s = call(uncounted, p); s != want) fail(name, "uncounted", s, want, coordinates);
  const auto n = static_cast<int>(std::tuple_size_v<Tuple>);
  if (swap.first % n != swap.second % n) {
    Tuple q = p;
    std::swap(q[static_cast<std::size_t>(swap.first % n)], q[static_cast<std::size_t>(swap.second % n)]);
    if (const Sign s = call(filtered, q); s != -want) fail(name, "filtered after a transposition", s, -want, coordinates);
  }
}

template <class Tuple>
bool distinct(const Tuple& p) {
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      if (p[i] == p[j]) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in(data, size);
  const int mode = in.byte() % 4;
  const std::uint8_t t = in.byte();
  const std::uint8_t s = in.byte();
  const std::pair<int, int> swap{s & 7, s >> 5};
  std::array<double, kCoordinates> v = decode(in, mode);
  transform(v, t);
  for (double x : v)
    if (!dtlab::coordinate_in_range(x)) {
      std::fprintf(stderr, "decoded coordinate %a is outside the supported range\n", x);
      __builtin_trap();
    }

  const std::array<Vec2, 4> p2{Vec2{v[0], v[1]}, Vec2{v[2], v[3]}, Vec2{v[4], v[5]}, Vec2{v[6], v[7]}};
  const std::array<Vec3, 5> p3{Vec3{v[0], v[1], v[2]}, Vec3{v[3], v[4], v[5]}, Vec3{v[6], v[7], v[8]},
                               Vec3{v[9], v[10], v[11]}, Vec3{v[12], v[13], v[14]}};
  const std::array<Vec2, 3> o2{p2[0], p2[1], p2[2]};
  const std::array<Vec3, 4> o3{p3[0], p3[1], p3[2], p3[3]};

  check("orient2d", o2, swap, dtlab::orient2d, dtlab::uncounted::orient2d,
        stage::orient2d_semistatic, stage::orient2d_adaptive, stage::orient2d_exact,
        ref::orient2d, v);
  check("incircle", p2, swap, dtlab::incircle, dtlab::uncounted::incircle,
        stage::incircle_semistatic, stage::incircle_adaptive, stage::incircle_exact,
        ref::incircle, v);
  check("orient3d", o3, swap, dtlab::orient3d, dtlab::uncounted::orient3d,
        stage::orient3d_semistatic, stage::orient3d_adaptive, stage::orient3d_exact,
        ref::orient3d, v);
  check("insphere", p3, swap, dtlab::insphere, dtlab::uncounted::insphere,
        stage::insphere_semistatic, stage::insphere_adaptive, stage::insphere_exact,
        ref::insphere, v);

  // The perturbation: the documented scheme, zero only on a line (plane), flips under a
  // transposition. Defined for distinct points only.
  if (distinct(p2)) {
    const Sign got = std::apply(dtlab::incircle_perturbed, p2);
    const Sign want = std::apply(ref::incircle_perturbed, p2);
    if (got != want) fail("incircle_perturbed", "kernel", got, want, v);
    if ((got == Sign::Zero) != ref::all_collinear(p2)) fail("incircle_perturbed", "zero iff collinear", got, want, v);
    if (swap.first % 4 != swap.second % 4) {
      std::array<Vec2, 4> q = p2;
      std::swap(q[static_cast<std::size_t>(swap.first % 4)], q[static_cast<std::size_t>(swap.second % 4)]);
      if (const Sign r = std::apply(dtlab::incircle_perturbed, q); r != -got)
        fail("incircle_perturbed", "after a transposition", r, -got, v);
    }
  }
  if (distinct(p3)) {
    const Sign got = std::apply(dtlab::insphere_perturbed, p3);
    const Sign want = std::apply(ref::insphere_perturbed, p3);
    if (got != want) fail("insphere_perturbed", "kernel", got, want, v);
    if ((got == Sign::Zero) != ref::all_coplanar(p3)) fail("insphere_perturbed", "zero iff coplanar", got, want, v);
    if (swap.first % 5 != swap.second % 5) {
      std::array<Vec3, 5> q = p3;
      std::swap(q[static_cast<std::size_t>(swap.first % 5)], q[static_cast<std::size_t>(swap.second % 5)]);
      if (const Sign r = std::apply(dtlab::insphere_perturbed, q); r != -got)
        fail("insphere_perturbed", "after a transposition", r, -got, v);
    }
  }
  return 0;
}
