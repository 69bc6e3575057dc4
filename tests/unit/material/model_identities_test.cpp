// Every model against the mechanics it must satisfy: P = dW/dF and A = dP/dF (finite differences
// with observed order 2, and dual numbers), frame indifference, isotropy, isochoric invariance,
// symmetric tangent, zero energy and stress in the reference state and the small-strain limit.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>  // after Eigen/Core, which it needs

#include "material/inadmissible_deformation.hpp"
#include "material/registry.hpp"
#include "material_test_utils.hpp"

namespace plisse {
namespace {

/// Test-only model with every invariant derivative non-zero (W_12, W_22 included), so the shared
/// response is checked on terms no production model uses yet.
struct CoupledTestModel {
  double c = 0.3, d = 0.2, a = 0.05, b = 0.02, e = 0.04;
  template <class T>
  T energy(const Mat3<T>& F) const {
    const IsochoricInvariants<T> inv = compute_isochoric_invariants(F);
    const T x = inv.I1bar - 3.0, y = inv.I2bar - 3.0;
    return c * x + d * y + a * x * y + b * y * y + e * x * x;
  }
  InvariantDerivatives invariant_derivatives(double I1bar, double I2bar) const {
    const double x = I1bar - 3.0, y = I2bar - 3.0;
    return {c * x + d * y + a * x * y + b * y * y + e * x * x,
            c + a * y + 2 * e * x,
            d + a * x + 2 * b * y,
            2 * e,
            a,
            2 * b};
  }
  PointResponse evaluate(const Mat3d& F) const { return evaluate_isochoric(*this, F); }
  double shear_modulus() const { return 2.0 * (c + d); }
};

template <class M>
M sample();
template <>
NeoHookean sample() {
  return {0.7};
}
template <>
MooneyRivlin sample() {
  return {0.6, 0.25};
}
template <>
Fung sample() {
  return {1.1, 0.4};
}
template <>
Yeoh sample() {
  return {0.5, -0.05, 0.01};
}
template <>
Gent sample() {
  return {1.2, 60.0};
}
template <>
ArrudaBoyce sample() {
  return {0.9, 3.0};
}
template <>
Ogden sample() {  // Ogden's 1972 fit to Treloar's data (MPa): three terms, one with negative α
  return {0.618, 1.3, 0.00118, 5.0, -0.00981, -2.0};
}
template <>
FibreReinforced sample() {
  // Two families, not unit vectors (normalised by the model). k2 small enough that central
  // differences stay accurate where the uniaxial stretch 5 of the test deformations stretches a
  // fibre 25-fold in Ī4 (exp(k2 (Ī4 - 1)²) = 3e12 there).
  return {0.4, 2.0, 0.05, 1.0, 0.3, 0.2, -0.2, 1.0, 0.5};
}
template <>
CoupledTestModel sample() {
  return {};
}

double max_abs(const auto& m) { return m.cwiseAbs().maxCoeff(); }

template <class M>
class ModelIdentities : public ::testing::Test {
 protected:
  const M model = sample<M>();
  double W(const Mat3d& F) const { return model.evaluate(F).W; }
  Mat3d P(const Mat3d& F) const { return model.evaluate(F).P; }
};
using Models = ::testing::Types<NeoHookean, MooneyRivlin, Fung, Yeoh, Gent, ArrudaBoyce, Ogden,
                                FibreReinforced, CoupledTestModel>;
TYPED_TEST_SUITE(ModelIdentities, Models);

TYPED_TEST(ModelIdentities, StressMatchesCentralDifferencesOfEnergy) {
  for (const Mat3d& F : test::test_deformations()) {
    const double h = 1e-5 * std::max(1.0, max_abs(F));
    Mat3d P_fd;
    for (int k = 0; k < 9; ++k) {
      Mat3d Fp = F, Fm = F;
      Fp.data()[k] += h;
      Fm.data()[k] -= h;
      P_fd.data()[k] = (this->W(Fp) - this->W(Fm)) / (2 * h);
    }
    const Mat3d P = this->P(F);
    EXPECT_LT(max_abs(P_fd - P), 1e-6 * max_abs(P)) << "F =\n" << F;
  }
}

TYPED_TEST(ModelIdentities, TangentMatchesCentralDifferencesOfStress) {
  for (const Mat3d& F : test::test_deformations()) {
    const Mat9d A_fd = test::central_difference_tangent(this->model, F);
    const Mat9d A = this->model.evaluate(F).A;
    EXPECT_LT(max_abs(A_fd - A), 1e-6 * max_abs(A)) << "F =\n" << F;
  }
}

// Taylor test (docs/architecture.md, "Tests"): the central-difference error of a correct derivative
// falls as h^2.
TYPED_TEST(ModelIdentities, DerivativesConvergeAtSecondOrder) {
  const std::vector<Mat3d> deformations = test::test_deformations();
  for (std::size_t n = 0; n < deformations.size(); ++n) {
    const Mat3d& F = deformations[n];
    const Mat3d dF = test::random_direction(100 + static_cast<unsigned>(n)) * max_abs(F);
    const PointResponse r = this->model.evaluate(F);
    const double dW = r.P.cwiseProduct(dF).sum();  // P : dF
    const Vec9d dP = r.A * Eigen::Map<const Vec9d>(dF.data());
    std::vector<double> err_P, err_A;
    for (double h = 1e-2; h > 1e-3; h /= 2) {
      const Mat3d Fp = F + h * dF, Fm = F - h * dF;
      err_P.push_back(std::abs((this->W(Fp) - this->W(Fm)) / (2 * h) - dW));
      const Mat3d dP_fd = (this->P(Fp) - this->P(Fm)) / (2 * h);
      err_A.push_back((Eigen::Map<const Vec9d>(dP_fd.data()) - dP).norm());
    }
    EXPECT_GT(test::observed_order(err_P), 1.8) << "F =\n" << F;
    EXPECT_LT(test::observed_order(err_P), 2.2) << "F =\n" << F;
    EXPECT_GT(test::observed_order(err_A), 1.8) << "F =\n" << F;
    EXPECT_LT(test::observed_order(err_A), 2.2) << "F =\n" << F;
  }
}

/// P and A of the model against dual-number derivatives of its templated energy.
template <class M>
void dual_number_check(const M& model) {
  using Dual = Eigen::AutoDiffScalar<Vec9d>;
  using Inner = Eigen::AutoDiffScalar<Eigen::Matrix<double, 9, 1>>;
  using Dual2 = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, 9, 1>>;  // dual of dual: the Hessian
  for (const Mat3d& F : test::test_deformations()) {
    const PointResponse r = model.evaluate(F);
    Mat3<Dual> Fd;
    Mat3<Dual2> Fdd;
    for (int k = 0; k < 9; ++k) {
      Fd.data()[k] = Dual(F.data()[k], 9, k);
      Fdd.data()[k].value() = Inner(F.data()[k], 9, k);
      Fdd.data()[k].derivatives() = Eigen::Matrix<Inner, 9, 1>::Unit(9, k);
      for (int m = 0; m < 9; ++m) Fdd.data()[k].derivatives()(m).derivatives().setZero();
    }
    const Dual W = model.energy(Fd);
    EXPECT_NEAR(W.value(), r.W, 1e-13 * std::max(1.0, std::abs(r.W)));
    const Vec9d P_vec = Eigen::Map<const Vec9d>(r.P.data());
    EXPECT_LT((W.derivatives() - P_vec).cwiseAbs().maxCoeff(), 1e-12 * P_vec.cwiseAbs().maxCoeff())
        << "F =\n"
        << F;
    const Dual2 W2 = model.energy(Fdd);
    Mat9d A_ad;
    for (int k = 0; k < 9; ++k) A_ad.col(k) = W2.derivatives()(k).derivatives();
    EXPECT_LT(max_abs(A_ad - r.A), 1e-11 * max_abs(r.A)) << "F =\n" << F;
  }
}

TYPED_TEST(ModelIdentities, DualNumbersGiveTheSameEnergyStressAndTangent) {
  if constexpr (!requires(const TypeParam& m, const Mat3d& F) { m.energy(F); }) {
    // Ogden: its stretches are eigenvalues (ogden.hpp); ogden_test.cpp checks it against the
    // invariant models it contains instead.
    GTEST_SKIP() << "no dual-number energy for a model of the principal stretches";
  } else {
    dual_number_check(this->model);
  }
}

TYPED_TEST(ModelIdentities, ZeroEnergyAndStressInTheReferenceState) {
  const PointResponse r = this->model.evaluate(Mat3d::Identity());
  EXPECT_EQ(r.W, 0.0);
  EXPECT_LT(max_abs(r.P), 1e-15 * this->model.shear_modulus());
}

// Linearisation at F = I: the incompressible isotropic elasticity tensor with no bulk part,
// A_ijkl = mu (δ_ik δ_jl + δ_il δ_jk) - 2 mu / 3 δ_ij δ_kl  (materials.md, M13).
TYPED_TEST(ModelIdentities, TangentAtIdentityIsDeviatoricLinearElasticity) {
  const double mu = this->model.shear_modulus();
  Mat9d expected = Mat9d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          expected(i + 3 * j, k + 3 * l) = mu * ((i == k) * (j == l) + (i == l) * (j == k)) -
                                           2.0 * mu / 3.0 * (i == j) * (k == l);
  EXPECT_LT(max_abs(this->model.evaluate(Mat3d::Identity()).A - expected), 1e-14 * mu);
}

TYPED_TEST(ModelIdentities, SmallStrainSimpleShearGivesTheShearModulus) {
  // A fibre family stretched by the shear adds its k1 at first order (its ψ'' jumps from 0 to k1
  // at Ī4 = 1): the small-strain shear stiffness depends on direction and sign.
  if constexpr (requires { TypeParam::kIsotropic; }) GTEST_SKIP() << "anisotropic";
  const double eps = 1e-6;
  Mat3d F = Mat3d::Identity();
  F(0, 1) = eps;  // x displaced along y: simple shear of amount eps
  EXPECT_NEAR(this->P(F)(0, 1) / eps, this->model.shear_modulus(),
              1e-8 * this->model.shear_modulus());
}

TYPED_TEST(ModelIdentities, FrameIndifferentIsotropicAndIsochoric) {
  const Mat3d Q = test::random_rotation(42);
  for (const Mat3d& F : test::test_deformations()) {
    const PointResponse r = this->model.evaluate(F);
    const double tol_W = 1e-12 * std::max(std::abs(r.W), 1e-3 * this->model.shear_modulus());
    const PointResponse rQ = this->model.evaluate(Q * F);
    EXPECT_NEAR(rQ.W, r.W, tol_W);                             // W(QF) = W(F)
    EXPECT_LT(max_abs(rQ.P - Q * r.P), 1e-12 * max_abs(r.P));  // P(QF) = Q P(F)
    if constexpr (!requires { TypeParam::kIsotropic; }) {      // isotropy: not for fibres
      EXPECT_NEAR(this->W(F * Q), r.W, tol_W);                 // W(FQ) = W(F)
      EXPECT_LT(max_abs(this->P(F * Q) - r.P * Q), 1e-12 * max_abs(r.P));  // P(FQ) = P(F) Q
    }
    for (const double a : {0.6, 1.7}) {
      EXPECT_NEAR(this->W(a * F), r.W, tol_W);                             // W(aF) = W(F)
      EXPECT_LT(max_abs(a * this->P(a * F) - r.P), 1e-12 * max_abs(r.P));  // P(aF) = P(F) / a
    }
  }
}

TYPED_TEST(ModelIdentities, TangentIsSymmetric) {
  for (const Mat3d& F : test::test_deformations()) {
    const Mat9d A = this->model.evaluate(F).A;
    EXPECT_LT(max_abs(A - A.transpose()), 1e-14 * max_abs(A)) << "F =\n" << F;
  }
}

TYPED_TEST(ModelIdentities, InvertedElementIsReportedNotNaN) {
  const Mat3d reflected = Vec3d(1.0, 1.0, -1.0).asDiagonal();
  EXPECT_THROW(this->model.evaluate(reflected), InadmissibleDeformation);
  EXPECT_THROW(this->model.evaluate(Mat3d::Zero()), InadmissibleDeformation);
  Mat3d with_nan = Mat3d::Identity();
  with_nan(1, 2) = std::nan("");
  EXPECT_THROW(this->model.evaluate(with_nan), InadmissibleDeformation);
}

TEST(Gent, PastTheExtensibilityLimitIsReported) {
  const Gent gent{1.0, 10.0};
  // Uniaxial λ: Ī1 - 3 = λ² + 2/λ - 3; λ = 3.6 gives 10.52 > jm = 10, λ = 3.3 gives 8.50 < 10.
  const auto uniaxial = [](double l) {
    return Mat3d(Vec3d(1 / std::sqrt(l), 1 / std::sqrt(l), l).asDiagonal());
  };
  EXPECT_TRUE(std::isfinite(gent.evaluate(uniaxial(3.3)).W));
  EXPECT_THROW(gent.evaluate(uniaxial(3.6)), InadmissibleDeformation);
  try {
    gent.evaluate(uniaxial(3.6));
  } catch (const InadmissibleDeformation& e) {
    EXPECT_NE(std::string(e.what()).find("jm = 10"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace plisse
