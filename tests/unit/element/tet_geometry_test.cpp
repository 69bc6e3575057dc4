// Reference geometry of the MINI tetrahedron: shape-function gradients, partition of unity,
// the bubble and its integrals, and rejection of inverted elements.
#include "element/tet_geometry.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "element/bubble.hpp"
#include "element_test_support.hpp"

namespace plisse::mini {
namespace {

/// Barycentric coordinates of X from the geometry: L_a(X) = δ_a0 + Grad L_a · (X - X_0).
std::array<double, 4> barycentric(const TetGeometry& g, const std::array<Vec3d, 4>& corners,
                                  const Vec3d& X) {
  std::array<double, 4> L{};
  for (int a = 0; a < 4; ++a) L[a] = (a == 0 ? 1.0 : 0.0) + g.grad_N[a].dot(X - corners[0]);
  return L;
}

TEST(TetGeometry, VolumeWeightsAndShapeGradients) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto X = test::random_tet(seed);
    const TetGeometry g = compute_tet_geometry(X);
    const double volume = (X[1] - X[0]).cross(X[2] - X[0]).dot(X[3] - X[0]) / 6.0;
    EXPECT_NEAR(g.volume, volume, 1e-14 * volume);
    double weight_sum = 0.0;
    for (double w : g.weight) weight_sum += w;
    EXPECT_NEAR(weight_sum, volume, 1e-14 * volume);
    const double G_scale = g.grad_N[1].norm();
    // Σ_a Grad N_a = 0 (the N_a sum to 1)
    EXPECT_LT((g.grad_N[0] + g.grad_N[1] + g.grad_N[2] + g.grad_N[3]).norm(), 1e-14 * G_scale);
    // Nodal interpolation: L_a(X_b) = δ_ab, and linear completeness Σ_a X_a ⊗ Grad N_a = I.
    Mat3d completeness = Mat3d::Zero();
    for (int a = 0; a < 4; ++a) {
      completeness += X[a] * g.grad_N[a].transpose();
      const auto L = barycentric(g, X, X[a]);
      for (int b = 0; b < 4; ++b) EXPECT_NEAR(L[b], a == b ? 1.0 : 0.0, 1e-13);
    }
    EXPECT_LT((completeness - Mat3d::Identity()).norm(), 1e-13);
    // Longest edge
    double longest = 0.0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < a; ++b) longest = std::max(longest, (X[a] - X[b]).norm());
    EXPECT_DOUBLE_EQ(g.size, longest);
  }
}

TEST(TetGeometry, PartitionOfUnityAtRandomPoints) {
  const auto X = test::random_tet(11);
  const TetGeometry g = compute_tet_geometry(X);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int n = 0; n < 20; ++n) {
    const Vec3d P = X[0] + Vec3d(u(rng), u(rng), u(rng));
    const auto L = barycentric(g, X, P);
    EXPECT_NEAR(L[0] + L[1] + L[2] + L[3], 1.0, 1e-13);
    Vec3d reproduced = Vec3d::Zero();  // Σ_a N_a(P) X_a = P
    for (int a = 0; a < 4; ++a) reproduced += L[a] * X[a];
    EXPECT_LT((reproduced - P).norm(), 1e-12 * X[0].norm());
  }
  for (int q = 0; q < kQuadPoints; ++q) {
    const auto& L = kQuadrature.points[q];
    EXPECT_NEAR(L[0] + L[1] + L[2] + L[3], 1.0, 1e-15);
  }
}

TEST(Bubble, ValueAndGradient) {
  const auto X = test::random_tet(4);
  const TetGeometry g = compute_tet_geometry(X);
  EXPECT_DOUBLE_EQ(bubble_value({0.25, 0.25, 0.25, 0.25}), 1.0);
  EXPECT_EQ(bubble_value({0.0, 0.3, 0.3, 0.4}), 0.0);  // zero on the face L_0 = 0
  // Gradient at each quadrature point against central differences of N_b(L(X)).
  const double h = 1e-6 * g.size;
  for (int q = 0; q < kQuadPoints; ++q) {
    Vec3d Xq = Vec3d::Zero();
    for (int a = 0; a < 4; ++a) Xq += kQuadrature.points[q][a] * X[a];
    Vec3d fd;
    for (int i = 0; i < 3; ++i) {
      const Vec3d e = h * Vec3d::Unit(i);
      fd(i) = (bubble_value(barycentric(g, X, Xq + e)) - bubble_value(barycentric(g, X, Xq - e))) /
              (2 * h);
    }
    EXPECT_LT((fd - g.grad_bubble[q]).norm(), 1e-8 * g.grad_bubble[q].norm()) << "point " << q;
  }
}

TEST(Bubble, IntegralsThatTheElementRelies) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const TetGeometry g = compute_tet_geometry(test::random_tet(seed));
    double g_scale = 0.0;
    for (const Vec3d& gb : g.grad_bubble) g_scale = std::max(g_scale, gb.norm());
    // ∫ Grad N_b dV = 0 (symmetric rule): homogeneous states do not load the bubble (Q2).
    Vec3d integral = Vec3d::Zero();
    for (int q = 0; q < kQuadPoints; ++q) integral += g.weight[q] * g.grad_bubble[q];
    EXPECT_LT(integral.norm(), 1e-14 * g.volume * g_scale);
    // Pressure-bubble coupling (Q3). Exactly, ∫ N_a Grad N_b dV = -Grad N_a ∫ N_b dV
    // = -(32/105) V Grad N_a (degree 4). Any symmetric rule keeps its direction, with another
    // factor: for the 4-point rule, 64 β² (α - β)² = 8 (3 - √5) / 25 ≈ 0.2445 instead of 0.3048.
    for (int a = 0; a < 4; ++a) {
      Vec3d coupling = Vec3d::Zero();
      for (int q = 0; q < kQuadPoints; ++q)
        coupling += g.weight[q] * kQuadrature.points[q][a] * g.grad_bubble[q];
      const Vec3d exact = -8.0 * (3.0 - std::sqrt(5.0)) / 25.0 * g.volume * g.grad_N[a];
      EXPECT_LT((coupling - exact).norm(), 1e-13 * exact.norm()) << "node " << a;
    }
  }
}

TEST(TetGeometry, RejectsInvertedAndDegenerateElements) {
  auto X = test::random_tet(2);
  std::swap(X[1], X[2]);  // negative orientation
  EXPECT_THROW(compute_tet_geometry(X), Error);
  X[3] = X[0] + 0.5 * (X[1] - X[0]) + 0.5 * (X[2] - X[0]);  // flat
  EXPECT_THROW(compute_tet_geometry(X), Error);
}

}  // namespace
}  // namespace plisse::mini
