// Quadrature rules of the element folder: weights, symmetry and exactness of the stated degree on a
// distorted tetrahedron, against exact integrals computed in barycentric monomials.
#include "element/quadrature.hpp"

#include <gtest/gtest.h>

#include <map>

#include "element/bubble.hpp"
#include "element/tet_geometry.hpp"
#include "element_test_support.hpp"

namespace plisse {
namespace {

using Exponents = std::array<int, 4>;
using BarycentricPolynomial = std::map<Exponents, double>;

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

/// ∫_T L0^a L1^b L2^c L3^d dV = a! b! c! d! 3! V / (a + b + c + d + 3)!
double integrate_exact(const BarycentricPolynomial& poly, double volume) {
  double sum = 0.0;
  for (const auto& [e, coefficient] : poly)
    sum += coefficient * factorial(e[0]) * factorial(e[1]) * factorial(e[2]) * factorial(e[3]) *
           6.0 * volume / factorial(e[0] + e[1] + e[2] + e[3] + 3);
  return sum;
}

/// x^i y^j z^k on the tetrahedron X as a homogeneous polynomial in L (x = Σ_a L_a X_a).
BarycentricPolynomial monomial_in_barycentric(const std::array<Vec3d, 4>& X, int i, int j, int k) {
  BarycentricPolynomial poly{{{0, 0, 0, 0}, 1.0}};
  auto multiply_by_coordinate = [&](int axis) {
    BarycentricPolynomial next;
    for (const auto& [e, c] : poly)
      for (int a = 0; a < 4; ++a) {
        Exponents f = e;
        ++f[a];
        next[f] += c * X[a](axis);
      }
    poly = next;
  };
  for (int n = 0; n < i; ++n) multiply_by_coordinate(0);
  for (int n = 0; n < j; ++n) multiply_by_coordinate(1);
  for (int n = 0; n < k; ++n) multiply_by_coordinate(2);
  return poly;
}

template <int N>
double integrate_rule(const TetQuadrature<N>& rule, const std::array<Vec3d, 4>& X, double volume,
                      int i, int j, int k) {
  double sum = 0.0;
  for (int q = 0; q < N; ++q) {
    Vec3d x = Vec3d::Zero();
    for (int a = 0; a < 4; ++a) x += rule.points[q][a] * X[a];
    sum += rule.weights[q] * std::pow(x(0), i) * std::pow(x(1), j) * std::pow(x(2), k);
  }
  return volume * sum;
}

/// Largest error over all monomials of total degree `degree`, relative to V max|x|^degree.
template <int N>
double worst_error_of_degree(const TetQuadrature<N>& rule, int degree) {
  const std::array<Vec3d, 4> X = test::random_tet(7, 1.0);
  const double volume = (X[1] - X[0]).cross(X[2] - X[0]).dot(X[3] - X[0]) / 6.0;
  double extent = 0.0;
  for (const Vec3d& x : X) extent = std::max(extent, x.cwiseAbs().maxCoeff());
  double worst = 0.0;
  for (int i = 0; i <= degree; ++i)
    for (int j = 0; i + j <= degree; ++j) {
      const int k = degree - i - j;
      const double exact = integrate_exact(monomial_in_barycentric(X, i, j, k), volume);
      const double approx = integrate_rule(rule, X, volume, i, j, k);
      worst = std::max(worst, std::abs(approx - exact) / (volume * std::pow(extent, degree)));
    }
  return worst;
}

template <int N>
void expect_valid_rule(const TetQuadrature<N>& rule) {
  double weight_sum = 0.0;
  for (int q = 0; q < N; ++q) {
    EXPECT_GT(rule.weights[q], 0.0);
    weight_sum += rule.weights[q];
    double coordinate_sum = 0.0;
    for (double L : rule.points[q]) {
      EXPECT_GT(L, 0.0);  // strictly inside: the bubble is not wasted on zeros
      coordinate_sum += L;
    }
    EXPECT_NEAR(coordinate_sum, 1.0, 1e-15);
  }
  EXPECT_NEAR(weight_sum, 1.0, 1e-15);
  // Full S4 symmetry: the transpositions (0 1), (1 2), (2 3) generate S4; each must map the
  // point set onto itself with equal weights.
  for (int t = 0; t < 3; ++t)
    for (int q = 0; q < N; ++q) {
      std::array<double, 4> swapped = rule.points[q];
      std::swap(swapped[t], swapped[t + 1]);
      bool found = false;
      for (int r = 0; r < N; ++r) {
        double d = 0.0;
        for (int a = 0; a < 4; ++a) d += std::abs(rule.points[r][a] - swapped[a]);
        found = found || (d < 1e-15 && rule.weights[r] == rule.weights[q]);
      }
      EXPECT_TRUE(found) << "point " << q << ", transposition " << t;
    }
}

TEST(TetQuadrature, Degree2RuleIsValidAndExactToDegree2) {
  expect_valid_rule(kTetQuadratureDegree2);
  for (int d = 0; d <= 2; ++d) EXPECT_LT(worst_error_of_degree(kTetQuadratureDegree2, d), 1e-13);
  EXPECT_GT(worst_error_of_degree(kTetQuadratureDegree2, 3), 1e-9);  // the degree is sharp
}

TEST(TetQuadrature, Degree5RuleIsValidAndExactToDegree5) {
  expect_valid_rule(kTetQuadratureDegree5);
  for (int d = 0; d <= 5; ++d) EXPECT_LT(worst_error_of_degree(kTetQuadratureDegree5, d), 1e-13);
  EXPECT_GT(worst_error_of_degree(kTetQuadratureDegree5, 6), 1e-9);  // the degree is sharp
}

/// Σ_q w_q N_a(q) Grad N_b(q) with the given rule, for node a of the tetrahedron X.
template <int N>
Vec3d pressure_bubble_coupling(const TetQuadrature<N>& rule, const mini::TetGeometry& g, int a) {
  Vec3d sum = Vec3d::Zero();
  for (int q = 0; q < N; ++q)
    sum += rule.weights[q] * g.volume * rule.points[q][a] *
           mini::bubble_gradient(rule.points[q], g.grad_N);
  return sum;
}

TEST(TetQuadrature, PressureBubbleCouplingOfEachRule) {
  // Exactly ∫ N_a Grad N_b dV = -(32/105) V Grad N_a (degree 4): the degree-5 rule reproduces it;
  // the degree-2 rule of the MINI kernel gives the same direction with factor 8 (3 - √5) / 25
  // (docs/theory/mixed_up.md, Q3).
  const mini::TetGeometry g = mini::compute_tet_geometry(test::random_tet(3));
  for (int a = 0; a < 4; ++a) {
    const Vec3d exact = -32.0 / 105.0 * g.volume * g.grad_N[a];
    const Vec3d degree2 = -8.0 * (3.0 - std::sqrt(5.0)) / 25.0 * g.volume * g.grad_N[a];
    EXPECT_LT((pressure_bubble_coupling(kTetQuadratureDegree5, g, a) - exact).norm(),
              1e-13 * exact.norm());
    EXPECT_LT((pressure_bubble_coupling(kTetQuadratureDegree2, g, a) - degree2).norm(),
              1e-13 * exact.norm());
  }
}

}  // namespace
}  // namespace plisse
