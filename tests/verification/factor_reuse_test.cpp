// Factor reuse (solver.newton.reuse_factor, solver/newton_solver.hpp): before factorising anew,
// Newton iterates with a factorisation already at hand while each iteration cuts the residual at
// least tenfold. It must change the cost, not the answer:
//  - every step converges by the same test as a plain Newton solve, ||R|| <= rtol ||R(x_0)||, with
//    x_0 the step's predicted start;
//  - the converged states agree with plain Newton's to the tolerance those tests leave;
//  - it takes fewer factorisations (Newton iterations proper) for the same steps.
// Cases: a stretched and sheared cube in equal steps with the stability check, whose LDL^T of the
// converged state is offered to the next step; a block pressed by a die, whose contact multiplier
// updates re-solve with a tangent that barely changed; a factor far from the solution (a jump
// from 10 % to 100 % of the load), which the contraction test must refuse. When a chord step is
// refused, Krylov steps (GMRES on the new tangent, preconditioned by the kept factor) go on
// without factorising: they must reach plain Newton's answer at Newton's rate, and leave to
// Newton what GMRES cannot finish within its iteration limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "mesh/generate.hpp"
#include "mesh/topology.hpp"
#include "physics/die_contact.hpp"
#include "physics/surface.hpp"
#include "solver/load_stepper.hpp"
#include "solver/newton_solver.hpp"

namespace plisse {
namespace {

constexpr double kRtol = 1e-8;

struct StepRecord {
  std::vector<double> state;
  int newton_iterations = 0;
  int reused_solves = 0;
  double start_norm = 0.0;  ///< ||R|| the relative test refers to (the pass's first)
  double final_norm = 0.0;
  double die_force = 0.0;
};

struct SteppedRun {
  bool completed = false;
  std::vector<StepRecord> steps;
  int newton_iterations = 0;  ///< over the whole run, all contact passes
  int reused_solves = 0;
};

Mesh unit_cube(int divisions) {
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.edge = 1.0;
  spec.divisions = divisions;
  return generate_mesh(spec);
}

std::vector<ConstrainedComponent> fixed(const Mesh& mesh, const std::string& tag,
                                        const Vec3d& motion) {
  std::vector<ConstrainedComponent> constraints;
  for (int v : triangle_nodes(mesh, mesh.surface_tags.at(tag)))
    for (int k = 0; k < 3; ++k) constraints.push_back({v, k, motion(k), Ramp{0.0, 1.0}});
  return constraints;
}

/// Steps `model` in `steps` equal steps to t = 1, recording every converged step.
SteppedRun step_through(MixedModel& model, int steps, bool reuse, bool stability,
                        const DieContact* die = nullptr) {
  SteppingSettings solver;
  solver.steps = steps;
  solver.max_step = 1.0 / steps;  // equal steps with and without reuse
  solver.newton.rtol = kRtol;
  solver.newton.atol = 1e-14;
  solver.newton.reuse_factor = reuse;
  LoadStepper stepper(model, solver);
  if (stability) stepper.set_stability({.check = true});
  SteppedRun run;
  const SteppingResult result = stepper.run(
      [&](const StepInfo& info) {
        StepRecord r;
        r.state = model.state();
        r.newton_iterations = info.newton_iterations;
        r.reused_solves = info.reused_solves;
        r.start_norm = info.reference_norm;
        r.final_norm = info.residual_norm;
        if (die) r.die_force = die->force_on_die(info.time, model.state()).z();
        run.steps.push_back(std::move(r));
      },
      [](const std::string&) {});
  run.completed = result.completed;
  run.newton_iterations = result.newton_iterations;
  run.reused_solves = result.reused_solves;
  return run;
}

/// max_i |a_i - b_i| / max_i |b_i|.
double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  return diff / scale;
}

/// The bottom of `mesh` fixed, its top moved by `top` (both ramped over t in [0, 1]).
std::vector<ConstrainedComponent> bottom_fixed_top_moved(const Mesh& mesh, const Vec3d& top) {
  std::vector<ConstrainedComponent> constraints = fixed(mesh, "bottom", Vec3d::Zero());
  const auto moved = fixed(mesh, "top", top);
  constraints.insert(constraints.end(), moved.begin(), moved.end());
  return constraints;
}

/// The neo-Hookean cube (c1 = 0.5) under `constraints`, solved by one NewtonSolver at each of
/// `times` in turn; the last solve's result, and the state it reached in `state`.
NewtonResult solve_cube_at(const Mesh& mesh, const std::vector<ConstrainedComponent>& constraints,
                           bool reuse, double rtol, const std::vector<double>& times,
                           std::vector<double>& state,
                           int krylov_iterations = NewtonSettings{}.reuse_krylov_iterations) {
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 0.0, constraints, {});
  NewtonSettings settings;
  settings.rtol = rtol;
  settings.atol = 1e-14;
  settings.reuse_factor = reuse;
  settings.reuse_krylov_iterations = krylov_iterations;
  NewtonSolver newton(model, settings);
  NewtonResult result;
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (k > 0) {
      EXPECT_TRUE(result.converged) << "t = " << times[k - 1];
    }
    model.set_time(times[k]);
    result = newton.solve();
  }
  state = model.state();
  return result;
}

SteppedRun stretch_cube(bool reuse) {
  const Mesh mesh = unit_cube(4);
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 0.0,
                   bottom_fixed_top_moved(mesh, Vec3d(0.15, 0.075, 0.5)), {});
  return step_through(model, 10, reuse, /*stability=*/true);
}

TEST(FactorReuse, StretchedCubeSameStatesWithFewerFactorisations) {
  const SteppedRun plain = stretch_cube(false);
  const SteppedRun reused = stretch_cube(true);
  ASSERT_TRUE(plain.completed);
  ASSERT_TRUE(reused.completed);
  ASSERT_EQ(plain.steps.size(), reused.steps.size());
  EXPECT_EQ(plain.reused_solves, 0);
  EXPECT_GT(reused.reused_solves, 0);
  for (std::size_t s = 0; s < reused.steps.size(); ++s) {
    const StepRecord& r = reused.steps[s];
    std::printf("  step %2zu: plain %d iterations; reuse %d iterations + %d reused solves\n", s + 1,
                plain.steps[s].newton_iterations, r.newton_iterations, r.reused_solves);
    // The convergence test of a plain solve, from the step's predicted start.
    EXPECT_LE(r.final_norm, kRtol * r.start_norm) << "step " << s + 1;
    // States to the tolerance: a residual of 1e-8 of the step's moves the state by about that
    // fraction of the step's increment (well-conditioned cube), far below 1e-7 of the state.
    EXPECT_LT(relative_difference(r.state, plain.steps[s].state), 1e-7) << "step " << s + 1;
  }
  // Plain Newton factorises 2 or 3 times per step. Early steps change the tangent too much for
  // chord steps with the last state's factor (the first cuts the residual less than tenfold and
  // is refused): Krylov steps finish them; the later ones converge in chord steps (measured: 24
  // factorisations plain, 2 with reuse, in the first step from rest).
  std::printf(
      "stretched cube, 10 steps: %d factorisations plain, %d with reuse (+%d reused "
      "solves)\n",
      plain.newton_iterations, reused.newton_iterations, reused.reused_solves);
  EXPECT_LT(reused.newton_iterations, plain.newton_iterations);
}

SteppedRun press_block(bool reuse) {
  const Mesh mesh = unit_cube(3);
  DieContactSettings settings;
  settings.name = "punch";
  settings.penalty = 30.0;
  settings.tolerance = 1e-6;
  std::vector<std::unique_ptr<ModelTerm>> terms;
  terms.push_back(std::make_unique<DieContact>(
      mesh,
      DieGeometry(DieShape::plane, Vec3d(0, 0, 1), Vec3d(0, 0, -1), Vec3d::UnitZ(), 0.0,
                  Vec3d(0, 0, -0.1), Ramp{0.0, 1.0}),
      settings, outward_triangles(mesh, "top")));
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 0.0,
                   fixed(mesh, "bottom", Vec3d::Zero()), std::move(terms));
  const auto* die = dynamic_cast<const DieContact*>(model.terms().front().get());
  return step_through(model, 4, reuse, /*stability=*/false, die);
}

TEST(FactorReuse, ContactMultiplierUpdatesReuseTheFactorAndGiveTheSameForces) {
  const SteppedRun plain = press_block(false);
  const SteppedRun reused = press_block(true);
  ASSERT_TRUE(plain.completed);
  ASSERT_TRUE(reused.completed);
  ASSERT_EQ(plain.steps.size(), reused.steps.size());
  EXPECT_GT(reused.reused_solves, 0);
  for (std::size_t s = 0; s < reused.steps.size(); ++s) {
    const StepRecord& r = reused.steps[s];
    EXPECT_LE(r.final_norm, kRtol * r.start_norm) << "step " << s + 1;
    EXPECT_NEAR(r.die_force, plain.steps[s].die_force, 1e-6 * std::abs(plain.steps[s].die_force))
        << "step " << s + 1;
    EXPECT_LT(relative_difference(r.state, plain.steps[s].state), 1e-6) << "step " << s + 1;
  }
  std::printf(
      "pressed block, 4 steps: %d factorisations plain, %d with reuse (+%d reused solves)\n",
      plain.newton_iterations, reused.newton_iterations, reused.reused_solves);
  EXPECT_LT(reused.newton_iterations, plain.newton_iterations);
}

/// The cube solved at 10 % of a stretch and shear, then at `to` in one step, plainly and with
/// reuse (the 10 % solve's factor at hand for the second).
struct Jump {
  NewtonResult plain, reused;
  std::vector<double> plain_state, reused_state;
};

Jump jump_from_tenth(double to, int krylov_iterations) {
  const Mesh mesh = unit_cube(4);
  const auto constraints = bottom_fixed_top_moved(mesh, Vec3d(0.3, 0.15, 0.4));
  Jump j;
  j.plain = solve_cube_at(mesh, constraints, false, kRtol, {0.1, to}, j.plain_state);
  j.reused =
      solve_cube_at(mesh, constraints, true, kRtol, {0.1, to}, j.reused_state, krylov_iterations);
  return j;
}

/// Both converged by the plain solve's test from the same start ("same" to what the 10 % solves
/// leave, rtol 1e-8 each on its own path) and to the same answer within what the test leaves.
void expect_the_plain_answer(const Jump& j) {
  ASSERT_TRUE(j.plain.converged);
  ASSERT_TRUE(j.reused.converged);
  EXPECT_NEAR(j.reused.residual_history.front(), j.plain.residual_history.front(),
              1e-6 * j.plain.residual_history.front());
  EXPECT_LE(j.reused.residual_norm, kRtol * j.reused.residual_history.front());
  EXPECT_LT(relative_difference(j.reused_state, j.plain_state), 1e-7);
}

TEST(FactorReuse, AFactorFarFromTheSolutionIsLeftToNewton) {
  // The whole motion in one step, no Krylov steps: the chord step is the whole reuse here.
  const Jump j = jump_from_tenth(1.0, 0);
  expect_the_plain_answer(j);
  // The old factor was tried and refused at once: a tenfold cut from the 10 % state's tangent
  // is out of reach for a jump to 100 %. Newton then starts from the same state as the plain
  // solve, with its own first tangent: the same first iterate (the refused trial left no trace).
  ASSERT_GE(j.reused.residual_history.size(), 2u);
  EXPECT_NEAR(j.reused.residual_history[1], j.plain.residual_history[1],
              1e-6 * j.plain.residual_history[1]);
  EXPECT_LE(j.reused.iterations, j.plain.iterations);
  EXPECT_EQ(j.reused.krylov_steps, 0);
}

TEST(FactorReuse, KrylovStepsFinishWithAFactorTooFarForChordSteps) {
  // 40 % in one step: a chord step with the 10 % factor cuts ||R|| less than tenfold (the
  // tangent moved), so the solve goes on in Krylov steps, GMRES on the new tangent
  // preconditioned by the old factor, and needs no factorisation at all.
  const Jump j = jump_from_tenth(0.4, NewtonSettings{}.reuse_krylov_iterations);
  expect_the_plain_answer(j);
  const NewtonResult& krylov = j.reused;
  std::printf("  plain Newton: %d iterations;", j.plain.iterations);
  for (double r : j.plain.residual_history) std::printf(" %.3e", r);
  std::printf("\n  reuse: %d iterations, %d Krylov steps, %d reused solves;", krylov.iterations,
              krylov.krylov_steps, krylov.reused_solves);
  for (double r : krylov.residual_history) std::printf(" %.3e", r);
  std::printf("\n");
  EXPECT_EQ(krylov.iterations, 0);
  EXPECT_GE(krylov.krylov_steps, 1);
  // The refused chord step (one solve) and at least one GMRES iteration per Krylov step.
  EXPECT_GT(krylov.reused_solves, krylov.krylov_steps);
  // A Krylov step is Newton's step up to GMRES's relative residual 1e-3: from the same start it
  // leaves the residual of Newton's full step within 1e-3 of the start's (plain Newton takes
  // the full step here: its line search accepts lambda = 1 when the residual falls enough).
  ASSERT_GE(krylov.residual_history.size(), 2u);
  ASSERT_GE(j.plain.residual_history.size(), 2u);
  EXPECT_NEAR(krylov.residual_history[1], j.plain.residual_history[1],
              1e-3 * j.plain.residual_history[0]);
  // Newton's rate: no more steps than plain Newton's iterations.
  EXPECT_LE(krylov.krylov_steps, j.plain.iterations);
}

TEST(FactorReuse, KrylovStepsGMRESCannotFinishAreLeftToNewton) {
  // One GMRES iteration per Krylov step cannot solve the whole jump's system to 1e-3: Newton
  // takes over from the same state, with the plain solve's test and answer.
  const Jump j = jump_from_tenth(1.0, 1);
  expect_the_plain_answer(j);
  EXPECT_EQ(j.reused.krylov_steps, 0);
  // The refused chord step and the one GMRES iteration, then Newton's own chord steps.
  EXPECT_GE(j.reused.reused_solves, 2);
  EXPECT_GT(j.reused.iterations, 0);
}

TEST(FactorReuse, NewtonKeepsItsFactorWhileItContractsTenfold) {
  // One solve from rest, no factor at hand: after the first Newton iteration cuts ||R|| tenfold,
  // the following ones keep its factor (chord steps) for as long as each cuts ||R|| tenfold.
  const Mesh mesh = unit_cube(4);
  const auto constraints = bottom_fixed_top_moved(mesh, Vec3d(0.06, 0.03, 0.1));
  std::vector<double> plain_state, chord_state;
  const NewtonResult plain = solve_cube_at(mesh, constraints, false, 1e-10, {1.0}, plain_state);
  const NewtonResult chord = solve_cube_at(mesh, constraints, true, 1e-10, {1.0}, chord_state);
  ASSERT_TRUE(plain.converged);
  ASSERT_TRUE(chord.converged);
  EXPECT_EQ(plain.reused_solves, 0);
  EXPECT_GT(chord.reused_solves, 0);
  EXPECT_LT(chord.iterations, plain.iterations);
  // Every solve, with a new factor or a kept one, is one entry of the residual history.
  EXPECT_EQ(static_cast<int>(chord.residual_history.size()),
            1 + chord.iterations + chord.reused_solves);
  // The same test as the plain solve, from the same start, and the same answer within what the
  // tolerance leaves (the plain solve stops within 1e-10 of the start's residual as well).
  EXPECT_EQ(chord.residual_history.front(), plain.residual_history.front());
  EXPECT_LE(chord.residual_norm, 1e-10 * chord.residual_history.front());
  EXPECT_LT(relative_difference(chord_state, plain_state), 1e-8);
  // The residual falls at every iterate: a chord step is taken only after a tenfold cut, and its
  // line search still asks for a decrease.
  for (std::size_t k = 1; k < chord.residual_history.size(); ++k)
    EXPECT_LT(chord.residual_history[k], chord.residual_history[k - 1]) << "iterate " << k;
}

}  // namespace
}  // namespace plisse
