// The Ogden model (material/ogden.hpp) where its spectral form needs care: against the invariant
// models it contains (α = 2 is neo-Hookean, α = ±2 Mooney-Rivlin) at deformations with distinct,
// two and three equal stretches; the tangent's continuity as two stretches meet; and the closed
// forms of Ogden (1972, section 4) for incompressible uniaxial, equibiaxial and planar tension and
// simple shear, with Ogden's fit to Treloar's data. Cauchy stresses σ = P Fᵀ / J of the isochoric
// part: the pressure adds to the diagonal only, so stress differences and shear stresses are the
// material's.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "material/registry.hpp"
#include "material_test_utils.hpp"

namespace plisse {
namespace {

const Ogden kTreloar{0.618, 1.3, 0.00118, 5.0, -0.00981, -2.0};  // MPa; Ogden (1972), Treloar fit

double max_abs(const auto& m) { return m.cwiseAbs().maxCoeff(); }

/// The test deformations plus exact ones with repeated stretches: two equal (equibiaxial and
/// uniaxial, along the axes), three equal with J ≠ 1, and the reference state.
std::vector<Mat3d> deformations_with_equal_stretches() {
  std::vector<Mat3d> out = test::test_deformations();
  out.push_back(Vec3d(2.0, 2.0, 0.25).asDiagonal());
  out.push_back(Vec3d(0.5, 4.0, 0.5).asDiagonal());
  out.push_back(1.3 * Mat3d::Identity());
  out.push_back(Mat3d::Identity());
  return out;
}

void expect_same_response(const PointResponse& a, const PointResponse& b, const Mat3d& F) {
  EXPECT_NEAR(a.W, b.W, 1e-13 * std::max(1.0, std::abs(b.W))) << "F =\n" << F;
  EXPECT_LE(max_abs(a.P - b.P), 1e-12 * std::max(1.0, max_abs(b.P))) << "F =\n" << F;
  EXPECT_LE(max_abs(a.A - b.A), 1e-12 * max_abs(b.A)) << "F =\n" << F;
}

TEST(Ogden, AlphaTwoIsNeoHookeanAtEveryDeformation) {
  const double c1 = 0.7;
  const Ogden ogden{2.0 * c1, 2.0};
  const NeoHookean neo{c1};
  for (const Mat3d& F : deformations_with_equal_stretches())
    expect_same_response(ogden.evaluate(F), neo.evaluate(F), F);
  EXPECT_DOUBLE_EQ(ogden.shear_modulus(), neo.shear_modulus());
}

// Σ λ̄_a^-2 = Ī2 for isochoric stretches (λ̄1 λ̄2 λ̄3 = 1), so μ1 = 2 c1, α1 = 2, μ2 = -2 c2,
// α2 = -2 gives c1 (Ī1 - 3) + c2 (Ī2 - 3).
TEST(Ogden, AlphaTwoAndMinusTwoIsMooneyRivlinAtEveryDeformation) {
  const double c1 = 0.6, c2 = 0.25;
  const Ogden ogden{2.0 * c1, 2.0, -2.0 * c2, -2.0};
  const MooneyRivlin mr{c1, c2};
  for (const Mat3d& F : deformations_with_equal_stretches())
    expect_same_response(ogden.evaluate(F), mr.evaluate(F), F);
  EXPECT_DOUBLE_EQ(ogden.shear_modulus(), mr.shear_modulus());
}

// Exact repeated stretches (diagonal F, so the eigenvalues of C coincide exactly): the tangent
// still equals the central differences of the stress, which split the stretches apart.
TEST(Ogden, TangentMatchesDifferencesWhereStretchesAreEqual) {
  for (const Mat3d& F : deformations_with_equal_stretches()) {
    const Mat9d A_fd = test::central_difference_tangent(kTreloar, F);
    const Mat9d A = kTreloar.evaluate(F).A;
    EXPECT_LT(max_abs(A_fd - A), 1e-6 * max_abs(A)) << "F =\n" << F;
  }
}

// Two stretches a relative δ apart: the tangent tends to the equal-stretch one linearly in δ
// down to δ = 1e-12, where a quotient (w_a - w_b) / (e_a - e_b) formed as written would have lost
// every digit.
TEST(Ogden, TangentIsContinuousAsStretchesMeet) {
  const Mat3d Q = test::random_rotation(5);
  for (const Vec3d& stretches : {Vec3d(1.7, 1.7, 1 / (1.7 * 1.7)), Vec3d(1.2, 1.2, 1.2)}) {
    const Mat3d F0 = Q * Mat3d(stretches.asDiagonal());
    const Mat9d A0 = kTreloar.evaluate(F0).A;
    for (const double delta : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
      Vec3d split = stretches;
      split(0) *= 1.0 + delta;
      const Mat9d A = kTreloar.evaluate(Q * Mat3d(split.asDiagonal())).A;
      EXPECT_LT(max_abs(A - A0), 10.0 * delta * max_abs(A0) + 1e-13 * max_abs(A0))
          << "stretches " << stretches.transpose() << ", δ = " << delta;
    }
  }
}

/// Σ_p μ_p (x^α_p - y^α_p): the difference of two principal Cauchy stresses of an isochoric
/// state with principal stretches x, y (Ogden 1972, eq. (4.4) without the pressure).
double principal_difference(const Ogden& m, double x, double y) {
  const Ogden::Terms t = m.terms();
  double s = 0.0;
  for (int p = 0; p < t.n; ++p) s += t.mu[p] * (std::pow(x, t.alpha[p]) - std::pow(y, t.alpha[p]));
  return s;
}

Mat3d cauchy(const Ogden& m, const Mat3d& F) {
  return m.evaluate(F).P * F.transpose() / F.determinant();
}

constexpr std::array<double, 7> kStretches = {0.5, 0.8, 1.05, 1.5, 2.0, 3.5, 5.0};

TEST(Ogden, UniaxialTensionMatchesClosedForm) {
  for (const double l : kStretches) {
    const Mat3d s = cauchy(kTreloar, Vec3d(1 / std::sqrt(l), 1 / std::sqrt(l), l).asDiagonal());
    const double expected = principal_difference(kTreloar, l, 1 / std::sqrt(l));
    EXPECT_NEAR(s(2, 2) - s(0, 0), expected, 1e-12 * std::abs(expected)) << "λ = " << l;
    EXPECT_NEAR(s(1, 1), s(0, 0), 1e-14 * std::abs(expected)) << "λ = " << l;
  }
}

TEST(Ogden, EquibiaxialTensionMatchesClosedForm) {
  for (const double l : kStretches) {
    const Mat3d s = cauchy(kTreloar, Vec3d(l, l, 1 / (l * l)).asDiagonal());
    const double expected = principal_difference(kTreloar, l, 1 / (l * l));
    EXPECT_NEAR(s(0, 0) - s(2, 2), expected, 1e-12 * std::abs(expected)) << "λ = " << l;
    EXPECT_NEAR(s(1, 1), s(0, 0), 1e-14 * std::abs(expected)) << "λ = " << l;
  }
}

// Planar (pure shear) tension F = diag(λ, 1, 1/λ): the transverse stress σ_yy is not zero.
TEST(Ogden, PlanarTensionMatchesClosedForm) {
  for (const double l : kStretches) {
    const Mat3d s = cauchy(kTreloar, Vec3d(l, 1.0, 1 / l).asDiagonal());
    const double axial = principal_difference(kTreloar, l, 1 / l);
    const double transverse = principal_difference(kTreloar, 1.0, 1 / l);
    EXPECT_NEAR(s(0, 0) - s(2, 2), axial, 1e-12 * std::abs(axial)) << "λ = " << l;
    EXPECT_NEAR(s(1, 1) - s(2, 2), transverse, 1e-12 * std::abs(axial)) << "λ = " << l;
  }
}

// Simple shear F = I + γ e_x ⊗ e_y: in-plane principal stretches λ1,2 = sqrt(1 + γ²/4) ± γ/2 on
// axes at θ with tan 2θ = 2/γ, so σ_xy = (σ1 - σ2) sin 2θ / 2 = Σ μ_p (λ1^α_p - λ2^α_p) / (λ1 +
// λ2); the energy is Σ μ_p / α_p (λ1^α_p + λ2^α_p - 2).
TEST(Ogden, SimpleShearMatchesClosedForm) {
  const Ogden::Terms t = kTreloar.terms();
  for (const double gamma : {0.01, 0.3, 1.0, 2.5, 5.0}) {
    Mat3d F = Mat3d::Identity();
    F(0, 1) = gamma;
    const double root = std::sqrt(1.0 + gamma * gamma / 4.0);
    const double l1 = root + gamma / 2.0, l2 = root - gamma / 2.0;
    const double expected = principal_difference(kTreloar, l1, l2) / (l1 + l2);
    const Mat3d s = cauchy(kTreloar, F);
    EXPECT_NEAR(s(0, 1), expected, 1e-12 * std::abs(expected)) << "γ = " << gamma;
    EXPECT_NEAR(s(1, 0), expected, 1e-12 * std::abs(expected)) << "γ = " << gamma;
    double W = 0.0;
    for (int p = 0; p < t.n; ++p)
      W += t.mu[p] / t.alpha[p] *
           (std::expm1(t.alpha[p] * std::log(l1)) + std::expm1(t.alpha[p] * std::log(l2)));
    // W ~ μ γ²/2 comes from stretches of order 1: both sides carry an absolute rounding error of
    // a few 1e-16 μ, which is 1e-11 of W at γ = 0.01.
    EXPECT_NEAR(kTreloar.evaluate(F).W, W, 1e-12 * W + 1e-14 * kTreloar.shear_modulus())
        << "γ = " << gamma;
  }
}

TEST(Ogden, RegistryRefusesTermsAgainstOgdensCondition) {
  EXPECT_TRUE(validate_material("ogden", {{"mu1", 0.618},
                                          {"alpha1", 1.3},
                                          {"mu2", 0.00118},
                                          {"alpha2", 5.0},
                                          {"mu3", -0.00981},
                                          {"alpha3", -2.0}})
                  .empty());
  EXPECT_TRUE(validate_material("ogden", {{"mu1", -0.5}, {"alpha1", -2.0}}).empty());
  const auto broken = validate_material("ogden", {{"mu1", 0.5}, {"alpha1", -2.0}});
  ASSERT_EQ(broken.size(), 1u);
  EXPECT_EQ(broken[0].key, "alpha1");
  EXPECT_NE(broken[0].rule.find("mu1 alpha1 must be > 0"), std::string::npos) << broken[0].rule;
  const auto half_term = validate_material("ogden", {{"mu1", 0.5}, {"alpha1", 2.0}, {"mu2", 0.1}});
  ASSERT_EQ(half_term.size(), 1u);
  EXPECT_EQ(half_term[0].key, "alpha2");
  EXPECT_NE(half_term[0].rule.find("or both 0"), std::string::npos) << half_term[0].rule;
  EXPECT_EQ(validate_material("ogden", {{"mu1", 0.5}}).size(), 1u);  // alpha1 required
  const AnyMaterial m = make_material("ogden", {{"mu1", 0.5}, {"alpha1", 3.0}});
  EXPECT_EQ(material_name(m), "ogden");
  EXPECT_DOUBLE_EQ(shear_modulus(m), 0.75);
}

}  // namespace
}  // namespace plisse
