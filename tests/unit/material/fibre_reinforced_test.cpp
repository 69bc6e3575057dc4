// The fibre-reinforced model (material/fibre_reinforced.hpp; Holzapfel, Gasser & Ogden 2000)
// against closed forms in incompressible uniaxial tension: pulled along its fibre family, the
// Cauchy stress difference is the matrix's 2 c1 (λ² - 1/λ) plus the fibre's 2 ψ'(Ī4) λ² with
// Ī4 = λ² (σ_f = 2 ψ' (F a) ⊗ (F a) up to the pressure); pulled across it, the fibre shortens
// (Ī4 = 1/λ < 1) and carries nothing. Two families at ±θ to the pull share it symmetrically.
// The derivative identities (P = dW/dF, A = dP/dF by differences and dual numbers, frame
// indifference) are in model_identities_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "material/registry.hpp"

namespace plisse {
namespace {

Mat3d cauchy(const FibreReinforced& m, const Mat3d& F) {
  return m.evaluate(F).P * F.transpose() / F.determinant();
}

double fibre_d1(double k1, double k2, double I4) {  // ψ'(Ī4)
  const double x = I4 - 1.0;
  return x > 0.0 ? k1 * x * std::exp(k2 * x * x) : 0.0;
}

TEST(FibreReinforced, UniaxialTensionAlongAndAcrossTheFibresMatchesClosedForms) {
  const double c1 = 0.2, k1 = 1.5, k2 = 0.3;
  const FibreReinforced along{c1, k1, k2, 0.0, 0.0, 2.0};  // fibre along z, not normalised
  const FibreReinforced across{c1, k1, k2, 1.0, 0.0, 0.0};
  for (const double l : {0.7, 1.05, 1.3, 2.0, 3.0}) {
    const Mat3d F = Vec3d(1 / std::sqrt(l), 1 / std::sqrt(l), l).asDiagonal();
    const double matrix = 2 * c1 * (l * l - 1 / l);
    const double fibre = 2 * fibre_d1(k1, k2, l * l) * l * l;
    const Mat3d s = cauchy(along, F);
    EXPECT_NEAR(s(2, 2) - s(0, 0), matrix + fibre, 1e-12 * std::abs(matrix + fibre)) << l;
    EXPECT_NEAR(s(1, 1), s(0, 0), 1e-12 * std::abs(matrix + fibre)) << l;
    // Across: the fibre along x has Ī4 = 1/λ, stretched only in compression (λ < 1), where
    // σxx - σyy = 2 ψ'(1/λ) / λ.
    const Mat3d t = cauchy(across, F);
    EXPECT_NEAR(t(2, 2) - t(1, 1), matrix, 1e-12 * std::abs(matrix)) << l;
    const double lateral = 2 * fibre_d1(k1, k2, 1 / l) / l;
    EXPECT_NEAR(t(0, 0) - t(1, 1), lateral, 1e-12 * std::abs(matrix)) << l;
  }
}

// Two families in the x-z plane at ±θ from z, pulled along z (F = diag(λ^-1/2, λ^-1/2, λ)):
// each has Ī4 = λ² cos²θ + sin²θ / λ, and the pair adds 2 ψ' (F a)(F a)ᵀ twice, whose zz - yy
// difference is 4 ψ' λ² cos²θ and whose shear σxz cancels between the families.
TEST(FibreReinforced, TwoSymmetricFamiliesShareTheLoadWithoutShear) {
  const double c1 = 0.2, k1 = 1.5, k2 = 0.3, theta = 0.4;
  const FibreReinforced m{
      c1, k1, k2, std::sin(theta), 0.0, std::cos(theta), -std::sin(theta), 0.0, std::cos(theta)};
  for (const double l : {1.1, 1.6, 2.5}) {
    const Mat3d F = Vec3d(1 / std::sqrt(l), 1 / std::sqrt(l), l).asDiagonal();
    const double c = std::cos(theta), sn = std::sin(theta);
    const double I4 = l * l * c * c + sn * sn / l;
    const double expected = 2 * c1 * (l * l - 1 / l) + 4 * fibre_d1(k1, k2, I4) * l * l * c * c;
    const Mat3d s = cauchy(m, F);
    EXPECT_NEAR(s(2, 2) - s(1, 1), expected, 1e-12 * expected) << l;
    EXPECT_NEAR(s(0, 2), 0.0, 1e-12 * expected) << l;
  }
}

TEST(FibreReinforced, QuadraticLimitAndRegistryRules) {
  // k2 = 0: ψ = k1 (Ī4 - 1)² / 2, so ψ' = k1 (Ī4 - 1) and the along-fibre stress is exact too.
  const FibreReinforced m{0.2, 1.5, 0.0, 0.0, 0.0, 1.0};
  const double l = 1.4;
  const Mat3d F = Vec3d(1 / std::sqrt(l), 1 / std::sqrt(l), l).asDiagonal();
  const double expected = 2 * 0.2 * (l * l - 1 / l) + 2 * 1.5 * (l * l - 1) * l * l;
  const Mat3d s = cauchy(m, F);
  EXPECT_NEAR(s(2, 2) - s(0, 0), expected, 1e-12 * expected);
  const double W = 0.2 * (l * l + 2 / l - 3) + 0.5 * 1.5 * (l * l - 1) * (l * l - 1);
  EXPECT_NEAR(m.evaluate(F).W, W, 1e-12 * W);
  EXPECT_NEAR(m.energy_density(F), W, 1e-12 * W);
  const auto broken = validate_material("fibre-reinforced", {{"c1", 0.2}, {"k1", 1.0}});
  ASSERT_EQ(broken.size(), 1u);
  EXPECT_EQ(broken[0].key, "a1_x");
  EXPECT_TRUE(
      validate_material("fibre-reinforced", {{"c1", 0.2}, {"k1", 1.0}, {"a1_y", 1.0}}).empty());
  EXPECT_FALSE(find_material_model("fibre-reinforced")->isotropic);
  EXPECT_TRUE(find_material_model("ogden")->isotropic);
}

}  // namespace
}  // namespace plisse
