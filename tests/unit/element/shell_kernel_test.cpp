/// The shell triangle's kernel (docs/theory/shell.md): the thickness rule, the plane-stress
/// derivatives (KL10, KL11), the residual and tangent against finite differences for every
/// registry model (KL15-KL18), and rigid motions.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "shell_test_support.hpp"

namespace plisse::test {
namespace {

using namespace plisse::shell;

TEST(ShellSection, GaussLegendreIsExactToDegreeTwoNMinusOne) {
  const double t = 0.8;
  for (int n = kMinThicknessPoints; n <= kMaxThicknessPoints; ++n) {
    const ShellSection s = make_shell_section(t, n);
    // ∫ ζ^k dζ over [-t/2, t/2] for the highest even degree the rule must integrate, 2n - 2,
    // and the sum of the weights (k = 0); round-off only: 1e-14 relative.
    for (int k : {0, 2 * n - 2}) {
      double sum = 0.0;
      for (int g = 0; g < n; ++g) sum += s.weight[g] * std::pow(s.zeta[g], k);
      const double exact = 2.0 * std::pow(t / 2.0, k + 1) / (k + 1);
      EXPECT_NEAR(sum, exact, 1e-14 * exact) << n << " points, degree " << k;
    }
  }
  EXPECT_THROW(make_shell_section(t, 1), Error);
  EXPECT_THROW(make_shell_section(-t, 5), Error);
}

/// A random in-plane C₂ with stretches between about 0.7 and 1.4, and a random frame.
Mat2d random_C2(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Mat2d F;
  F << 1.0 + 0.3 * unit(rng), 0.3 * unit(rng), 0.3 * unit(rng), 1.0 + 0.3 * unit(rng);
  return F.transpose() * F;
}

Vec3d components(const Mat2d& C) { return Vec3d(C(0, 0), C(1, 1), C(0, 1)); }

Mat2d from_components(const Vec3d& c) {
  Mat2d C;
  C << c(0), c(2), c(2), c(1);
  return C;
}

/// 1/κ [1/MPa] for the plane-stress tests: exact incompressibility, and bulk moduli 1000, 10 and
/// 0.8 MPa against shear moduli near 1 MPa (Poisson's ratios near 0.4995, 0.45 and 0.06, KL12).
constexpr std::array<double, 4> kInverseBulkModuli = {0.0, 1e-3, 0.1, 1.25};

TEST(ShellPlaneStress, DerivativesMatchFiniteDifferencesForEveryModel) {
  std::mt19937 rng(3);
  const Mat3d frame = Eigen::AngleAxisd(0.7, Vec3d(1, -1, 2).normalized()).toRotationMatrix();
  for (double inverse_bulk_modulus : kInverseBulkModuli) {
    for (const AnyMaterial& material : every_material()) {
      const Vec3d c = components(random_C2(rng)) + Vec3d(0.2, 0.2, 0.0);  // fibres stretched
      auto response = [&](const Vec3d& cc) {
        return std::visit(
            [&](const auto& m) {
              return evaluate_plane_stress(m, 0, from_components(cc), frame, inverse_bulk_modulus);
            },
            material);
      };
      const PlaneStressResponse r = response(c);
      // Central differences with h = 1e-6: truncation ~ h² |W'''| ~ 1e-12, round-off
      // ~ 1e-16 |W| / h ~ 1e-10; the derivatives are O(1) MPa, so 1e-7 leaves a margin of 1000.
      // With 1/κ > 0 the condensed C33 is converged to second order in a step below 1e-8 C33
      // (KL12): its error in W₂ is below 1e-16 MPa, far under the differences' own.
      const double h = 1e-6;
      for (int a = 0; a < 3; ++a) {
        const Vec3d e = h * Vec3d::Unit(a);
        const PlaneStressResponse plus = response(c + e);
        const PlaneStressResponse minus = response(c - e);
        const std::string what =
            material_name(material) + ", 1/kappa " + std::to_string(inverse_bulk_modulus);
        EXPECT_NEAR(r.dW(a), (plus.W - minus.W) / (2 * h), 1e-7) << what;
        const Vec3d column = (plus.dW - minus.dW) / (2 * h);
        for (int b = 0; b < 3; ++b) EXPECT_NEAR(r.d2W(b, a), column(b), 1e-7) << what << a << b;
      }
    }
  }
}

TEST(ShellPlaneStress, TheInvariantFormIsTheGeneralFormForEveryInvariantModel) {
  // (KL11a) against (KL9)-(KL11) through F, P and A, for every model of W(Ī1, Ī2) at 20 random
  // C₂ (stretches about 0.7 to 1.4) in a tilted frame: the same function of C₂, so they differ
  // by round-off (measured 1.0e-15 to 3.1e-15 of the largest entry); 1e-13 allows for the
  // general path's inverse of F and its 9 x 9 products. evaluate_plane_stress takes (KL11a) for
  // these models (the same bits), and both refuse a C₂ that is not positive definite.
  std::mt19937 rng(11);
  const Mat3d frame = Eigen::AngleAxisd(0.4, Vec3d(2, 1, -1).normalized()).toRotationMatrix();
  int invariant_models = 0;
  for (const AnyMaterial& material : every_material()) {
    std::visit(
        [&](const auto& m) {
          using Model = std::decay_t<decltype(m)>;
          if constexpr (InvariantModel<Model>) {
            ++invariant_models;
            double largest = 0.0;
            for (int k = 0; k < 20; ++k) {
              const Mat2d C2 = random_C2(rng);
              const PlaneStressInvariants I = plane_stress_invariants(C2);
              const PlaneStressResponse fast =
                  condense_invariants(C2, I, m.invariant_derivatives(I.I1, I.I2));
              const PlaneStressResponse taken = evaluate_plane_stress(m, 0, C2, frame);
              EXPECT_EQ(taken.W, fast.W) << material_name(material);
              EXPECT_EQ(taken.dW, fast.dW) << material_name(material);
              EXPECT_EQ(taken.d2W, fast.d2W) << material_name(material);
              const Mat3d F = plane_stress_deformation(C2, frame);
              const PlaneStressResponse general =
                  condense_plane_stress(C2, frame, F, m.evaluate(F));
              const double scale = std::max({std::abs(general.W), general.dW.cwiseAbs().maxCoeff(),
                                             general.d2W.cwiseAbs().maxCoeff()});
              largest = std::max({largest, std::abs(fast.W - general.W) / scale,
                                  (fast.dW - general.dW).cwiseAbs().maxCoeff() / scale,
                                  (fast.d2W - general.d2W).cwiseAbs().maxCoeff() / scale,
                                  std::abs(fast.C33 - general.C33) / general.C33});
              const PlaneStressResponse residual_only =
                  evaluate_plane_stress(m, 0, C2, frame, 0.0, false);
              EXPECT_EQ(residual_only.W, fast.W) << material_name(material);
              EXPECT_EQ(residual_only.dW, fast.dW) << material_name(material);
            }
            std::printf("%-14s invariant form against the general form: %.1e\n",
                        material_name(material).c_str(), largest);
            EXPECT_LT(largest, 1e-13) << material_name(material);
            Mat2d folded;
            folded << 1.0, 1.2, 1.2, 1.0;  // det < 0
            EXPECT_THROW(evaluate_plane_stress(m, 0, folded, frame), InadmissibleDeformation);
          }
        },
        material);
  }
  EXPECT_EQ(invariant_models, 6);  // neo-Hookean, Mooney-Rivlin, Fung, Yeoh, Gent, Arruda-Boyce
}

TEST(ShellPlaneStress, NearlyIncompressibleNeoHookeanAgainstTheZeroNormalStress) {
  // A principal in-plane stretch (λ1, λ2): λ3 from ∂W/∂λ3 = 0 by bisection (independent of
  // KL12's Newton's method), then W₂ = W(λ1, λ2, λ3) and, by the envelope theorem,
  // ∂W₂/∂λ1 = ∂W/∂λ1 at that λ3. The kernel gives ∂W₂/∂c, and dC11/dλ1 = 2 λ1. Round-off only:
  // 1e-12.
  for (double kappa : {1000.0, 10.0, 0.8}) {
    const PrincipalNeoHookean closed{0.5, kappa};
    const NeoHookean nh{0.5};
    for (const Vec2d& stretch : {Vec2d(1.3, 0.9), Vec2d(1.2, 1.2), Vec2d(0.8, 1.5)}) {
      const double l3 = closed.plane_stress_thickness(stretch.x(), stretch.y());
      const Vec3d l(stretch.x(), stretch.y(), l3);
      const Mat2d C = Vec2d(l(0) * l(0), l(1) * l(1)).asDiagonal();
      const PlaneStressResponse r = evaluate_plane_stress(nh, 0, C, Mat3d::Identity(), 1.0 / kappa);
      EXPECT_NEAR(std::sqrt(r.C33), l3, 1e-12) << kappa;
      EXPECT_NEAR(r.J, l.prod(), 1e-12) << kappa;
      EXPECT_NEAR(r.W, closed.energy(l), 1e-12) << kappa;
      EXPECT_NEAR(2.0 * l(0) * r.dW(0), closed.derivative(l, 0), 1e-12) << kappa;
      EXPECT_NEAR(2.0 * l(1) * r.dW(1), closed.derivative(l, 1), 1e-12) << kappa;
      EXPECT_NEAR(r.dW(2), 0.0, 1e-13) << kappa;  // no shear in the principal axes
    }
  }
}

TEST(ShellPlaneStress, SmallStrainIsLinearPlaneStressWithThePoissonRatioOfTheBulkModulus) {
  // At a small in-plane strain ε, S₂ = E/(1 - ν²) ((1 - ν) ε + ν tr ε I) with E = 9 κ μ /(3 κ + μ)
  // and ν = (3 κ - 2 μ) / (2 (3 κ + μ)): the isochoric model with κ/2 (J - 1)² is linear
  // isotropic elasticity there. ε ~ 1e-6, so the nonlinear terms are 1e-6 of the stress.
  const NeoHookean nh{0.5};  // μ = 1 MPa
  const double mu = 1.0;
  Mat2d eps;
  eps << 1.0e-6, 0.4e-6, 0.4e-6, -0.7e-6;
  for (double kappa : {2.0 / 3.0, 2.0, 1000.0}) {  // ν = 0, 0.29, 0.4995
    const double E = 9.0 * kappa * mu / (3.0 * kappa + mu);
    const double nu = (3.0 * kappa - 2.0 * mu) / (2.0 * (3.0 * kappa + mu));
    const Mat2d S = E / (1.0 - nu * nu) * ((1.0 - nu) * eps + nu * eps.trace() * Mat2d::Identity());
    const PlaneStressResponse r =
        evaluate_plane_stress(nh, 0, Mat2d::Identity() + 2.0 * eps, Mat3d::Identity(), 1.0 / kappa);
    const Vec3d expected(0.5 * S(0, 0), 0.5 * S(1, 1), S(0, 1));  // ∂W₂/∂c = (S11/2, S22/2, S12)
    EXPECT_LT((r.dW - expected).norm(), 1e-5 * expected.norm()) << "kappa " << kappa;
    // The thickness strain: ε33 = -ν/(1 - ν) tr ε.
    EXPECT_NEAR(0.5 * (r.C33 - 1.0), -nu / (1.0 - nu) * eps.trace(), 1e-5 * eps.norm())
        << "kappa " << kappa;
  }
}

TEST(ShellPlaneStress, LargeBulkModulusApproachesExactIncompressibility) {
  // The response with 1/κ > 0 tends to that of KL9 like 1/κ (the volume change it allows is of
  // the order of the stress over κ): at κ = 1e4 and 1e6 MPa against μ ~ 1 MPa, the stress and
  // the Hessian differ by about 1e-4 and 1e-6 of their size.
  std::mt19937 rng(11);
  for (const AnyMaterial& material : every_material()) {
    const Mat2d C = random_C2(rng) + 0.2 * Mat2d::Identity();
    auto at = [&](double inverse_bulk_modulus) {
      return std::visit(
          [&](const auto& m) {
            return evaluate_plane_stress(m, 0, C, Mat3d::Identity(), inverse_bulk_modulus);
          },
          material);
    };
    const PlaneStressResponse exact = at(0.0);
    std::array<double, 2> difference{};
    for (int k = 0; k < 2; ++k) {
      const PlaneStressResponse nearly = at(k == 0 ? 1e-4 : 1e-6);
      difference[k] = std::max((nearly.dW - exact.dW).norm() / exact.dW.norm(),
                               (nearly.d2W - exact.d2W).norm() / exact.d2W.norm());
    }
    std::printf(
        "%s: relative difference from exact incompressibility %.1e (kappa 1e4), %.1e "
        "(1e6)\n",
        material_name(material).c_str(), difference[0], difference[1]);
    EXPECT_LT(difference[0], 1e-2) << material_name(material);
    EXPECT_GT(difference[0] / difference[1], 50.0) << material_name(material);  // about 100
  }
}

TEST(ShellPlaneStress, NeoHookeanClosedForm) {
  // W₂ = c1 (C11 + C22 + 1/det C₂ - 3) for the neo-Hookean model at det F = 1 (KL9); its
  // derivative in C11 is c1 (1 - C22 / det²). Round-off only: 1e-13.
  const NeoHookean nh{0.5};
  std::mt19937 rng(5);
  const Mat2d C = random_C2(rng);
  const PlaneStressResponse r = evaluate_plane_stress(nh, 0, C, Mat3d::Identity());
  const double det = C.determinant();
  EXPECT_NEAR(r.W, 0.5 * (C.trace() + 1.0 / det - 3.0), 1e-13);
  EXPECT_NEAR(r.dW(0), 0.5 * (1.0 - C(1, 1) / (det * det)), 1e-13);
}

/// The reference patch and a deformed state of it: the curved patch stretched by 15 % in every
/// direction and moved randomly by up to 5 % of its size.
struct PatchState {
  ShellGeometry geometry;
  PatchVec u;
};

PatchState deformed_curved_patch(unsigned seed, const SlotKinds& neighbours) {
  const PatchPositions X = curved_patch(seed);
  PatchState s{compute_shell_geometry(X, neighbours), PatchVec::Zero()};
  std::mt19937 rng(seed + 100);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Vec3d centre = X[0];
  for (int n = 0; n < kPatchNodes; ++n) {
    const Vec3d Xn = s.geometry.X.segment<3>(3 * n);
    s.u.segment<3>(3 * n) = 0.15 * (Xn - centre) + 0.05 * Vec3d(unit(rng), unit(rng), unit(rng));
  }
  return s;
}

/// The largest difference between the residual and central differences of the energy, and
/// between the tangent and central differences of the residual, each relative to the largest
/// entry of what it checks.
struct FiniteDifferenceErrors {
  double residual = 0.0;
  double tangent = 0.0;
};

FiniteDifferenceErrors compare_with_finite_differences(const PatchState& s,
                                                       const ShellSection& section,
                                                       const AnyMaterial& material,
                                                       double inverse_bulk_modulus, double h) {
  PatchVec r;
  PatchMat K;
  EXPECT_TRUE(assemble_shell(s.geometry, section, s.u, material, inverse_bulk_modulus, r, &K).ok);
  PatchVec r_fd;
  PatchMat K_fd;
  for (int j = 0; j < kPatchDofs; ++j) {
    PatchVec up = s.u;
    PatchVec um = s.u;
    up(j) += h;
    um(j) -= h;
    PatchVec rp;
    PatchVec rm;
    const double Ep =
        assemble_shell(s.geometry, section, up, material, inverse_bulk_modulus, rp, nullptr).energy;
    const double Em =
        assemble_shell(s.geometry, section, um, material, inverse_bulk_modulus, rm, nullptr).energy;
    r_fd(j) = (Ep - Em) / (2 * h);
    K_fd.col(j) = (rp - rm) / (2 * h);
  }
  return {(r - r_fd).cwiseAbs().maxCoeff() / r.cwiseAbs().maxCoeff(),
          (K - K_fd).cwiseAbs().maxCoeff() / K.cwiseAbs().maxCoeff()};
}

TEST(ShellKernel, ResidualAndTangentMatchFiniteDifferencesForEveryModel) {
  const ShellSection section = make_shell_section(0.1);
  const std::vector<SlotKinds> cases = {all_nodes(), free_sides({1})};
  for (const SlotKinds& neighbours : cases) {
    const PatchState s = deformed_curved_patch(7, neighbours);
    const char* side = neighbours[4] == Slot::missing ? "free" : "inner";
    // Exactly incompressible (KL9), and with a bulk modulus of 2 MPa against shear moduli near
    // 1 MPa (Poisson's ratio near 0.29, KL12).
    for (double inverse_bulk_modulus : {0.0, 0.5}) {
      for (const AnyMaterial& material : every_material()) {
        // h = 1e-6 mm on a patch of 1 mm: truncation ~ h² ~ 1e-12 and round-off ~ 1e-16 / h
        // ~ 1e-10 relative to the entries; 1e-7 relative leaves a margin of 1000 and is far below
        // any wrong term (a missing term of KL16 or KL18 shows at 1e-2 or more).
        const FiniteDifferenceErrors e =
            compare_with_finite_differences(s, section, material, inverse_bulk_modulus, 1e-6);
        std::printf("%s, 1/kappa %g, side 1 %s: residual error %.1e, tangent error %.1e\n",
                    material_name(material).c_str(), inverse_bulk_modulus, side, e.residual,
                    e.tangent);
        EXPECT_LT(e.residual, 1e-7) << material_name(material) << ", 1/kappa "
                                    << inverse_bulk_modulus << ", side 1 " << side;
        EXPECT_LT(e.tangent, 1e-7) << material_name(material) << ", 1/kappa "
                                   << inverse_bulk_modulus << ", side 1 " << side;
      }
    }
  }
}

// A residual alone (no tangent asked) skips the plane-stress condensation's Hessian, most of the
// point's work: it must give the energy and the residual of the call that also forms the tangent,
// to the last bit (the same operations in the same order), for every model, exactly and nearly
// incompressible.
TEST(ShellKernel, TheResidualAloneIsTheResidualOfTheCallWithTheTangent) {
  const ShellSection section = make_shell_section(0.1);
  const PatchState s = deformed_curved_patch(11, all_nodes());
  for (double inverse_bulk_modulus : {0.0, 0.5}) {
    for (const AnyMaterial& material : every_material()) {
      PatchVec with_tangent, alone;
      PatchMat K;
      const ShellStatus full = assemble_shell(s.geometry, section, s.u, material,
                                              inverse_bulk_modulus, with_tangent, &K);
      const ShellStatus residual =
          assemble_shell(s.geometry, section, s.u, material, inverse_bulk_modulus, alone, nullptr);
      ASSERT_TRUE(full.ok && residual.ok) << material_name(material);
      EXPECT_EQ(residual.energy, full.energy) << material_name(material);
      EXPECT_EQ(alone, with_tangent)
          << material_name(material) << ", 1/kappa " << inverse_bulk_modulus;
    }
  }
}

TEST(ShellKernel, TangentIsSymmetricAndMissingNeighbourIsUncoupled) {
  const PatchState s = deformed_curved_patch(11, free_sides({2}));
  PatchVec r;
  PatchMat K;
  ASSERT_TRUE(
      assemble_shell(s.geometry, make_shell_section(0.1), s.u, NeoHookean{0.5}, 0.0, r, &K).ok);
  // A Hessian: symmetric to round-off (1e-12 of its largest entry).
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
  // Slot 5 (across side 2) and slots 10, 11 (beyond it) are missing: exactly zero rows and
  // columns (KL8, KL1b).
  for (int slot : {5, outer_slot(2, 0), outer_slot(2, 1)}) {
    EXPECT_EQ(r.segment<3>(3 * slot).cwiseAbs().maxCoeff(), 0.0) << "slot " << slot;
    EXPECT_EQ(K.middleRows<3>(3 * slot).cwiseAbs().maxCoeff(), 0.0) << "slot " << slot;
    EXPECT_EQ(K.middleCols<3>(3 * slot).cwiseAbs().maxCoeff(), 0.0) << "slot " << slot;
  }
}

/// x -> Q x + c applied to every node's current position, as a displacement of the patch.
PatchVec moved_rigidly(const ShellGeometry& g, const PatchVec& u, const Mat3d& Q, const Vec3d& c) {
  PatchVec out;
  for (int n = 0; n < kPatchNodes; ++n) {
    const Vec3d X = g.X.segment<3>(3 * n);
    out.segment<3>(3 * n) = Q * (X + u.segment<3>(3 * n)) + c - X;
  }
  return out;
}

TEST(ShellKernel, RigidMotionsChangeNothing) {
  const ShellSection section = make_shell_section(0.1);
  const Mat3d Q = Eigen::AngleAxisd(1.1, Vec3d(0.3, -1, 0.6).normalized()).toRotationMatrix();
  const Vec3d c(0.7, -2.0, 1.3);
  const NeoHookean nh{0.5};
  const PatchState s = deformed_curved_patch(13, all_nodes());
  PatchVec r;
  PatchMat K;
  // From the reference: zero energy and residual. Scale: the energy of a 10 % strain is about
  // μ (0.1)² t A ~ 5e-4 mJ and its forces ~ 5e-3 N; round-off leaves 1e-13 of that.
  const PatchVec rigid = moved_rigidly(s.geometry, PatchVec::Zero(), Q, c);
  const ShellStatus at_rest = assemble_shell(s.geometry, section, rigid, nh, 0.0, r, &K);
  std::printf("rigid motion from the reference: energy %.1e mJ, residual %.1e N\n", at_rest.energy,
              r.cwiseAbs().maxCoeff());
  EXPECT_NEAR(at_rest.energy, 0.0, 1e-15);
  EXPECT_LT(r.cwiseAbs().maxCoeff(), 1e-14);
  // The tangent at rest annihilates the infinitesimal rotations and translations.
  PatchVec mode;
  for (int n = 0; n < kPatchNodes; ++n) {
    const Vec3d x = s.geometry.X.segment<3>(3 * n) + rigid.segment<3>(3 * n);
    mode.segment<3>(3 * n) = Vec3d(0.2, -0.5, 1.0).cross(x) + Vec3d(1.0, 0.4, -0.3);
  }
  const double rigid_tangent =
      (K * mode).cwiseAbs().maxCoeff() / (K.cwiseAbs().maxCoeff() * mode.norm());
  std::printf("tangent times the rigid modes: %.1e relative\n", rigid_tangent);
  EXPECT_LT(rigid_tangent, 1e-12);
  // From a deformed state: the same energy, the residual turned with the patch (relative 1e-12).
  PatchVec r0;
  const double E0 = assemble_shell(s.geometry, section, s.u, nh, 0.0, r0, nullptr).energy;
  const ShellStatus moved = assemble_shell(
      s.geometry, section, moved_rigidly(s.geometry, s.u, Q, c), nh, 0.0, r, nullptr);
  double turned = 0.0;
  for (int n = 0; n < kPatchNodes; ++n)
    turned = std::max(turned, (r.segment<3>(3 * n) - Q * r0.segment<3>(3 * n)).norm() / r0.norm());
  std::printf("rigid motion of a deformed patch: energy %.1e, residual %.1e relative\n",
              std::abs(moved.energy / E0 - 1.0), turned);
  EXPECT_NEAR(moved.energy, E0, 1e-12 * E0);
  EXPECT_LT(turned, 1e-12);
}

TEST(ShellKernel, InadmissibleStateIsReportedNotThrown) {
  const PatchState s = deformed_curved_patch(17, all_nodes());
  PatchVec u = PatchVec::Zero();
  // Node 1 onto node 0: the triangle collapses.
  u.segment<3>(3) = s.geometry.X.segment<3>(0) - s.geometry.X.segment<3>(3);
  PatchVec r;
  PatchMat K;
  const ShellStatus status =
      assemble_shell(s.geometry, make_shell_section(0.1), u, NeoHookean{0.5}, 0.0, r, &K);
  EXPECT_FALSE(status.ok);
  EXPECT_EQ(r.cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace plisse::test
