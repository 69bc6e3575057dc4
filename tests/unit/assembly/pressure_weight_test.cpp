// The weighted free system of MixedModel (docs/theory/mixed_up.md, X1): the pressure unknowns
// enter the free vectors as p / w and their equations times w, w = mu / h, so that every entry of
// the residual is a force.
//  - w is the shear modulus over the edge of the regular tetrahedron of the mean element volume
//    (closed form for a unit cube of 384 tetrahedra, to round-off);
//  - get_free / set_free divide and multiply the pressures by w and nothing else (exact);
//  - the assembled tangent is the derivative of the weighted residual with respect to the free
//    vector: central differences along a random direction agree to 1e-7 (truncation ~ eps^2,
//    round-off ~ 1e-16 / eps with eps = 1e-6);
//  - consequence the weighting exists for: with displacements prescribed, Newton's iterates and
//    the line search's decisions do not depend on the modulus. A body 150 times softer (the
//    paper's c1 = 0.0033 MPa against 0.5 MPa) takes the same iterations, and its residual history
//    relative to its start is the same to 1e-9. Unweighted, the volume rows (mm^3) outweigh the
//    soft body's forces (N) and the backtracking line search cuts the first steps.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "mesh/generate.hpp"
#include "mesh/topology.hpp"
#include "solver/newton_solver.hpp"
#include "solver/petsc_call.hpp"

namespace plisse {
namespace {

Mesh unit_cube() {
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.edge = 1.0;
  spec.divisions = 4;
  return generate_mesh(spec);
}

/// Bottom fixed, top moved by `top` (ramped over t in [0, 1]).
std::vector<ConstrainedComponent> stretch(const Mesh& mesh, const Vec3d& top) {
  std::vector<ConstrainedComponent> constraints;
  for (int v : triangle_nodes(mesh, mesh.surface_tags.at("bottom")))
    for (int k = 0; k < 3; ++k) constraints.push_back({v, k, 0.0, Ramp{0.0, 1.0}});
  for (int v : triangle_nodes(mesh, mesh.surface_tags.at("top")))
    for (int k = 0; k < 3; ++k) constraints.push_back({v, k, top(k), Ramp{0.0, 1.0}});
  return constraints;
}

TEST(PressureWeight, IsTheShearModulusOverTheElementEdge) {
  const Mesh mesh = unit_cube();
  ASSERT_EQ(mesh.n_tets(), 384);
  const MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.25}}), 0.0, {});
  const double mu = 0.5;                                           // 2 c1
  const double h = std::cbrt(6.0 * std::sqrt(2.0) * 1.0 / 384.0);  // V = h^3 / (6 sqrt 2)
  EXPECT_NEAR(model.pressure_weight(), mu / h, 1e-14 * mu / h);
}

TEST(PressureWeight, FreeVectorsCarryPressureOverWeight) {
  const Mesh mesh = unit_cube();
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.25}}), 0.0,
                   stretch(mesh, Vec3d(0.0, 0.0, 0.1)));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (double& value : model.state()) value = unit(rng);
  model.set_time(1.0);
  const std::vector<double> before = model.state();
  Vec x = model.create_vector();
  model.get_free(x);
  const std::vector<double> full = model.full_from_free(x);  // constrained entries 0
  const double w = model.pressure_weight();
  const PetscScalar* a = nullptr;
  PLISSE_PETSC(VecGetArrayRead(x, &a));
  for (int d = 0; d < model.dofs().n_dofs(); ++d) {
    const int eq = model.dofs().equation(d);
    if (eq < 0) continue;
    const double expected = model.dofs().is_pressure(d) ? before[d] / w : before[d];
    EXPECT_EQ(a[eq], expected) << "dof " << d;
    EXPECT_EQ(full[d], model.dofs().is_pressure(d) ? a[eq] * w : a[eq]) << "dof " << d;
  }
  PLISSE_PETSC(VecRestoreArrayRead(x, &a));
  model.set_free(x);
  for (int d = 0; d < model.dofs().n_dofs(); ++d)
    EXPECT_NEAR(model.state()[d], before[d], 1e-15 * std::abs(before[d])) << "dof " << d;
  VecDestroy(&x);
}

TEST(PressureWeight, TangentIsTheDerivativeOfTheWeightedResidual) {
  const Mesh mesh = unit_cube();
  MixedModel model(mesh, make_material("mooney-rivlin", {{"c1", 0.02}, {"c2", 0.005}}), 0.0,
                   stretch(mesh, Vec3d(0.05, 0.02, 0.15)));
  model.set_time(1.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int v = 0; v < mesh.n_nodes(); ++v) {  // a state away from equilibrium, p ~ mu
    for (int k = 0; k < 3; ++k) model.state()[DofMap::dof(v, k)] += 0.01 * unit(rng);
    model.state()[DofMap::dof(v, 3)] = 0.05 * unit(rng);
  }
  model.set_time(1.0);
  Vec x = model.create_vector(), v = nullptr, xp = nullptr, xm = nullptr, fp = nullptr,
      fm = nullptr, Kv = nullptr;
  model.get_free(x);
  for (Vec* y : {&v, &xp, &xm, &fp, &fm, &Kv}) PLISSE_PETSC(VecDuplicate(x, y));
  PetscScalar* direction = nullptr;
  PetscInt n = 0;
  PLISSE_PETSC(VecGetLocalSize(v, &n));
  PLISSE_PETSC(VecGetArray(v, &direction));
  for (PetscInt i = 0; i < n; ++i) direction[i] = unit(rng);
  PLISSE_PETSC(VecRestoreArray(v, &direction));
  Mat K = model.create_matrix();
  model.set_free(x);
  ASSERT_TRUE(model.assemble_tangent(K).ok);
  PLISSE_PETSC(MatMult(K, v, Kv));
  const double eps = 1e-6;
  PLISSE_PETSC(VecWAXPY(xp, eps, v, x));
  PLISSE_PETSC(VecWAXPY(xm, -eps, v, x));
  model.set_free(xp);
  ASSERT_TRUE(model.assemble_residual(fp).ok);
  model.set_free(xm);
  ASSERT_TRUE(model.assemble_residual(fm).ok);
  PLISSE_PETSC(VecAXPY(fp, -1.0, fm));    // f(x + eps v) - f(x - eps v)
  PLISSE_PETSC(VecScale(fp, 0.5 / eps));  // central difference
  PetscReal reference = 0.0, error = 0.0;
  PLISSE_PETSC(VecNorm(Kv, NORM_2, &reference));
  PLISSE_PETSC(VecAXPY(fp, -1.0, Kv));
  PLISSE_PETSC(VecNorm(fp, NORM_2, &error));
  EXPECT_LT(error, 1e-7 * reference);
  MatDestroy(&K);
  for (Vec* y : {&x, &v, &xp, &xm, &fp, &fm, &Kv}) VecDestroy(y);
}

TEST(PressureWeight, NewtonDoesNotDependOnTheModulusWhenDisplacementsArePrescribed) {
  const Mesh mesh = unit_cube();
  const auto solve = [&](double c1) {
    MixedModel model(mesh, make_material("neo-hookean", {{"c1", c1}}), 0.0,
                     stretch(mesh, Vec3d(0.1, 0.05, 0.3)));
    NewtonSettings settings;  // the default backtracking line search
    settings.rtol = 1e-9;
    settings.atol = 0.0;  // an absolute force would not scale with the modulus
    NewtonSolver newton(model, settings);
    model.set_time(1.0);
    return newton.solve();
  };
  const NewtonResult stiff = solve(0.5);
  const NewtonResult soft = solve(0.0033);
  ASSERT_TRUE(stiff.converged);
  ASSERT_TRUE(soft.converged);
  EXPECT_EQ(soft.iterations, stiff.iterations);
  EXPECT_EQ(soft.reused_solves, stiff.reused_solves);
  ASSERT_EQ(soft.residual_history.size(), stiff.residual_history.size());
  for (std::size_t k = 0; k < soft.residual_history.size(); ++k) {
    const double a = soft.residual_history[k] / soft.residual_history[0];
    const double b = stiff.residual_history[k] / stiff.residual_history[0];
    EXPECT_NEAR(a, b, 1e-9 + 1e-6 * b) << "iterate " << k;
  }
}

}  // namespace
}  // namespace plisse
