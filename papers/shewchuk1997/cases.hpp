// Inputs of papers/shewchuk1997: fixed-seed point tuples for orient2d, incircle, orient3d and
// insphere, drawn from verify/generators/near_degenerate.hpp with a fresh line / circle / plane /
// sphere per tuple, so that no two tuples share a degeneracy. Three inputs per predicate:
//   random      independent points uniform in [-1, 1)^d (Shewchuk's "uniform random");
//   near        points up to 3 ulps per coordinate off a random line / circle / plane / sphere
//               (his "nearly degenerate" in spirit: the answer is almost never zero, but the
//               double determinant cannot tell);
//   degenerate  exactly collinear / cocircular / coplanar / cospherical integer points: zero.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "kernel/vec.hpp"
#include "verify/generators/near_degenerate.hpp"

namespace dtlab::papers {

enum class Input { Random, Near, Degenerate };
inline constexpr std::array<Input, 3> kInputs = {Input::Random, Input::Near, Input::Degenerate};
inline const char* to_string(Input in) {
  return in == Input::Random ? "random" : (in == Input::Near ? "near" : "degenerate");
}

// Up to 3 ulps per coordinate, as bench/predicate_inputs.hpp: enough to defeat the semi-static
// filter on almost every tuple, too little to move a tuple far from its degenerate position.
inline constexpr int kNearUlps = 3;

// The first N generated points, as one tuple.
template <std::size_t N, class Point>
std::array<Point, N> first(const std::vector<Point>& points) {
  std::array<Point, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = points[i];
  return out;
}

template <std::size_t N>
std::array<Vec2, N> tuple2(gen::Rng& rng, Input in) {
  constexpr bool kCircle = N == 4;  // incircle; orient2d otherwise
  switch (in) {
    case Input::Random: return first<N>(gen::uniform_box(rng, N, Vec2{-1, -1}, Vec2{1, 1}));
    case Input::Near:
      return first<N>(kCircle ? gen::near_cocircular2(rng, N, kNearUlps) : gen::near_collinear2(rng, N, kNearUlps));
    case Input::Degenerate:
      return first<N>(kCircle ? gen::exact_cocircular2(rng, N) : gen::exact_collinear2(rng, N));
  }
  return {};
}

template <std::size_t N>
std::array<Vec3, N> tuple3(gen::Rng& rng, Input in) {
  constexpr bool kSphere = N == 5;  // insphere; orient3d otherwise
  switch (in) {
    case Input::Random: return first<N>(gen::uniform_box(rng, N, Vec3{-1, -1, -1}, Vec3{1, 1, 1}));
    case Input::Near:
      return first<N>(kSphere ? gen::near_cospherical3(rng, N, kNearUlps) : gen::near_coplanar3(rng, N, kNearUlps));
    case Input::Degenerate:
      return first<N>(kSphere ? gen::exact_cospherical3(rng, N) : gen::exact_coplanar3(rng, N));
  }
  return {};
}

// `count` tuples of input `in` for the predicate numbered `predicate` (its own seed per pair).
template <class Point, std::size_t N>
std::vector<std::array<Point, N>> make_cases(int predicate, Input in, std::size_t count) {
  gen::Rng rng(gen::kDefaultSeed + 97u * static_cast<std::uint64_t>(predicate) + static_cast<std::uint64_t>(in));
  std::vector<std::array<Point, N>> cases;
  cases.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    if constexpr (std::is_same_v<Point, Vec2>)
      cases.push_back(tuple2<N>(rng, in));
    else
      cases.push_back(tuple3<N>(rng, in));
  }
  return cases;
}

}  // namespace dtlab::papers
