// The 6-node boundary face (docs/theory/loads.md, L7-L9; cavities.md, C12-C13): the degree-4
// triangle rule against the exact moments of every monomial of degree <= 4, the consistent
// pressure load of a flat face, the resultant of a curved face against its vector area (a
// boundary line integral), the load stiffness and the cone-volume gradient against central
// differences, and the cone volume against an independent product Gauss rule.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "physics/cavity_volume.hpp"
#include "physics/follower_pressure.hpp"
#include "physics/quadratic_triangle.hpp"
#include "physics/triangle_quadrature.hpp"

namespace plisse {
namespace {

using Nodes = std::array<Vec3d, 6>;

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

TEST(TriangleRule, IntegratesEveryMonomialOfDegreeFourExactly) {
  double sum = 0.0;
  for (const auto& p : kTriangleRuleDegree4) {
    EXPECT_GT(p.weight, 0.0);
    EXPECT_NEAR(p.L[0] + p.L[1] + p.L[2], 1.0, 1e-16);
    sum += p.weight;
  }
  EXPECT_NEAR(sum, 1.0, 1e-15);
  // Mean over the triangle of L0^i L1^j L2^k = 2 i! j! k! / (i + j + k + 2)!.
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; i + j <= 4; ++j)
      for (int k = 0; i + j + k <= 4; ++k) {
        double rule = 0.0;
        for (const auto& p : kTriangleRuleDegree4)
          rule += p.weight * std::pow(p.L[0], i) * std::pow(p.L[1], j) * std::pow(p.L[2], k);
        const double exact =
            2.0 * factorial(i) * factorial(j) * factorial(k) / factorial(i + j + k + 2);
        EXPECT_NEAR(rule, exact, 1e-15) << i << " " << j << " " << k;
      }
  // Degree 5 is not exact: the rule has exactly the degree it claims.
  double rule = 0.0;
  for (const auto& p : kTriangleRuleDegree4) rule += p.weight * std::pow(p.L[0], 5);
  EXPECT_GT(std::abs(rule - 2.0 * factorial(5) / factorial(7)), 1e-6);
}

TEST(QuadraticTriangle, ShapeFunctionsAreNodalAndTheirDerivativesMatchDifferences) {
  const std::array<std::array<double, 3>, 6> at = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}}};
  for (int b = 0; b < 6; ++b) {
    const auto N = quadratic_triangle::shape_values(at[b]);
    for (int a = 0; a < 6; ++a) EXPECT_EQ(N[a], a == b ? 1.0 : 0.0);
  }
  const std::array<double, 3> L = {0.2, 0.3, 0.5};
  const auto d = quadratic_triangle::shape_derivatives(L);
  const double h = 1e-6;
  const auto shift = [&](double dxi, double deta) {
    return quadratic_triangle::shape_values({L[0] - dxi - deta, L[1] + dxi, L[2] + deta});
  };
  const auto xp = shift(h, 0), xm = shift(-h, 0), ep = shift(0, h), em = shift(0, -h);
  for (int a = 0; a < 6; ++a) {
    EXPECT_NEAR(d[0][a], (xp[a] - xm[a]) / (2 * h), 1e-9);
    EXPECT_NEAR(d[1][a], (ep[a] - em[a]) / (2 * h), 1e-9);
  }
}

/// A flat triangle in a tilted plane with its edge nodes at the midpoints.
Nodes flat_face() {
  const Vec3d x0(0.3, -0.2, 1.0), x1(2.1, 0.4, 1.5), x2(0.7, 1.9, 0.2);
  return {x0, x1, x2, 0.5 * (x0 + x1), 0.5 * (x1 + x2), 0.5 * (x2 + x0)};
}

/// flat_face with its edge nodes moved off the plane (and along it): a curved face.
Nodes curved_face() {
  Nodes xs = flat_face();
  xs[3] += Vec3d(0.1, -0.2, 0.35);
  xs[4] += Vec3d(-0.15, 0.05, 0.25);
  xs[5] += Vec3d(0.05, 0.1, -0.3);
  return xs;
}

TEST(FollowerPressure6, FlatFaceGetsTheConsistentLoadNothingOnTheCorners) {
  const Nodes xs = flat_face();
  const double p = 0.37;
  const std::array<int, 18> dofs = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17};
  std::vector<double> r(18, 0.0);
  add_follower_pressure_residual(p, xs, dofs, r);
  // Analytic consistent load of a uniform pressure on a flat 6-node triangle with straight edges:
  // ∫ N_a dA = 0 at the corners and A/3 at the edge nodes, so r_a = p A n (0 or 1/3), with
  // A n = c / 2, c = (x1 - x0) x (x2 - x0).
  const Vec3d area_vector = 0.5 * (xs[1] - xs[0]).cross(xs[2] - xs[0]);
  for (int a = 0; a < 6; ++a) {
    const Vec3d expected = a < 3 ? Vec3d::Zero() : Vec3d(p * area_vector / 3.0);
    const Vec3d got(r[3 * a], r[3 * a + 1], r[3 * a + 2]);
    EXPECT_LT((got - expected).norm(), 1e-15 * p * area_vector.norm()) << "node " << a;
  }
}

/// The vector area ∫ (x_ξ × x_η) dξ dη of a face as (1/2) ∮ x × dx over its three quadratic
/// edges (Stokes), each integrated by 3-point Gauss-Legendre (the integrand x × x' is cubic).
Vec3d vector_area_from_boundary(const Nodes& xs) {
  const std::array<double, 3> s = {0.5 - std::sqrt(0.15), 0.5, 0.5 + std::sqrt(0.15)};
  const std::array<double, 3> w = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  const int ends[3][3] = {{0, 3, 1}, {1, 4, 2}, {2, 5, 0}};  // start, middle, end
  Vec3d sum = Vec3d::Zero();
  for (const auto& e : ends) {
    const Vec3d &a = xs[e[0]], &m = xs[e[1]], &b = xs[e[2]];
    for (int q = 0; q < 3; ++q) {
      const double t = s[q];
      const Vec3d x = (1 - t) * (1 - 2 * t) * a + 4 * t * (1 - t) * m + t * (2 * t - 1) * b;
      const Vec3d dx = (4 * t - 3) * a + (4 - 8 * t) * m + (4 * t - 1) * b;
      sum += w[q] * x.cross(dx);
    }
  }
  return 0.5 * sum;
}

TEST(FollowerPressure6, CurvedFaceResultantIsPressureTimesItsVectorArea) {
  const Nodes xs = curved_face();
  const double p = 0.8;
  std::array<int, 18> dofs;
  for (int i = 0; i < 18; ++i) dofs[i] = i;
  std::vector<double> r(18, 0.0);
  add_follower_pressure_residual(p, xs, dofs, r);
  Vec3d resultant = Vec3d::Zero();
  for (int a = 0; a < 6; ++a) resultant += Vec3d(r[3 * a], r[3 * a + 1], r[3 * a + 2]);
  const Vec3d exact = p * vector_area_from_boundary(xs);
  EXPECT_LT((resultant - exact).norm(), 1e-14 * exact.norm());
  // The curvature matters: the flat face's vector area differs.
  EXPECT_GT((exact - p * vector_area_from_boundary(flat_face())).norm(), 1e-2 * exact.norm());
}

Nodes perturbed(Nodes xs, int j, double h) {
  xs[j / 3][j % 3] += h;
  return xs;
}

TEST(FollowerPressure6, LoadStiffnessIsTheDerivativeOfTheResidual) {
  const Nodes xs = curved_face();
  const double p = 1.3;
  std::array<int, 18> dofs;
  for (int i = 0; i < 18; ++i) dofs[i] = i;
  Eigen::Matrix<double, 18, 18, Eigen::RowMajor> k;
  follower_pressure_stiffness(p, xs, k);
  const double h = 1e-6;
  double worst = 0.0;
  for (int j = 0; j < 18; ++j) {
    std::vector<double> rp(18, 0.0), rm(18, 0.0);
    add_follower_pressure_residual(p, perturbed(xs, j, h), dofs, rp);
    add_follower_pressure_residual(p, perturbed(xs, j, -h), dofs, rm);
    for (int i = 0; i < 18; ++i)
      worst = std::max(worst, std::abs((rp[i] - rm[i]) / (2 * h) - k(i, j)));
  }
  EXPECT_LT(worst, 1e-7 * k.cwiseAbs().maxCoeff());
  // On one face the load stiffness is not symmetric (only the assembled closed surface is, L4).
  EXPECT_GT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-3 * k.cwiseAbs().maxCoeff());
}

/// (1/3) ∫ x · (x_ξ × x_η) dξ dη by a Duffy-collapsed 8 x 8 Gauss-Legendre product rule
/// (exact for polynomials of degree <= 14 on the triangle), independent of the triangle rule.
double cone_volume_by_product_rule(const Nodes& xs) {
  const std::array<double, 8> t = {0.019855071751231884158, 0.1016667612931866302,
                                   0.23723379504183550709,  0.40828267875217509753,
                                   0.59171732124782490247,  0.76276620495816449291,
                                   0.8983332387068133698,   0.98014492824876811584};
  const std::array<double, 8> w = {0.050614268145188129576, 0.11119051722668723527,
                                   0.15685332293894364367,  0.18134189168918099148,
                                   0.18134189168918099148,  0.15685332293894364367,
                                   0.11119051722668723527,  0.050614268145188129576};
  double sum = 0.0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const double xi = t[i], eta = t[j] * (1.0 - t[i]);  // dξ dη = (1 - u) du dv
      const std::array<double, 3> L = {1.0 - xi - eta, xi, eta};
      const auto N = quadratic_triangle::shape_values(L);
      const auto d = quadratic_triangle::shape_derivatives(L);
      Vec3d x = Vec3d::Zero(), x_xi = Vec3d::Zero(), x_eta = Vec3d::Zero();
      for (int a = 0; a < 6; ++a) {
        x += N[a] * xs[a];
        x_xi += d[0][a] * xs[a];
        x_eta += d[1][a] * xs[a];
      }
      sum += w[i] * w[j] * (1.0 - t[i]) * x.dot(x_xi.cross(x_eta));
    }
  return sum / 3.0;
}

TEST(QuadraticConeVolume, MatchesAnIndependentRuleAndTheFlatFormula) {
  const Nodes flat = flat_face();
  EXPECT_NEAR(quadratic_cone_volume(flat), flat[0].dot(flat[1].cross(flat[2])) / 6.0, 1e-15);
  const Nodes xs = curved_face();
  const double independent = cone_volume_by_product_rule(xs);
  EXPECT_NEAR(quadratic_cone_volume(xs), independent, 1e-13 * std::abs(independent));
  EXPECT_GT(std::abs(independent - quadratic_cone_volume(flat)), 1e-2 * std::abs(independent));
}

TEST(QuadraticConeVolume, GradientIsTheDerivativeOfTheVolume) {
  const Nodes xs = curved_face();
  const auto g = quadratic_cone_volume_gradient(xs);
  const double h = 1e-6;
  double worst = 0.0, scale = 0.0;
  for (int j = 0; j < 18; ++j) {
    const double fd =
        (quadratic_cone_volume(perturbed(xs, j, h)) - quadratic_cone_volume(perturbed(xs, j, -h))) /
        (2 * h);
    worst = std::max(worst, std::abs(fd - g[j / 3][j % 3]));
    scale = std::max(scale, std::abs(g[j / 3][j % 3]));
  }
  EXPECT_LT(worst, 1e-8 * scale);
  // Euler's theorem for a homogeneous cubic: Σ x_a · dV/dx_a = 3 V.
  double euler = 0.0;
  for (int a = 0; a < 6; ++a) euler += xs[a].dot(g[a]);
  EXPECT_NEAR(euler, 3.0 * quadratic_cone_volume(xs), 1e-13 * std::abs(euler));
}

}  // namespace
}  // namespace plisse
