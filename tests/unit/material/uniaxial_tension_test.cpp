// Incompressible uniaxial tension F = diag(λ^-1/2, λ^-1/2, λ): the Cauchy stress difference
// σ_zz - σ_xx (σ = P Fᵀ / J) against closed forms, from compression (λ = 0.5) up to the cube test's
// stretch 5. The pressure only adds to the diagonal equally, so the difference is the material's.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "material/registry.hpp"

namespace plisse {
namespace {

constexpr std::array<double, 7> kStretches = {0.5, 0.8, 1.05, 1.5, 2.0, 3.5, 5.0};

template <class Model>
double stress_difference(const Model& model, double l) {
  const Mat3d F = Vec3d(1.0 / std::sqrt(l), 1.0 / std::sqrt(l), l).asDiagonal();
  const Mat3d sigma = model.evaluate(F).P * F.transpose() / F.determinant();
  return sigma(2, 2) - sigma(0, 0);
}

double I1_uniaxial(double l) { return l * l + 2.0 / l; }

TEST(UniaxialTension, NeoHookeanMatchesPaperClosedForm) {
  const NeoHookean m{0.0033};
  for (const double l : kStretches) {
    const double expected =
        2 * m.c1 * (l * l - 1 / l);  // paper, Table 1 with B = diag(1/λ, 1/λ, λ²)
    EXPECT_NEAR(stress_difference(m, l), expected, 1e-12 * std::abs(expected)) << "λ = " << l;
  }
}

TEST(UniaxialTension, MooneyRivlinMatchesPaperEquation7) {
  const MooneyRivlin m{0.0030, 0.0007};
  for (const double l : kStretches) {
    const double expected =
        2 * m.c1 * (l * l - 1 / l) - 2 * m.c2 * (1 / (l * l) - l);  // eq. 7, L/L0 = λ
    EXPECT_NEAR(stress_difference(m, l), expected, 1e-12 * std::abs(expected)) << "λ = " << l;
  }
}

TEST(UniaxialTension, FungMatchesPaperClosedForm) {
  const Fung m{0.0066, 0.3};
  for (const double l : kStretches) {
    const double expected = m.mu * std::exp(m.gamma * (I1_uniaxial(l) - 3)) * (l * l - 1 / l);
    EXPECT_NEAR(stress_difference(m, l), expected, 1e-12 * std::abs(expected)) << "λ = " << l;
  }
}

// For the other models, 2 (λ² - 1/λ)(W_1 + W_2/λ) (materials.md, M14) with W_1 written out here.
TEST(UniaxialTension, YeohGentArrudaBoyceMatchClosedForms) {
  const Yeoh yeoh{0.5, -0.05, 0.01};
  const Gent gent{1.2, 60.0};
  const ArrudaBoyce ab{0.9, 3.0};
  for (const double l : kStretches) {
    const double x = I1_uniaxial(l) - 3, g = l * l - 1 / l;
    const double e_yeoh = 2 * g * (yeoh.c1 + 2 * yeoh.c2 * x + 3 * yeoh.c3 * x * x);
    const double e_gent = g * gent.mu / (1 - x / gent.jm);
    const double I1 = I1_uniaxial(l), b = 1 / (ab.lambda_m * ab.lambda_m);
    const double e_ab =
        2 * g * ab.mu *
        (1.0 / 2 + 2.0 / 20 * b * I1 + 3 * 11.0 / 1050 * b * b * I1 * I1 +
         4 * 19.0 / 7000 * std::pow(b * I1, 3) + 5 * 519.0 / 673750 * std::pow(b * I1, 4));
    EXPECT_NEAR(stress_difference(yeoh, l), e_yeoh, 1e-12 * std::abs(e_yeoh)) << "λ = " << l;
    EXPECT_NEAR(stress_difference(gent, l), e_gent, 1e-12 * std::abs(e_gent)) << "λ = " << l;
    EXPECT_NEAR(stress_difference(ab, l), e_ab, 1e-12 * std::abs(e_ab)) << "λ = " << l;
  }
}

// The lateral faces are traction free: σ_xx = σ_yy exactly by symmetry of the deformation.
TEST(UniaxialTension, LateralStressesAreEqual) {
  const MooneyRivlin m{0.0030, 0.0007};
  const Mat3d F = Vec3d(1 / std::sqrt(5.0), 1 / std::sqrt(5.0), 5.0).asDiagonal();
  const Mat3d sigma = m.evaluate(F).P * F.transpose();
  EXPECT_NEAR(sigma(0, 0), sigma(1, 1), 1e-15 * sigma.norm());
  EXPECT_NEAR(sigma(0, 1), 0.0, 1e-15 * sigma.norm());
}

}  // namespace
}  // namespace plisse
