// Koiter's asymptotic estimate of the buckled state (docs/theory/stability.md, S10a) on the
// clamped strip of stability_test.cpp (L = 20, W = 2, t = 1 mm, 3 layers, 0.5 mm in-plane), set to
// the exact homogeneous compression at (1 + δ) ε_c, ε_c the strain where the homogeneous state
// loses stability (found by bisection of the inertia). There the estimate
// u + sΦ + s²V, s = root of k + q s + c s², is checked against the buckled state Newton converges
// to from it (an independent solve of the full equations at the same load):
//  - k, the fitted slope of the one-mode residual, is Φ·KΦ = λ Φ·MΦ (E1) of the eigenpair;
//  - the estimate's error relative to the buckled deflection falls like δ (Koiter: the state is
//    exact to O(s²), s² ∝ δ, so the relative error is O(s²) = O(δ)): below δ/10 at δ = 0.2, 0.1,
//    0.05 (measured 1.82e-2, 8.49e-3, 3.98e-3), and halving δ must at least divide it by 1.5 (by
//    2 asymptotically; an error that does not fall, or falls like √δ, fails);
//  - Newton converges from the estimate in at most 3 iterations onto a stable buckled state.
#include "solver/branch_start.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "solver/eigenmodes.hpp"
#include "solver/newton_solver.hpp"
#include "solver/stability.hpp"
#include "verification/stability/fixtures/stability_models.hpp"

namespace plisse {
namespace {

struct EstimateCheck {
  BranchStart start;
  double k_mode = 0.0;   ///< λ Φ·MΦ [N/mm]
  double buckled = 0.0;  ///< max nodal |x_b - u| [mm]
  double error = 0.0;    ///< max nodal |x_b - x_estimate| / buckled
  int newton_iterations = -1;
  int negative_after = -1, stable_count = -1;
};

EstimateCheck check_at(const test::StripSpec& spec, double strain) {
  EstimateCheck out;
  test::ModelOnMesh m = test::clamped_strip(spec);
  MixedModel& model = *m.model;
  test::set_homogeneous_compression(model, spec, strain);
  model.save_converged();
  const std::vector<double> u = model.state();
  InertiaCheck check(model);
  out.stable_count = expected_negative_pivots(model);
  EXPECT_EQ(check.compute().negative, out.stable_count + 1) << "strain " << strain;
  const std::vector<Eigenmode> modes = lowest_eigenmodes(model, {1, 0.0, 1e-10});
  const std::vector<double> volumes = lumped_nodal_volumes(model.mesh());
  double phi_m_phi = 0.0;
  for (int v = 0; v < model.mesh().n_nodes(); ++v)
    for (int k = 0; k < 3; ++k)
      phi_m_phi += volumes[v] * std::pow(modes[0].state[DofMap::dof(v, k)], 2);
  out.k_mode = modes[0].eigenvalue * phi_m_phi;
  out.start = asymptotic_branch_start(model, check.factor(), modes[0].state, 0.01 * spec.thickness);
  EXPECT_EQ(model.state(), u) << "the estimate did not restore the converged state";
  if (out.start.amplitude == 0.0) return out;

  model.state() = out.start.state;
  NewtonSettings settings;
  settings.rtol = 1e-10;
  settings.atol = 1e-12;
  NewtonSolver newton(model, settings);
  const NewtonResult result = newton.solve();
  EXPECT_TRUE(result.converged) << result.reason;
  out.newton_iterations = result.iterations;
  const int n_nodes = model.mesh().n_nodes();
  out.buckled = max_nodal_distance(model.state(), u, n_nodes);
  out.error = max_nodal_distance(model.state(), out.start.state, n_nodes) / out.buckled;
  out.negative_after = check.compute().negative;
  return out;
}

TEST(BranchStart, KoitersEstimateOfTheBuckledStripErrsLikeTheDistanceFromTheCriticalLoad) {
  const test::StripSpec spec;
  // Homogeneous compression: stable at 1.0, unstable at 1.6 times Euler's (stability_test.cpp).
  const double euler = std::pow(std::numbers::pi * spec.thickness / spec.length, 2) / 3.0;
  const double critical = test::critical_strain_by_bisection(spec, euler, 1.6 * euler, 1e-8);
  std::printf("critical strain of the homogeneous state %.8f = %.4f eps_Euler\n", critical,
              critical / euler);
  double previous = 0.0;
  for (const double delta : {0.2, 0.1, 0.05}) {
    const EstimateCheck c = check_at(spec, (1.0 + delta) * critical);
    std::printf(
        "delta %.3f: k %.6e N/mm (lambda Phi.M Phi %.6e), q %.3e N/mm^2, c %.5e N/mm^3, amplitude "
        "%.5f mm; buckled state %.5f mm away, estimate off by %.3e of it; Newton %d "
        "iterations\n",
        delta, c.start.k, c.k_mode, c.start.q, c.start.c, c.start.amplitude, c.buckled, c.error,
        c.newton_iterations);
    ASSERT_NE(c.start.amplitude, 0.0) << "no buckled state estimated at delta " << delta;
    EXPECT_NEAR(c.start.k / c.k_mode, 1.0, 1e-5) << "delta " << delta;
    EXPECT_GT(c.start.c, 0.0) << "a strut's post-buckling is stable (supercritical)";
    // Nearly symmetric: the two sides' roots differ by |q| s / |k| (the tetrahedra are not
    // symmetric about the mid-plane), below S10a's 1 % for equally near, so the positive side.
    EXPECT_LT(std::abs(c.start.q) * c.buckled / std::abs(c.start.k), 0.01)
        << "a strut's bifurcation is symmetric";
    EXPECT_GT(c.start.amplitude, 0.0) << "symmetric: the mode's own orientation";
    EXPECT_LE(c.newton_iterations, 3) << "delta " << delta;
    EXPECT_EQ(c.negative_after, c.stable_count) << "the buckled state is stable";
    EXPECT_LT(c.error, 0.1 * delta) << "delta " << delta;
    if (previous > 0.0) {
      EXPECT_LT(c.error, previous / 1.5) << "delta " << delta;
    }
    previous = c.error;
  }
}

}  // namespace
}  // namespace plisse
