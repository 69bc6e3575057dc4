// Stability check from the inertia of the tangent (docs/theory/stability.md): the count of
// negative pivots of the MUMPS LDL^T factorisation is the exact eigenvalue count, a stable state
// has exactly the free pressure unknowns plus the cavity multipliers as negative pivots, and a
// clamped strip in compression gains one negative pivot at Euler's critical strain.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "solver/stability.hpp"
#include "verification/stability/fixtures/stability_models.hpp"

namespace plisse {
namespace {

/// The tangent over the free dofs at the model's state as a dense matrix.
Eigen::MatrixXd dense_tangent(MixedModel& model) {
  Mat K = model.create_matrix();
  model.assemble_tangent(K);
  const int n = model.n_free();
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
  for (PetscInt i = 0; i < n; ++i) {
    PetscInt nc = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* vals = nullptr;
    MatGetRow(K, i, &nc, &cols, &vals);
    for (PetscInt k = 0; k < nc; ++k) D(i, cols[k]) = vals[k];
    MatRestoreRow(K, i, &nc, &cols, &vals);
  }
  MatDestroy(&K);
  return D;
}

// The MUMPS count is the eigenvalue count of the symmetric tangent (Sylvester: LDL^T is a
// congruence), checked against a dense symmetric eigensolver on a small strip pushed far beyond
// its first critical strain, where several displacement modes are negative. Exact integers; the
// dense spectrum must have no eigenvalue within 1e-9 of its largest |λ| (an unambiguous sign).
TEST(InertiaCheck, CountsTheNegativeEigenvaluesOfTheTangentExactly) {
  test::StripSpec spec;
  spec.length = 6.0;
  spec.width = 1.0;
  spec.element_size = 0.5;
  test::ModelOnMesh m = test::clamped_strip(spec);
  MixedModel& model = *m.model;
  const Mesh& mesh = *m.mesh;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
  for (double strain : {0.0, 0.05, 0.25}) {  // Euler: eps_cr = pi^2 / 108 = 0.091 here
    // Uniaxial compression, lateral stress free: l1 = 1 - strain, l2 = l3 = l1^(-1/2), and
    // sigma = 2 c1 dev B - p I with sigma_22 = 0 (mixed_up.md, F1); plus noise.
    const double l1 = 1.0 - strain, l2 = 1.0 / std::sqrt(l1);
    const double p = 2.0 * spec.c1 * (l2 * l2 - (l1 * l1 + 2.0 * l2 * l2) / 3.0);
    auto& x = model.state();
    for (int v = 0; v < mesh.n_nodes(); ++v) {
      const Vec3d& X = mesh.nodes[v];
      x[DofMap::dof(v, 0)] = (l1 - 1.0) * X[0] + noise(random);
      x[DofMap::dof(v, 1)] = (l2 - 1.0) * X[1] + noise(random);
      x[DofMap::dof(v, 2)] = (l2 - 1.0) * X[2] + noise(random);
      x[DofMap::dof(v, 3)] = p + 1e-2 * spec.c1 * noise(random);
    }
    const Eigen::MatrixXd K = dense_tangent(model);
    ASSERT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
    const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
    const double scale = lambda.cwiseAbs().maxCoeff();
    ASSERT_GT(lambda.cwiseAbs().minCoeff(), 1e-9 * scale) << "ambiguous sign at strain " << strain;
    const int dense_negative = static_cast<int>((lambda.array() < 0.0).count());
    InertiaCheck check(model);
    const Inertia inertia = check.compute();
    std::printf("strain %.2f: %d negative eigenvalues (free pressures %d), MUMPS %d negative, %d "
                "zero, %d positive\n",
                strain, dense_negative, model.dofs().n_free_pressure(), inertia.negative,
                inertia.zero, inertia.positive);
    EXPECT_EQ(inertia.negative, dense_negative) << "strain " << strain;
    EXPECT_EQ(inertia.zero, 0);
    EXPECT_EQ(inertia.negative + inertia.zero + inertia.positive, model.n_free());
    if (strain == 0.0) {
      EXPECT_EQ(inertia.negative, expected_negative_pivots(model));
    }
    if (strain == 0.25) {
      EXPECT_GT(inertia.negative, expected_negative_pivots(model) + 1);  // several modes lost
    }
  }
}

/// Settings of the verification runs: fixed steps (no growth), tight Newton tolerances.
SolverSettings fixed_steps(int steps) {
  SolverSettings settings;
  settings.steps = steps;
  settings.growth = 1.0;
  settings.newton.rtol = 1e-10;
  settings.newton.atol = 1e-12;
  return settings;
}

StabilityOptions check_only() {
  StabilityOptions o;
  o.check = true;
  o.modes = 2;
  return o;
}

void print_log(const test::SteppedRun& run) {
  for (const auto& line : run.log) std::printf("  log: %s\n", line.c_str());
}

TEST(StabilityCheck, ClampedStripGainsOneNegativePivotAtTheEulerStrain) {
  test::StripSpec spec;
  test::ModelOnMesh m = test::clamped_strip(spec);
  const test::SteppedRun run =
      test::run_steps(*m.model, fixed_steps(40), check_only(), /*measure_deflection=*/true);
  print_log(run);
  ASSERT_TRUE(run.result.completed) << run.result.failure;
  const double euler = std::pow(std::numbers::pi * spec.thickness / spec.length, 2) / 3.0;
  for (size_t k = 0; k < run.steps.size(); ++k) {
    const StepInfo& s = run.steps[k];
    std::printf("step %2d strain %.5f (eps/eps_Euler %.3f): %d negative (stable %d), %d zero, "
                "deflection %.3g mm%s\n",
                s.step, spec.shortening * s.time / spec.length,
                spec.shortening * s.time / spec.length / euler, s.negative_pivots,
                s.expected_negative_pivots, s.zero_pivots, run.deflection[k],
                s.new_instability ? "  NEW INSTABILITY" : "");
  }
}

TEST(BranchSwitching, ClampedStripDeflectsAfterTheSwitch) {
  test::StripSpec spec;
  test::ModelOnMesh m = test::clamped_strip(spec);
  StabilityOptions options = check_only();
  options.branch_switch = true;
  options.perturbation_mm = 0.01 * spec.thickness;
  const test::SteppedRun run =
      test::run_steps(*m.model, fixed_steps(40), options, /*measure_deflection=*/true);
  print_log(run);
  ASSERT_TRUE(run.result.completed) << run.result.failure;
  const double euler = std::pow(std::numbers::pi * spec.thickness / spec.length, 2) / 3.0;
  for (size_t k = 0; k < run.steps.size(); ++k) {
    const StepInfo& s = run.steps[k];
    std::printf("step %2d eps/eps_Euler %.3f: %d negative (stable %d), deflection %.4g mm%s\n",
                s.step, spec.shortening * s.time / spec.length / euler, s.negative_pivots,
                s.expected_negative_pivots, run.deflection[k],
                s.branch_switched ? "  SWITCHED" : "");
  }
}

}  // namespace
}  // namespace plisse
