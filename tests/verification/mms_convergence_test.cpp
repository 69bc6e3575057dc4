// Manufactured solutions on uniformly refined cubes (docs/verification/mms.md): the MINI element
// must converge at the optimal rates of P1 displacements and P1 pressures, the Taylor-Hood element
// at those of P2 displacements and P1 pressures, for exact and near incompressibility. Rates are
// asserted between the two finest levels, where the error is asymptotic; the expected values are
// 2, 1, >= 1 (MINI) and 3, 2, 2 (Taylor-Hood) for u in L2, u in H1 and p in L2.
#include <gtest/gtest.h>

#include <cmath>

#include "verification/mms_cases.hpp"
#include "verification/simplex_quadrature.hpp"

namespace plisse::test {
namespace {

TEST(CollapsedQuadrature, IsExactForTheDeclaredDegree) {
  // Reference simplices: ∫ ξ1^i ξ2^j dA = i! j! / (i + j + 2)!, ∫ ξ1^i ξ2^j ξ3^k dV =
  // i! j! k! / (i + j + k + 3)!; the rules weigh fractions of the measure (1/2, resp. 1/6).
  const auto factorial = [](int m) { return std::tgamma(m + 1.0); };
  for (int n = 2; n <= 4; ++n) {
    const SimplexRule<2> triangle = collapsed_triangle_rule(n);
    const SimplexRule<3> tet = collapsed_tet_rule(n);
    for (int i = 0; i <= 2 * n; ++i)
      for (int j = 0; i + j <= 2 * n - 2; ++j) {
        double sum = 0.0;
        for (std::size_t q = 0; q < triangle.points.size(); ++q)
          sum += triangle.weights[q] * std::pow(triangle.points[q][1], i) *
                 std::pow(triangle.points[q][2], j);
        const double exact = factorial(i) * factorial(j) / factorial(i + j + 2);
        EXPECT_NEAR(0.5 * sum, exact, 1e-14)
            << "triangle, n = " << n << ", i = " << i << ", j = " << j;
        for (int k = 0; i + j + k <= 2 * n - 3; ++k) {
          double tet_sum = 0.0;
          for (std::size_t q = 0; q < tet.points.size(); ++q)
            tet_sum += tet.weights[q] * std::pow(tet.points[q][1], i) *
                       std::pow(tet.points[q][2], j) * std::pow(tet.points[q][3], k);
          const double tet_exact =
              factorial(i) * factorial(j) * factorial(k) / factorial(i + j + k + 3);
          EXPECT_NEAR(tet_sum / 6.0, tet_exact, 1e-14) << "tet, n = " << n;
        }
      }
  }
}

TEST(ManufacturedSolution, BodyForceIsMinusDivergenceOfStress) {
  // The chain-rule divergence (mms.md, M7) against central differences of P itself: agreement to
  // the differences' own error O(δ²) shows that the sign and index conventions of A are right.
  for (const MmsProblem& problem :
       {exact_incompressible_neo_hookean(), near_incompressible_mooney_rivlin()}) {
    const Vec3d X(0.3, 0.7, 0.45);
    const double delta = 1e-4;
    Vec3d by_differences = Vec3d::Zero();
    for (int J = 0; J < 3; ++J) {
      const Vec3d dX = delta * Vec3d::Unit(J);
      by_differences +=
          (total_stress(problem, X + dX) - total_stress(problem, X - dX)).col(J) / (2 * delta);
    }
    const Vec3d chain = divergence_of_stress(problem, X);
    EXPECT_LT((chain - by_differences).norm(), 1e-6 * chain.norm()) << chain.transpose();
  }
}

TEST(ManufacturedSolution, ExactMapIsIsochoric) {
  const ManufacturedSolution s;  // epsilon = 0
  for (const Vec3d& X : {Vec3d(0.1, 0.2, 0.3), Vec3d(0.9, 0.5, 0.7), Vec3d(1.0, 1.0, 1.0)}) {
    EXPECT_NEAR(s.F(X).determinant(), 1.0, 1e-14);
    // F is the derivative of u: central differences, error O(δ²) ~ 1e-10.
    const double delta = 1e-5;
    for (int J = 0; J < 3; ++J) {
      const Vec3d dX = delta * Vec3d::Unit(J);
      const Vec3d column = (s.u(X + dX) - s.u(X - dX)) / (2 * delta);
      EXPECT_LT((column - s.grad_u(X).col(J)).norm(), 1e-9);
    }
  }
}

TEST(ManufacturedSolution, ExactIncompressibilityNeoHookeanConvergesOptimally) {
  expect_optimal_rates("MMS, neo-Hookean, exact incompressibility",
                       exact_incompressible_neo_hookean(), {4, 8, 16});
}

TEST(ManufacturedSolution, NearIncompressibilityMooneyRivlinConvergesOptimally) {
  expect_optimal_rates("MMS, Mooney-Rivlin, kappa = 100 mu", near_incompressible_mooney_rivlin(),
                       {4, 8, 16});
}

TEST(ManufacturedSolution, TaylorHoodExactIncompressibilityNeoHookeanConvergesOptimally) {
  expect_optimal_rates("MMS, Taylor-Hood, neo-Hookean, exact incompressibility",
                       with_taylor_hood(exact_incompressible_neo_hookean()), {2, 4, 8});
}

TEST(ManufacturedSolution, TaylorHoodNearIncompressibilityMooneyRivlinConvergesOptimally) {
  expect_optimal_rates("MMS, Taylor-Hood, Mooney-Rivlin, kappa = 100 mu",
                       with_taylor_hood(near_incompressible_mooney_rivlin()), {2, 4, 8});
}

}  // namespace
}  // namespace plisse::test
