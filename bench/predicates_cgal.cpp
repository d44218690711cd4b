// CGAL's Exact_predicates_inexact_constructions_kernel (Epick) on predicates_bench's cases: the
// only translation unit of the benchmark that compiles CGAL's headers.
//
// Sign conventions, checked on every case against dtlab's exact stage before timing (a mismatch
// fails the benchmark with the case's index):
//   CGAL::orientation(p, q, r)               == orient2d(p, q, r)       (LEFT_TURN = POSITIVE)
//   CGAL::side_of_oriented_circle(p, q, r, t) == incircle(p, q, r, t)   (ON_POSITIVE_SIDE = inside
//                                                                        for p, q, r ccw)
//   CGAL::orientation(p, q, r, s)            == orient3d(p, q, r, s)    (sign of det(q-p, r-p, s-p))
//   CGAL::side_of_oriented_sphere(p, q, r, s, t) == insphere(p, q, r, s, t) (ON_POSITIVE_SIDE =
//                                                                        inside for positive pqrs)
// so each CGAL result maps to dtlab's Sign by its integer value, with no sign flip.
#include "bench/predicates_cgal.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/version.h>

#include <memory>
#include <string>
#include <vector>

#include "kernel/predicates.hpp"

namespace dtlab::bench {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = K::Point_2;
using P3 = K::Point_3;

P2 to_cgal(const Vec2& p) { return P2(p.x, p.y); }
P3 to_cgal(const Vec3& p) { return P3(p.x, p.y, p.z); }

template <class R>
Sign to_sign(R r) {
  return static_cast<Sign>(static_cast<int>(r));
}

// The cases as CGAL points, converted once (not timed), with dtlab's exact signs to check against.
template <class CgalPoint, class Case>
struct CgalCases {
  std::vector<std::array<CgalPoint, std::tuple_size_v<Case>>> cases;
  std::vector<Sign> expected;
};

template <class CgalPoint, class Case, class Exact>
std::shared_ptr<const CgalCases<CgalPoint, Case>> convert(const std::vector<Case>& in, Exact exact) {
  auto out = std::make_shared<CgalCases<CgalPoint, Case>>();
  for (const Case& c : in) {
    std::array<CgalPoint, std::tuple_size_v<Case>> t;
    for (std::size_t i = 0; i < c.size(); ++i) t[i] = to_cgal(c[i]);
    out->cases.push_back(t);
    out->expected.push_back(exact(c));
  }
  return out;
}

template <class Data, class F>
void add(const char* predicate, Dist d, std::shared_ptr<const Data> data, F f) {
  for (const Consumer consumer : {Consumer::Sum, Consumer::Branch})
    benchmark::RegisterBenchmark(
        bench_name(predicate, "cgal_epick", d, consumer).c_str(),
        [data, consumer, f](benchmark::State& state) {
          for (std::size_t i = 0; i < data->cases.size(); ++i)
            if (f(data->cases[i]) != data->expected[i]) {
              state.SkipWithError(("CGAL and dtlab disagree on case " + std::to_string(i)).c_str());
              return;
            }
          run_cases(state, data->cases, consumer, f);
        });
}

}  // namespace

const char* cgal_version() { return CGAL_VERSION_STR; }

void register_cgal_orient2d(Dist d) {
  auto data = convert<P2>(orient2d_cases(d), [](const Orient2dCase& t) {
    return stage::orient2d_exact(t[0], t[1], t[2]);
  });
  add("orient2d", d, data, [](const auto& t) { return to_sign(CGAL::orientation(t[0], t[1], t[2])); });
}

void register_cgal_incircle(Dist d) {
  auto data = convert<P2>(incircle_cases(d), [](const IncircleCase& t) {
    return stage::incircle_exact(t[0], t[1], t[2], t[3]);
  });
  add("incircle", d, data, [](const auto& t) {
    return to_sign(CGAL::side_of_oriented_circle(t[0], t[1], t[2], t[3]));
  });
}

void register_cgal_orient3d(Dist d) {
  auto data = convert<P3>(orient3d_cases(d), [](const Orient3dCase& t) {
    return stage::orient3d_exact(t[0], t[1], t[2], t[3]);
  });
  add("orient3d", d, data,
      [](const auto& t) { return to_sign(CGAL::orientation(t[0], t[1], t[2], t[3])); });
}

void register_cgal_insphere(Dist d) {
  auto data = convert<P3>(insphere_cases(d), [](const InsphereCase& t) {
    return stage::insphere_exact(t[0], t[1], t[2], t[3], t[4]);
  });
  add("insphere", d, data, [](const auto& t) {
    return to_sign(CGAL::side_of_oriented_sphere(t[0], t[1], t[2], t[3], t[4]));
  });
}

}  // namespace dtlab::bench
