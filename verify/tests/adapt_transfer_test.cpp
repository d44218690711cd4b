// Solution transfer (algorithms/adapt/transfer.hpp): exact on linear fields, identity on the
// same mesh, O(h^2) on a quadratic, the conservative option, boundary snap, bad input named; in
// 3D exact on linear fields (across a hole too), the snap outside, the limit, conservation.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "algorithms/adapt/transfer.hpp"
#include "kernel/error.hpp"
#include "verify/generators/grid_meshes.hpp"
#include "verify/generators/kuhn_cubes.hpp"

namespace dtlab {
namespace {

MeshData2 grid(int n, double jitter) { return gen::jittered_grid(n, jitter); }

// A polygon of k sides inscribed in the unit circle, fanned from its centre.
MeshData2 disc(int k) {
  MeshData2 m;
  m.vertices.push_back({0.0, 0.0});
  for (int i = 0; i < k; ++i) {
    const double a = 2.0 * std::numbers::pi * i / k;
    m.vertices.push_back({std::cos(a), std::sin(a)});
  }
  m.vertex_refs.assign(m.vertices.size(), 0);
  for (int i = 0; i < k; ++i) {
    m.triangles.push_back({0, std::uint32_t(1 + i), std::uint32_t(1 + (i + 1) % k)});
    m.triangle_refs.push_back(1);
  }
  return m;
}

template <class F>
std::vector<double> sample(const MeshData2& m, F f, std::size_t nc = 1) {
  std::vector<double> u;
  for (const Vec2& p : m.vertices) {
    for (std::size_t k = 0; k < nc; ++k) u.push_back(f(p) * double(k + 1) + double(k));
  }
  return u;
}

TEST(AdaptTransfer, ExactOnLinearFieldsAnyComponentCount) {
  const MeshData2 a = grid(13, 0.3), b = grid(29, 0.25);
  auto lin = [](const Vec2& p) { return 3.0 * p.x - 2.0 * p.y + 0.5; };
  for (std::size_t nc : {1u, 3u, 6u}) {
    const std::vector<double> u = sample(a, lin, nc);
    const std::vector<double> w = transfer_field2(a, u, nc, b);
    const std::vector<double> expected = sample(b, lin, nc);
    ASSERT_EQ(w.size(), expected.size());
    for (std::size_t i = 0; i < w.size(); ++i) EXPECT_NEAR(w[i], expected[i], 1e-12 * (1.0 + std::abs(expected[i])));
  }
}

TEST(AdaptTransfer, IdentityOnTheSameMesh) {
  const MeshData2 a = grid(17, 0.3);
  const std::vector<double> u = sample(a, [](const Vec2& p) { return std::sin(5 * p.x) * std::exp(p.y); });
  TransferStats st;
  const std::vector<double> w = transfer_field2(a, u, 1, a, {}, &st);
  EXPECT_EQ(w, u);
  EXPECT_EQ(st.located, a.vertices.size());
  EXPECT_EQ(st.snapped, 0u);
}

TEST(AdaptTransfer, QuadraticConvergesAtSecondOrder) {
  auto q = [](const Vec2& p) { return p.x * p.x + 3.0 * p.x * p.y - p.y * p.y; };
  const MeshData2 target = grid(37, 0.2);
  const std::vector<double> exact = sample(target, q);
  double previous = 0.0;
  for (int n : {8, 16, 32}) {
    const MeshData2 a = grid(n, 0.0);
    const std::vector<double> w = transfer_field2(a, sample(a, q), 1, target);
    double err = 0.0;
    for (std::size_t i = 0; i < w.size(); ++i) err = std::max(err, std::abs(w[i] - exact[i]));
    if (previous > 0.0) {
      const double rate = std::log2(previous / err);
      EXPECT_GT(rate, 1.7) << "n = " << n;
    }
    previous = err;
  }
}

TEST(AdaptTransfer, ConservativePreservesTheIntegral) {
  const MeshData2 a = disc(24), b = disc(37);  // different domains: the plain transfer loses mass
  const std::vector<double> u = sample(a, [](const Vec2& p) { return 2.0 + p.x * p.x + std::sin(3 * p.y); }, 3);
  TransferStats plain, cons;
  transfer_field2(a, u, 3, b, {}, &plain);
  const std::vector<double> w = transfer_field2(a, u, 3, b, {.conservative = true}, &cons);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_GT(std::abs(plain.integral_new[k] - plain.integral_old[k]), 1e-6 * std::abs(plain.integral_old[k]));
    EXPECT_NEAR(integrate_p1(b, w, 3, k), integrate_p1(a, u, 3, k), 1e-12 * std::abs(integrate_p1(a, u, 3, k)));
  }
}

TEST(AdaptTransfer, PointsOutsideACircleTakeTheNearestBoundaryValue) {
  const MeshData2 a = disc(16), b = disc(40);
  auto f = [](const Vec2& p) { return 1.0 + 2.0 * p.x + 5.0 * p.y; };
  TransferStats st;
  const std::vector<double> w = transfer_field2(a, sample(a, f), 1, b, {}, &st);
  EXPECT_GT(st.snapped, 0u);
  EXPECT_LT(st.max_outside_distance, 1.0 - std::cos(std::numbers::pi / 16) + 1e-12);
  // The value is f at the nearest point of the old boundary, found here by brute force.
  for (std::size_t v = 1; v < b.vertices.size(); ++v) {
    const Vec2 p = b.vertices[v];
    double best = 1e300, value = 0.0;
    for (int i = 0; i < 16; ++i) {
      const Vec2 s = a.vertices[1 + i], e = a.vertices[1 + (i + 1) % 16];
      const Vec2 d = e - s;
      const double t = std::clamp(dot(p - s, d) / dot(d, d), 0.0, 1.0);
      const Vec2 q{s.x + t * d.x, s.y + t * d.y};
      if (norm(p - q) < best) best = norm(p - q), value = f(q);
    }
    EXPECT_NEAR(w[v], value, 1e-12) << "new vertex " << v + 1;
  }
}

TEST(AdaptTransfer, MetricsStayPositiveDefinite) {
  const MeshData2 a = grid(9, 0.3), b = disc(30);  // b shrunk into a below
  MeshData2 c = b;
  for (Vec2& p : c.vertices) p = {0.5 + 0.45 * p.x, 0.5 + 0.45 * p.y};
  std::vector<Metric2> m;
  for (const Vec2& p : a.vertices) {
    // Strongly anisotropic, rotating: a component-wise mix of these would still be SPD, but the
    // size interpolation is what the control space uses (kernel/metric.hpp).
    const double th = 3.0 * p.x, l1 = 1e4, l2 = 1.0;
    const double co = std::cos(th), si = std::sin(th);
    m.push_back(Metric2{{l1 * co * co + l2 * si * si, (l1 - l2) * co * si, l1 * si * si + l2 * co * co}});
  }
  const std::vector<Metric2> w = transfer_metrics2(a, m, c);
  ASSERT_EQ(w.size(), c.vertices.size());
  for (std::size_t v = 0; v < w.size(); ++v) EXPECT_TRUE(w[v].is_positive_definite()) << v;
  const std::vector<Metric2> same = transfer_metrics2(a, m, a);
  for (std::size_t v = 0; v < m.size(); ++v) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(same[v].m[k], m[v].m[k], 1e-9 * 1e4) << v;
  }
  EXPECT_THROW(transfer_metrics2(a, std::span<const Metric2>(m).first(3), c), InputError);
}

TEST(AdaptTransfer, FarOutsideIsNamed) {
  const MeshData2 a = disc(16);
  MeshData2 b = disc(16);
  b.vertices[3] = {5.0, 5.0};
  try {
    transfer_field2(a, std::vector<double>(a.vertices.size(), 1.0), 1, b);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("new vertex 4"), std::string::npos) << e.what();
  }
}

TEST(AdaptTransfer, BadInputNamed) {
  const MeshData2 a = grid(4, 0.0);
  try {
    transfer_field2(a, std::vector<double>(a.vertices.size() * 2 + 1, 0.0), 2, a);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("values but the old mesh has"), std::string::npos) << e.what();
  }
  MeshData2 bad = a;
  std::swap(bad.triangles[5][1], bad.triangles[5][2]);  // clockwise
  try {
    transfer_field2(bad, std::vector<double>(bad.vertices.size(), 0.0), 1, a);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("6"), std::string::npos) << e.what();
  }
}

// The cells of an n x n x m block of unit cubes (minus the cells `hole` says), Kuhn-cut, scaled.
MeshData3 block(int n, int m, double scale, bool (*hole)(int, int, int) = nullptr) {
  std::vector<std::array<int, 3>> cells;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < m; ++k)
        if (hole == nullptr || !hole(i, j, k)) cells.push_back({i, j, k});
  MeshData3 d = gen::kuhn_cubes(cells);
  for (Vec3& p : d.vertices) p = scale * p;
  return d;
}

double linear3(const Vec3& p) { return 1.0 + 2.0 * p.x - p.y + 0.5 * p.z; }

std::vector<double> sample3(const MeshData3& m, double (*f)(const Vec3&)) {
  std::vector<double> out;
  for (const Vec3& p : m.vertices) out.push_back(f(p));
  return out;
}

TEST(AdaptTransfer3, ExactOnLinearFields) {
  const MeshData3 a = block(2, 2, 1.0), b = block(3, 3, 2.0 / 3.0);  // the same cube [0, 2]^3
  TransferStats st;
  const std::vector<double> w = transfer_field3(a, sample3(a, linear3), 1, b, {}, &st);
  EXPECT_EQ(st.located, b.vertices.size());
  EXPECT_EQ(st.snapped, 0u);
  for (std::size_t v = 0; v < b.vertices.size(); ++v) EXPECT_NEAR(w[v], linear3(b.vertices[v]), 1e-12);
}

TEST(AdaptTransfer3, AcrossAHole) {
  // A ring of cells around the hole [1, 2] x [1, 2] x [0, 1], old at size 1, new at size 1/2.
  const MeshData3 a = block(3, 1, 1.0, [](int i, int j, int) { return i == 1 && j == 1; });
  const MeshData3 b = block(6, 2, 0.5, [](int i, int j, int) { return (i == 2 || i == 3) && (j == 2 || j == 3); });
  TransferStats st;
  const std::vector<double> w = transfer_field3(a, sample3(a, linear3), 1, b, {}, &st);
  EXPECT_EQ(st.located, b.vertices.size());
  EXPECT_EQ(st.snapped, 0u);
  for (std::size_t v = 0; v < b.vertices.size(); ++v) EXPECT_NEAR(w[v], linear3(b.vertices[v]), 1e-12);
}

TEST(AdaptTransfer3, OutsideTakesTheNearestBoundaryPointAndFarIsNamed) {
  const MeshData3 a = block(2, 2, 1.0);
  MeshData3 b = block(2, 2, 1.0);
  for (Vec3& p : b.vertices) p = Vec3{1, 1, 1} + 1.01 * (p - Vec3{1, 1, 1});  // 1 % larger
  TransferStats st;
  const std::vector<double> w = transfer_field3(a, sample3(a, linear3), 1, b, {}, &st);
  EXPECT_GT(st.snapped, 0u);
  EXPECT_NEAR(st.max_outside_distance, 0.01 * std::sqrt(3.0), 1e-12);  // a corner of the cube
  for (std::size_t v = 0; v < b.vertices.size(); ++v) {
    const Vec3& p = b.vertices[v];
    const Vec3 nearest{std::clamp(p.x, 0.0, 2.0), std::clamp(p.y, 0.0, 2.0), std::clamp(p.z, 0.0, 2.0)};
    EXPECT_NEAR(w[v], linear3(nearest), 1e-12);
  }
  for (Vec3& p : b.vertices) p = 3.0 * p;
  try {
    transfer_field3(a, sample3(a, linear3), 1, b);
    FAIL() << "a mesh three times larger was transferred";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("outside the old mesh"), std::string::npos) << e.what();
  }
}

TEST(AdaptTransfer3, ConservativePreservesTheIntegralAndMetricsStayPositive) {
  const MeshData3 a = block(2, 2, 1.0);
  MeshData3 b = block(3, 3, 0.7);  // [0, 2.1]^3: larger, so the plain transfer gains mass
  auto f = [](const Vec3& p) { return 2.0 + p.x * p.x + std::sin(3 * p.y) * p.z; };
  std::vector<double> u;
  std::vector<Metric3> m;
  for (const Vec3& p : a.vertices) {
    u.push_back(f(p));
    m.push_back(Metric3::from_sizes({1, 0, 0}, {0, 1, 0}, 0.1 + p.x, 0.01 + 0.1 * p.y, 0.5));
  }
  TransferStats st;
  const std::vector<double> w = transfer_field3(a, u, 1, b, {.conservative = true}, &st);
  EXPECT_NEAR(integrate_p1(b, w, 1, 0), integrate_p1(a, u, 1, 0), 1e-12 * std::abs(integrate_p1(a, u, 1, 0)));
  for (const Metric3& x : transfer_metrics3(a, m, b)) EXPECT_TRUE(x.is_positive_definite());
  EXPECT_THROW(transfer_metrics3(a, std::vector<Metric3>(3), b), InputError);
  EXPECT_THROW(transfer_field3(a, std::vector<double>(5), 1, b), InputError);
}

}  // namespace
}  // namespace dtlab
