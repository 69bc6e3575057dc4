// Stability check from the inertia of the tangent (docs/theory/stability.md): the count of
// negative pivots of the MUMPS LDL^T factorisation is the exact eigenvalue count, a stable state
// has exactly the free pressure unknowns plus the cavity multipliers as negative pivots, and a
// clamped strip in compression gains one negative pivot at Euler's critical strain.
#include "solver/stability.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <set>

#include "mesh/generate.hpp"
#include "support/cube_tension.hpp"
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

/// Settings of the verification runs: fixed steps (no growth), tight Newton tolerances.
SteppingSettings fixed_steps(int steps) {
  SteppingSettings settings;
  settings.steps = steps;
  settings.growth = 1.0;
  settings.newton.rtol = 1e-10;
  settings.newton.atol = 1e-12;
  return settings;
}

StabilityCheckSettings check_only() {
  StabilityCheckSettings o;
  o.check = true;
  o.modes = 2;
  return o;
}

void print_log(const test::SteppedRun& run) {
  for (const auto& line : run.log) std::printf("  log: %s\n", line.c_str());
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
    // sigma = 2 c1 dev B - p I with sigma_22 = 0 (mixed_up.md, Y1); plus noise.
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
    std::printf(
        "strain %.2f: %d negative eigenvalues (free pressures %d), MUMPS %d negative, %d "
        "zero, %d positive\n",
        strain, dense_negative, model.dofs().n_free_pressure(), inertia.negative, inertia.zero,
        inertia.positive);
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

// A follower pressure on the open top face of a cube makes the tangent unsymmetric: the check
// factorises the symmetric part 0.5 (K + K^T) (stability.md, S8), whose negative eigenvalues a
// dense eigensolver counts. The state is compressed hard enough (load 0.6 c1 on the top, a state
// shortened by 20 %, a hydrostatic pressure of 4 c1, noise) to take the symmetric part past
// stability.
TEST(InertiaCheck, UsesTheSymmetricPartOfAnUnsymmetricTangent) {
  test::ModelOnMesh m = test::model_from_case(R"(
mesh: {generate: cube, edge: 1.0, divisions: 3}
material: {model: neo-hookean, c1: 0.5}
boundary:
  - {type: fixed, surface: bottom}
loads:
  - {type: pressure, name: push, surface: top, value: 0.3}
)",
                                              "cube-pressure.yaml");
  MixedModel& model = *m.model;
  ASSERT_FALSE(model.symmetric());
  model.set_time(1.0);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> noise(-1e-2, 1e-2);
  auto& x = model.state();
  for (int v = 0; v < m.mesh->n_nodes(); ++v) {
    const Vec3d& X = m.mesh->nodes[v];
    x[DofMap::dof(v, 0)] = 0.1 * X[0] * X[2] + noise(random);
    x[DofMap::dof(v, 1)] = 0.1 * X[1] * X[2] + noise(random);
    x[DofMap::dof(v, 2)] = -0.2 * X[2] + noise(random);
    x[DofMap::dof(v, 3)] = 2.0 + noise(random);  // hydrostatic compression 4 c1
  }
  model.set_time(1.0);  // constrained components back to their values
  const Eigen::MatrixXd K = dense_tangent(model);
  const double asymmetry = (K - K.transpose()).cwiseAbs().maxCoeff();
  EXPECT_GT(asymmetry, 1e-6 * K.cwiseAbs().maxCoeff());  // really unsymmetric
  const Eigen::MatrixXd S = 0.5 * (K + K.transpose());
  const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(S).eigenvalues();
  ASSERT_GT(lambda.cwiseAbs().minCoeff(), 1e-9 * lambda.cwiseAbs().maxCoeff());
  const int dense_negative = static_cast<int>((lambda.array() < 0.0).count());
  InertiaCheck check(model);
  EXPECT_TRUE(check.uses_symmetric_part());
  const Inertia first = check.compute();
  const Inertia again = check.compute();  // reused pattern and symbolic factorisation
  std::printf(
      "unsymmetric tangent: symmetric part has %d negative eigenvalues (%d pressures); "
      "MUMPS %d, %d zero\n",
      dense_negative, model.dofs().n_free_pressure(), first.negative, first.zero);
  EXPECT_EQ(first.negative, dense_negative);
  EXPECT_EQ(first.zero, 0);
  EXPECT_EQ(again.negative, first.negative);
  EXPECT_EQ(again.zero, first.zero);
  EXPECT_GT(first.negative, model.dofs().n_free_pressure());  // past stability
}

// The options are validated before a run.
TEST(LoadStepperStability, RefusesInconsistentOptions) {
  test::StripSpec spec;
  spec.length = 4.0;
  spec.width = 1.0;
  test::ModelOnMesh m = test::clamped_strip(spec);
  LoadStepper stepper(*m.model, SteppingSettings{});
  StabilityCheckSettings o;
  o.branch_switch = true;
  o.perturbation_mm = 0.01;
  EXPECT_THROW(stepper.set_stability(o), Error);  // branch switching without the check
  o.check = true;
  o.perturbation_mm = 0.0;
  EXPECT_THROW(stepper.set_stability(o), Error);  // no amplitude
  o.perturbation_mm = 0.01;
  o.modes = 0;
  EXPECT_THROW(stepper.set_stability(o), Error);
  o.modes = 1;
  EXPECT_NO_THROW(stepper.set_stability(o));
}

// Without the check the steps report "not checked".
TEST(LoadStepperStability, StepsAreNotCheckedByDefault) {
  test::StripSpec spec;
  spec.length = 4.0;
  spec.width = 1.0;
  spec.shortening = 0.01;
  test::ModelOnMesh m = test::clamped_strip(spec);
  const test::SteppedRun run = test::run_steps(*m.model, fixed_steps(2), StabilityCheckSettings{});
  ASSERT_EQ(run.steps.size(), 2u);
  for (const StepInfo& s : run.steps) {
    EXPECT_EQ(s.negative_pivots, -1);
    EXPECT_TRUE(s.stable);
    EXPECT_FALSE(s.new_instability);
  }
  EXPECT_EQ(run.stability_checks, 0);
}

/// Every step checked, stable, with exactly `expected` negative pivots and no zero pivot.
void expect_stable_throughout(const test::SteppedRun& run, int expected) {
  for (const StepInfo& s : run.steps) {
    EXPECT_EQ(s.negative_pivots, expected) << "step " << s.step;
    EXPECT_EQ(s.expected_negative_pivots, expected) << "step " << s.step;
    EXPECT_EQ(s.zero_pivots, 0) << "step " << s.step;
    EXPECT_TRUE(s.stable) << "step " << s.step;
    EXPECT_FALSE(s.new_instability) << "step " << s.step;
    EXPECT_TRUE(s.modes.empty()) << "step " << s.step;
  }
}

// Uniaxial tension of the incompressible cube (examples/cube-tension-*.yaml set-up, built in code):
// sliding symmetry planes, top face pulled to stretch 3. The homogeneous tension of a neo-Hookean
// or Mooney-Rivlin solid is stable, so every step has exactly one negative pivot per free pressure
// unknown (stability.md, S4), for exact and for near incompressibility (kappa = 100 mu).
struct CubeCase {
  const char* title;
  const char* model;
  MaterialValues values;
  double inverse_bulk_modulus;
};

void expect_stable_cube_tension(const CubeCase& c) {
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.edge = 5.0;
  spec.divisions = 3;
  const Mesh mesh = generate_mesh(spec);
  const std::vector<ConstrainedComponent> constraints =
      test::cube_tension_constraints(mesh, 10.0);  // stretch 3
  MixedModel model(mesh, make_material(c.model, c.values), c.inverse_bulk_modulus, constraints);
  const test::SteppedRun run = test::run_steps(model, fixed_steps(10), check_only());
  print_log(run);
  ASSERT_TRUE(run.result.completed) << run.result.failure;
  ASSERT_EQ(run.steps.size(), 10u);
  std::printf("%s: %d free pressures, negative pivots at the last step %d\n", c.title,
              model.dofs().n_free_pressure(), run.steps.back().negative_pivots);
  EXPECT_EQ(model.dofs().n_free_pressure(), mesh.n_nodes());  // no pressure is constrained
  expect_stable_throughout(run, model.dofs().n_free_pressure());
}

TEST(StabilityCheck, CubeTensionIsStableWithOneNegativePivotPerPressure) {
  expect_stable_cube_tension({"neo-Hookean, exact", "neo-hookean", {{"c1", 0.25}}, 0.0});
  expect_stable_cube_tension(
      {"Mooney-Rivlin, kappa = 100 mu", "mooney-rivlin", {{"c1", 0.2}, {"c2", 0.05}}, 1.0 / 50.0});
}

// The thin balloon of tests/verification/cavity (octant, A = 20 mm, H = 1 mm, neo-Hookean) inflated
// by prescribed volume through its pressure maximum (at V/V0 = 2.8, run to 4): under volume control
// the state stays stable past the maximum, and the cavity pressure, the multiplier of the volume
// constraint, adds exactly one negative pivot (stability.md, S6).
TEST(StabilityCheck, VolumeControlledBalloonIsStableThroughItsPressureMaximum) {
  test::ModelOnMesh m = test::model_from_case(R"(
mesh: {generate: spherical-shell, inner_radius: 20.0, thickness: 1.0, layers: 2,
       element_size: 2.0, symmetry: octant}
material: {model: neo-hookean, c1: 0.1}
boundary:
  - {type: symmetry, surface: sym_x}
  - {type: symmetry, surface: sym_y}
  - {type: symmetry, surface: sym_z}
cavities:
  - {name: balloon, surface: inner, control: volume, volume_ratio: 4.0}
)",
                                              "balloon.yaml");
  MixedModel& model = *m.model;
  ASSERT_EQ(model.terms().size(), 1u);
  EXPECT_EQ(model.terms().front()->negative_directions(), 1);
  const int expected = model.dofs().n_free_pressure() + 1;
  EXPECT_EQ(expected_negative_pivots(model), expected);
  const test::SteppedRun run = test::run_steps(model, fixed_steps(20), check_only());
  print_log(run);
  ASSERT_TRUE(run.result.completed) << run.result.failure;
  expect_stable_throughout(run, expected);
  // The run passes the pressure maximum: the cavity pressure rises, then falls by more than 2 %.
  std::vector<double> pressure;
  for (const auto& g : run.globals) pressure.push_back(g.at(0));
  const auto peak = std::max_element(pressure.begin(), pressure.end());
  std::printf("balloon: pressure maximum %.6f MPa at step %td of %zu, last %.6f MPa\n", *peak,
              peak - pressure.begin() + 1, pressure.size(), pressure.back());
  EXPECT_GT(peak - pressure.begin(), 2);
  EXPECT_LT(pressure.back(), 0.98 * *peak);
}

// The same balloon filled by an isothermal ideal gas (mass ratio 2): the (p_c, p_c) entry
// -V_c/(p_c + p_amb) < 0 also adds exactly one negative pivot to the stable state (S6).
TEST(StabilityCheck, GasFilledBalloonCountsOneNegativePivotForTheCavity) {
  test::ModelOnMesh m = test::model_from_case(R"(
mesh: {generate: spherical-shell, inner_radius: 20.0, thickness: 1.0, layers: 2,
       element_size: 2.0, symmetry: octant}
material: {model: neo-hookean, c1: 0.1}
boundary:
  - {type: symmetry, surface: sym_x}
  - {type: symmetry, surface: sym_y}
  - {type: symmetry, surface: sym_z}
cavities:
  - {name: balloon, surface: inner, control: gas, initial_pressure: 0.0, mass_ratio: 2.0,
     ambient_pressure: 0.1}
)",
                                              "balloon-gas.yaml");
  MixedModel& model = *m.model;
  const int expected = model.dofs().n_free_pressure() + 1;
  EXPECT_EQ(expected_negative_pivots(model), expected);
  const test::SteppedRun run = test::run_steps(model, fixed_steps(4), check_only());
  print_log(run);
  ASSERT_TRUE(run.result.completed) << run.result.failure;
  ASSERT_EQ(run.steps.size(), 4u);
  expect_stable_throughout(run, expected);
  EXPECT_GT(run.globals.back().at(0), 0.0);  // the gas is compressed: positive gauge pressure
}

// Euler buckling of a slender clamped strip (L = 20, W = 2, t = 1 mm, 3 layers, in-plane element
// 0.5 mm; test::clamped_strip) shortened to 3 times the clamped-clamped Euler strain
//   eps_cr = pi^2 t^2 / (3 L^2) = 0.00822          (EI (2 pi / L)^2 = E W t eps, E = 3 mu = 6 c1)
// in 40 equal steps. The perfect strip stays straight (deflection at round-off) on the
// homogeneous branch, stable before the critical strain; one negative pivot is added at the first
// critical strain, a second one at the second (antisymmetric) mode, 2.05 eps_cr for Euler.
// The FE critical strain is above Euler's: linear tetrahedra bend too stiffly with 3 layers and
// 0.5 mm in-plane elements (about 1.5 eps_cr here, converging towards eps_cr with in-plane
// refinement: StabilityCheckSlow). Shear deformation (t/L = 1/20: about 1 %) and finite strain
// (< 2 % at strains of 1 %) lower it slightly. Asserted: the bracket of the step lies in
// [1.0, 1.6] eps_cr and holds the critical strain of the homogeneous state found by bisection.
TEST(StabilityCheck, ClampedStripGainsOneNegativePivotAtTheEulerStrain) {
  test::StripSpec spec;
  test::ModelOnMesh m = test::clamped_strip(spec);
  const int stable = expected_negative_pivots(*m.model);
  const test::SteppedRun run =
      test::run_steps(*m.model, fixed_steps(40), check_only(), /*measure_deflection=*/true);
  print_log(run);
  ASSERT_TRUE(run.result.completed) << run.result.failure;
  const double euler = std::pow(std::numbers::pi * spec.thickness / spec.length, 2) / 3.0;
  // The cost of the check (printed for the documentation, not asserted: the machine is shared).
  const PhaseTimes& nt = run.newton_times;
  std::printf(
      "cost: %d checks %.3f s (%.1f ms each, of which assembly %.1f ms); Newton %d "
      "numeric factorisations %.3f s (%.1f ms each), assembly %.3f s, linear solve %.3f "
      "s; eigenmodes %.3f s\n",
      run.stability_checks, run.stability_seconds,
      1e3 * run.stability_seconds / std::max(1, run.stability_checks),
      1e3 * run.stability_assembly_seconds / std::max(1, run.stability_checks), nt.factorisations,
      nt.factorisation, 1e3 * nt.factorisation / std::max(1, nt.factorisations), nt.assembly,
      nt.linear_solve, run.eigenmode_seconds);
  EXPECT_EQ(run.stability_checks, 40);
  const auto strain = [&](const StepInfo& s) { return spec.shortening * s.time / spec.length; };
  int first = -1, second = -1;
  for (size_t k = 0; k < run.steps.size(); ++k) {
    const StepInfo& s = run.steps[k];
    // Round-off, amplified in the step that crosses the critical strain by the reuse iterations
    // (newton_solver.hpp): from the last stable state's factor they multiply the residual's
    // component along the softening mode, and the converged residual (rtol 1e-8) leaves a
    // deflection of r / lambda along a mode of nearly zero stiffness (measured 3.5e-10 mm at
    // step 20, 5e-14 or less elsewhere). A bent strip deflects by tenths of a millimetre.
    EXPECT_LT(run.deflection[k], 1e-9) << "step " << s.step << ": the perfect strip bent";
    EXPECT_EQ(s.zero_pivots, 0);
    EXPECT_GE(s.negative_pivots, stable);
    if (s.new_instability && first < 0)
      first = static_cast<int>(k);
    else if (s.new_instability && second < 0)
      second = static_cast<int>(k);
  }
  ASSERT_GT(first, 0) << "no instability found";
  for (int k = 0; k < first; ++k) {
    EXPECT_TRUE(run.steps[k].stable) << "step " << run.steps[k].step;
    EXPECT_EQ(run.steps[k].negative_pivots, stable);
  }
  const StepInfo& at = run.steps[first];
  EXPECT_EQ(at.negative_pivots, stable + 1);
  EXPECT_FALSE(at.stable);
  EXPECT_FALSE(at.branch_switched);
  ASSERT_EQ(at.modes.size(), 2u);
  EXPECT_LT(at.modes.front().eigenvalue, 0.0);
  EXPECT_GT(at.modes[1].eigenvalue, 0.0);  // one mode lost, the next still stable
  const double low = strain(run.steps[first - 1]), high = strain(at);
  const double bisected = test::critical_strain_by_bisection(spec, low, high, 1e-4);
  std::printf(
      "critical strain: bracket [%.5f, %.5f] = [%.3f, %.3f] eps_Euler; bisection %.5f "
      "= %.4f eps_Euler (eps_Euler = %.5f)\n",
      low, high, low / euler, high / euler, bisected, bisected / euler, euler);
  EXPECT_GE(low, 1.0 * euler);
  EXPECT_LE(high, 1.6 * euler);
  EXPECT_GT(bisected, low);
  EXPECT_LT(bisected, high);
  // The second, antisymmetric mode at about 2 times the first critical strain.
  ASSERT_GT(second, first) << "no second instability";
  EXPECT_EQ(run.steps[second].negative_pivots, stable + 2);
  const double ratio = strain(run.steps[second]) / high;
  EXPECT_GT(ratio, 1.8);
  EXPECT_LT(ratio, 2.3);
}

// The same strip with branch switching by perturbations alone (`branch_start: perturbation`,
// 0.01 t; Koiter's estimate: branch_start_test.cpp): at the first new instability the
// stepper perturbs along mode 1 and re-solves; Newton falls back onto the homogeneous state from
// small amplitudes and the amplitude grows by 4 until it does not (stability.md, S10). The
// switched state is stable again (the post-buckling branch of a strut is stable), switching
// happens once, and a few steps later the deflection is orders of magnitude above the
// perturbation, while the perfect strip's stays at round-off (previous test).
TEST(BranchSwitching, ClampedStripDeflectsLaterallyAfterTheSwitch) {
  test::StripSpec spec;
  test::ModelOnMesh m = test::clamped_strip(spec);
  const int stable = expected_negative_pivots(*m.model);
  StabilityCheckSettings options = check_only();
  options.branch_switch = true;
  options.perturbation_mm = 0.01 * spec.thickness;
  options.koiter_start = false;
  SteppingSettings settings = fixed_steps(40);
  settings.end_time = 0.7;  // to 2.1 eps_cr: before the second mode
  const test::SteppedRun run = test::run_steps(*m.model, settings, options, true);
  print_log(run);
  ASSERT_TRUE(run.result.completed) << run.result.failure;
  int switched = -1;
  for (size_t k = 0; k < run.steps.size(); ++k)
    if (run.steps[k].branch_switched) {
      EXPECT_LT(switched, 0) << "switched twice";
      switched = static_cast<int>(k);
    }
  ASSERT_GT(switched, 0) << "no branch switch";
  const StepInfo& at = run.steps[switched];
  EXPECT_TRUE(at.new_instability);
  EXPECT_EQ(at.unstable_negative_pivots, stable + 1);
  EXPECT_EQ(at.negative_pivots, stable);  // the buckled state is stable
  EXPECT_TRUE(at.stable);
  EXPECT_GE(at.perturbation_mm, options.perturbation_mm);
  for (int k = 0; k < switched; ++k) EXPECT_LT(run.deflection[k], 1e-10);
  ASSERT_GE(run.steps.size(), static_cast<size_t>(switched + 4));
  const double later = run.deflection[switched + 3];
  std::printf(
      "deflection: %.3g mm at the switch (amplitude %.3g mm), %.3g mm three steps later, "
      "%.3g mm at the end\n",
      run.deflection[switched], at.perturbation_mm, later, run.deflection.back());
  EXPECT_GT(later, 10.0 * options.perturbation_mm);
  for (size_t k = switched; k < run.steps.size(); ++k) {
    EXPECT_TRUE(run.steps[k].stable) << "step " << run.steps[k].step;
    if (k > static_cast<size_t>(switched)) {
      EXPECT_GT(run.deflection[k], run.deflection[k - 1]);  // grows with the end shortening
    }
  }
}

}  // namespace
}  // namespace plisse
