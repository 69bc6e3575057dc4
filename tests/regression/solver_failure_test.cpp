// Requirement: when the step cannot be cut further, plisse stops with exit status 1, a diagnostic
// naming the step, the worst element and the reason, and the last converged state written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "output/history_writer.hpp"
#include "output/json_file.hpp"
#include "output/pvd_writer.hpp"
#include "output/vtu_reader.hpp"
#include "support/run_case.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

/// A case given as YAML text, written to `name`'s scratch directory as case.yaml and run by the
/// built plisse into its run/: the exit status, what plisse printed (log.txt) and the directory.
struct CaseRun {
  int status = -1;
  std::string log;
  std::filesystem::path dir;
};
CaseRun run_yaml(const std::string& name, const std::string& yaml) {
  const auto dir = test::scratch_directory(name);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "case.yaml") << yaml;
  const int status = test::run_plisse(
      "run " + (dir / "case.yaml").string() + " -o " + (dir / "run").string(), dir / "log.txt");
  std::ifstream in(dir / "log.txt");
  return {status, std::string((std::istreambuf_iterator<char>(in)), {}), dir};
}

/// The example `example` (a file of examples/) run by the built plisse into `name`'s scratch
/// directory with the command-line `options`: the exit status and what plisse printed.
CaseRun run_example(const std::string& name, const std::string& example,
                    const std::string& options) {
  const auto dir = test::scratch_directory(name);
  const int status = test::run_plisse("run " + std::string(PLISSE_SOURCE_DIR) + "/examples/" +
                                          example + " -o " + dir.string() + " " + options,
                                      dir.string() + ".log");
  std::ifstream in(dir.string() + ".log");
  return {status, std::string((std::istreambuf_iterator<char>(in)), {}), dir};
}

TEST(SolverFailure, StopsWithExitStatus1AndNamesStepElementAndReason) {
  const auto dir = test::scratch_directory("solver-failure");
  const std::string case_file =
      std::string(PLISSE_SOURCE_DIR) + "/tests/regression/failure-case.yaml";
  const int status =
      test::run_plisse("run " + case_file + " -o " + dir.string(), dir.string() + ".log");
  EXPECT_EQ(status, 1);
  std::ifstream in(dir.string() + ".log");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("solver failure"), std::string::npos) << text;
  EXPECT_NE(text.find("step "), std::string::npos) << text;
  EXPECT_NE(text.find("worst element"), std::string::npos) << text;
  EXPECT_NE(text.find("below the minimum"), std::string::npos) << text;
  // Step sizes in significant digits, not six decimals (a small minimum read "0.000000").
  EXPECT_EQ(text.find("0.000000"), std::string::npos) << text;
  const auto summary = read_json_file(dir / "summary.json");
  EXPECT_FALSE(summary["completed"].get<bool>());
  EXPECT_NE(summary["failure"].get<std::string>().find("worst element"), std::string::npos);
  // Whatever converged before the failure is in the run directory.
  const HistoryTable h = read_history(dir / "history.csv");
  if (!h.rows.empty()) {
    EXPECT_TRUE(std::filesystem::exists(dir / "step_0001.vtu"));
  }
}

// A shell whose Newton iterate is inadmissible: the party balloon's fourfold volume in one step
// with full Newton steps. A shell triangle has no det F to name (J = 1, exactly incompressible):
// the failure says what a shell's refusal means, the triangle and no J.
TEST(SolverFailure, AnInadmissibleShellTriangleIsNamedAsSuch) {
  const CaseRun r = run_example("shell-inadmissible", "shell-balloon.yaml",
                                "--set solver.steps=1 --set solver.max_step=1 --set "
                                "solver.min_step=1 --set solver.newton.line_search=basic");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.log.find("a shell triangle collapsed, or its wall folded tighter than half its "
                       "thickness; worst element"),
            std::string::npos)
      << r.log;
  EXPECT_EQ(r.log.find("an element inverted"), std::string::npos) << r.log;
  EXPECT_EQ(r.log.find("min J"), std::string::npos) << r.log;
}

// A tolerance below what round-off lets Newton reach: the homogeneous cube converges to the
// round-off floor of its residual (about 1e-15 of its start) and the line search then finds no
// lower one. The failure says so and what to change, not that the step was too large (the
// message for a line search that keeps shortening full steps from the start). The tolerance,
// 1e-17, is below double precision's relative resolution (1.1e-16): an rtol of 1e-15 lies at the
// floor itself, which some machines' BLAS kernels reached on this cube and others did not.
TEST(SolverFailure, AToleranceBelowTheRoundOffFloorIsNamedAsSuch) {
  const CaseRun r = run_example(
      "round-off-floor", "cube-tension-neo-hookean.yaml",
      "--set solver.newton.rtol=1e-17 --set solver.newton.atol=0 --set solver.min_step=0.5");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.log.find("round-off floor of this problem lies above its tolerance"),
            std::string::npos)
      << r.log;
  EXPECT_NE(r.log.find("a looser solver.newton.rtol or atol"), std::string::npos) << r.log;
  EXPECT_EQ(r.log.find("a small load carried in bending"), std::string::npos) << r.log;
}

// Requirement: a run that stops before its end writes its last converged step with the step
// velocity v = (u_n - u_{n-1}) / dt of that step. Cube tension with the top pulled 20 mm along a
// linear ramp over 1 s: the deformation is homogeneous with u_z = 4 t Z, linear in time, so
// v_z = u_z / t exactly at every node. Two steps of 0.3 s at most: the run stops at t = 0.6 when
// it reaches solver.max_steps, and output.every is too large for any step to be written before.
TEST(SolverFailure, LastStepOfAStoppedRunCarriesItsStepVelocity) {
  const auto dir = test::scratch_directory("stopped-velocity");
  const std::string case_file =
      std::string(PLISSE_SOURCE_DIR) + "/examples/cube-tension-neo-hookean.yaml";
  const int status = test::run_plisse(
      "run " + case_file + " -o " + dir.string() +
          " --set solver.steps=2 --set solver.max_steps=2 --set solver.max_step=0.3"
          " --set output.every=100",
      dir.string() + ".log");
  ASSERT_EQ(status, 1);
  const auto summary = read_json_file(dir / "summary.json");
  ASSERT_EQ(summary["steps"].get<int>(), 2);
  const double t = summary["final_time"].get<double>();
  const VtuField u = read_vtu_point_field(dir / "step_0002.vtu", "displacement");
  const VtuField v = read_vtu_point_field(dir / "step_0002.vtu", "velocity");
  ASSERT_EQ(u.values.size(), v.values.size());
  double largest = 0.0;
  for (std::size_t i = 2; i < u.values.size(); i += 3) {
    EXPECT_NEAR(v.values[i], u.values[i] / t, 1e-8 * (1.0 + std::abs(u.values[i] / t)))
        << "value " << i;
    largest = std::max(largest, std::abs(v.values[i]));
  }
  EXPECT_NEAR(largest, 20.0, 1e-8);  // the top moves at 20 mm/s
}

// Requirement: plisse judges convergence itself. -snes_type ksponly makes PETSc take one linear
// step and report CONVERGED_ITS without any residual test; before, such a run "completed" with
// states that were not equilibria. Now no step is accepted and the run stops naming the reason.
TEST(SolverFailure, APetscOptionThatSkipsTheResidualTestCannotConvergeAStep) {
  const auto dir = test::scratch_directory("solver-ksponly");
  const auto r = test::run_plisse_captured("run " + test::example("cube-tension-neo-hookean.yaml") +
                                           " --set solver.steps=2 -o " + dir.string() +
                                           " --petsc '-snes_type ksponly'");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("without plisse's residual test"), std::string::npos) << r.output;
  EXPECT_TRUE(read_history(dir / "history.csv").rows.empty());
  EXPECT_FALSE(read_json_file(dir / "summary.json")["completed"].get<bool>());
}

TEST(SolverFailure, OutOfMemoryInTheFactorisationStopsAtOnceAndSaysSo) {
  // MUMPS may use 3 MB of working memory (ICNTL(23)): the first factorisation is refused with
  // INFOG(1) = -19, as a full machine refuses an allocation with -13. A cut-back needs the same
  // factor, so the run stops at once, says "out of memory" and how much, and keeps step 0.
  const auto dir = test::scratch_directory("solver-out-of-memory");
  const auto r =
      test::run_plisse_captured("run " + test::example("sphere-inflation.yaml") + " -o " +
                                dir.string() + " --petsc '-mat_mumps_icntl_23 3'");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("step 1: out of memory: the factorisation of the tangent needs "),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("(ICNTL(23); MUMPS INFOG(1) = -19)"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("cutting the step"), std::string::npos) << r.output;
  const nlohmann::json summary = read_json_file(dir / "summary.json");
  EXPECT_EQ(summary["cutbacks"].get<int>(), 0);
  EXPECT_FALSE(summary["completed"].get<bool>());
  EXPECT_NE(summary["failure"].get<std::string>().find("out of memory"), std::string::npos);
}

TEST(SolverFailure, AFactorWorkspaceThatProvesTooSmallIsGrownAndTheStepGoesOn) {
  // The strip with a rigid end cap delays pivots beyond MUMPS's estimate: with no margin
  // (ICNTL(14) = 0) the factorisation fails with INFOG(1) = -9. plisse doubles the margin (to
  // 40 %) and factorises again: the same history as with the default margin, no cut-back.
  const std::string strip =
      std::string(PLISSE_SOURCE_DIR) + "/tests/regression/cases/strip-loads.yaml";
  const auto plain = test::scratch_directory("solver-workspace-default");
  const auto grown = test::scratch_directory("solver-workspace-grown");
  ASSERT_EQ(test::run_plisse_captured("run " + strip + " -o " + plain.string()).status, 0);
  const auto r = test::run_plisse_captured("run " + strip + " -o " + grown.string() +
                                           " --petsc '-mat_mumps_icntl_14 0'");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("step 1: the factorisation needed more working memory than MUMPS "
                          "estimated (INFOG(1) = -9): its margin ICNTL(14) is now 40 %"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(read_json_file(grown / "summary.json")["cutbacks"].get<int>(), 0);
  const HistoryTable a = read_history(plain / "history.csv"),
                     b = read_history(grown / "history.csv");
  ASSERT_EQ(a.columns, b.columns);
  ASSERT_EQ(a.rows.size(), b.rows.size());
  for (std::size_t i = 0; i < a.rows.size(); ++i)
    for (std::size_t k = 0; k < a.columns.size(); ++k)
      if (a.columns[k] != "residual_norm" && a.columns[k] != "newton_iterations") {
        EXPECT_NEAR(a.rows[i][k], b.rows[i][k], 1e-10 * (1.0 + std::abs(a.rows[i][k])))
            << a.columns[k] << ", step " << i + 1;
      }
}

}  // namespace
}  // namespace plisse

namespace plisse {
namespace {

// Requirement: a load beyond the body's limit load stops the run at the load it could not raise,
// says so with that load factor, and keeps it in summary.json. A neo-Hookean thin shell sphere
// (R = 100 mm, t = 0.1 mm, c1 = 0.1 MPa, octant) under a follower pressure ramped to 3e-4 MPa,
// past its maximum p_max = 4 c1 (t/R)(1/l - 1/l^7) at l = 7^(1/6), 2.4789e-4 MPa (the thin-shell
// closed form of examples/shell-balloon.yaml): the run stops at the load factor p_max / 3e-4 =
// 0.8263 of the closed form, within 3e-3 above it (the discrete shell's maximum on elements of
// 10 mm: measured 1.5e-3 above) and 5e-3 below (the last step that converged before it). The
// pressure reached is named in the log and summary.json.
TEST(SolverFailure, ALoadPastTheLimitLoadStopsNamingTheLoadReached) {
  const CaseRun run =
      run_yaml("limit-load",
               "element: shell\n"
               "mesh: {generate: spherical-shell, inner_radius: 99.95, thickness: 0.1,"
               " element_size: 10.0, symmetry: octant}\n"
               "material: {model: neo-hookean, c1: 0.1}\n"
               "boundary:\n"
               "  - {type: symmetry, surface: sym_x}\n"
               "  - {type: symmetry, surface: sym_y}\n"
               "  - {type: symmetry, surface: sym_z}\n"
               "loads: [{type: pressure, name: p, surface: inner, value: 3.0e-4}]\n"
               "solver: {steps: 10, min_step: 1.0e-4, stability: {check: true}}\n");
  EXPECT_EQ(run.status, 1);
  const std::string& text = run.log;
  const std::filesystem::path& dir = run.dir;
  EXPECT_NE(text.find("the load could not be raised past load factor"), std::string::npos) << text;
  EXPECT_NE(text.find("prescribe a displacement instead"), std::string::npos) << text;
  const auto summary = read_json_file(dir / "run" / "summary.json");
  ASSERT_TRUE(summary.contains("limit")) << summary.dump();
  const double reached = summary["limit"]["load_factor"].get<double>();
  const double l = std::pow(7.0, 1.0 / 6.0);
  const double limit = 4.0 * 0.1 * (0.1 / 100.0) * (1.0 / l - std::pow(l, -7.0)) / 3.0e-4;
  std::printf("load factor reached %.6f, thin-shell limit %.6f (%.1e)\n", reached, limit,
              reached / limit - 1.0);
  EXPECT_LE(reached, limit * (1.0 + 3e-3));
  EXPECT_GE(reached, limit * (1.0 - 5e-3));
  // The last converged step, which history.csv ends with (its column 1 is the time), and the
  // pressure there, which the log and summary.json name: the load factor times 3e-4 MPa.
  const HistoryTable h = read_history(dir / "run" / "history.csv");
  ASSERT_FALSE(h.rows.empty());
  EXPECT_DOUBLE_EQ(h.rows.back()[1], summary["limit"]["time"].get<double>());
  ASSERT_TRUE(summary["limit"]["loads"].contains("pressure:p")) << summary.dump();
  const double pressure = summary["limit"]["loads"]["pressure:p"].get<double>();
  EXPECT_NEAR(pressure, reached * 3.0e-4, 1e-12);
  EXPECT_DOUBLE_EQ(pressure, h.rows.back()[test::history_column(h, "pressure:p")]);
  char named[64];
  std::snprintf(named, sizeof named, "; there pressure:p = %.6g. If", pressure);
  EXPECT_NE(text.find(named), std::string::npos) << named << "\n" << text;
}

// Requirement: a Newton solve that fails because the back-tracking line search shortened nearly
// every step says so and names the line search that takes such steps. A shell strip (110 x 10 x
// 1 mm, clamped at x = 0, plane strain) under its weight from flat: the load (w/L ~ 1e-3) is
// carried in bending, and each full Newton step's second-order membrane forces raise the
// residual a hundredfold, so bt cuts every step (and the steps with it). With `line_search: cp`
// the same case converges in one step with at most 4 Newton iterations.
/// The shell strip of the tests below: 110 x 10 x 1 mm, clamped at x = 0, plane strain, under its
/// weight from flat, on cells of `element_size` mm; `solver` is the case's `solver:` line.
std::string strip_under_its_weight(const std::string& element_size, const std::string& solver) {
  return "element: shell\n"
         "mesh: {generate: sheet, length: 110.0, width: 10.0, thickness: 1.0, element_size: " +
         element_size +
         "}\n"
         "material: {model: neo-hookean, c1: 0.5, density: 2.5e-13}\n"
         "boundary:\n"
         "  - {type: clamped, surface: left}\n"
         "  - {type: symmetry, surface: front}\n"
         "  - {type: symmetry, surface: back}\n"
         "loads: [{type: gravity, name: g, acceleration: [0, 0, -9810]}]\n"
         "solver: " +
         solver + "\n";
}

TEST(SolverFailure, ALineSearchThatShortensEveryStepIsNamedWithItsRemedy) {
  const auto with = [](const std::string& line_search) {
    const CaseRun run = run_yaml(
        "line-search-" + line_search,
        strip_under_its_weight("2.5", "{steps: 1, newton: {line_search: " + line_search + "}}"));
    return std::pair{run.log, read_json_file(run.dir / "run" / "summary.json")};
  };
  const auto [bt_log, bt] = with("bt");
  EXPECT_NE(bt_log.find("each full Newton step raised the residual"), std::string::npos) << bt_log;
  EXPECT_NE(bt_log.find("solver.newton.line_search: cp"), std::string::npos) << bt_log;
  EXPECT_GT(bt["cutbacks"].get<int>(), 0);
  const auto [cp_log, cp] = with("cp");
  EXPECT_EQ(cp_log.find("each full Newton step raised the residual"), std::string::npos) << cp_log;
  EXPECT_TRUE(cp["completed"].get<bool>()) << cp_log;
  EXPECT_EQ(cp["steps"].get<int>(), 1);
  EXPECT_EQ(cp["cutbacks"].get<int>(), 0);
  EXPECT_LE(cp["newton_iterations"].get<int>(), 4);
}

// Requirement: solver.newton.stall_iterations gives a creeping Newton solve up early, and the
// run ends where it ends without it. The strip under its weight with bt (the test above) creeps:
// each attempt spends all 25 iterations, each cutting the residual by a few percent, before the
// step is cut back. With stall_iterations: 3 every failed attempt ends after 3 iterations and says
// why; the run takes fewer Newton iterations in all (each one a factorisation) and its last state
// is the plain run's within what two solves to rtol 1e-8 may differ by (1e-6 of the largest
// displacement; the two differed by 1.3e-7 of it).
TEST(SolverFailure, AStalledSolveIsGivenUpEarlyAndTheRunEndsInTheSameState) {
  const auto with = [](int stall) {
    const CaseRun run = run_yaml(
        "stall-" + std::to_string(stall),
        strip_under_its_weight("2.5", "{steps: 1, newton: {line_search: bt, stall_iterations: " +
                                          std::to_string(stall) + "}}"));
    EXPECT_EQ(run.status, 0) << run.log;
    return run;
  };
  const CaseRun plain = with(0), stalled = with(3);
  EXPECT_EQ(plain.log.find("stalled"), std::string::npos) << plain.log;
  EXPECT_NE(plain.log.find("failed after 25 iterations"), std::string::npos) << plain.log;
  // Every failed attempt of the stalled run ended after 3 iterations, and there was one.
  const std::string expected =
      "failed after 3 iterations: Newton did not converge (stalled: 3 iterations in a row";
  int attempts = 0;
  for (std::size_t at = stalled.log.find("failed after "); at != std::string::npos;
       at = stalled.log.find("failed after ", at + 1)) {
    ++attempts;
    EXPECT_EQ(stalled.log.compare(at, expected.size(), expected), 0) << stalled.log.substr(at, 200);
    // The crawl's remedy is named however few iterations the attempt took.
    const std::string line = stalled.log.substr(at, stalled.log.find('\n', at) - at);
    EXPECT_NE(line.find("solver.newton.line_search: cp"), std::string::npos) << line;
  }
  EXPECT_GT(attempts, 0) << stalled.log;
  const auto summary = [](const CaseRun& r) {
    return read_json_file(r.dir / "run" / "summary.json");
  };
  const int plain_iterations = summary(plain)["newton_iterations"].get<int>();
  const int stalled_iterations = summary(stalled)["newton_iterations"].get<int>();
  EXPECT_LT(2 * stalled_iterations, plain_iterations)
      << stalled_iterations << " against " << plain_iterations;
  const auto last_displacement = [](const CaseRun& r) {
    const auto run = r.dir / "run";
    return read_vtu_point_field(run / read_pvd(run / "solution.pvd").back().file, "displacement");
  };
  const VtuField a = last_displacement(plain), b = last_displacement(stalled);
  ASSERT_EQ(a.values.size(), b.values.size());
  double largest = 0.0, difference = 0.0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    largest = std::max(largest, std::abs(a.values[i]));
    difference = std::max(difference, std::abs(a.values[i] - b.values[i]));
  }
  EXPECT_GT(largest, 0.1);  // the tip sags 0.13 mm
  EXPECT_LT(difference, 1e-6 * largest);
}

// Requirement: the arc-length corrector gives a stalled solve up as load stepping does. The shell
// balloon with arc length, its corrector's tolerance 1e-17 (solver.newton.rtol, below double
// precision's resolution: it cannot be met) while load-controlled Newton keeps 1e-10 (PETSc's
// -snes_rtol, which only SNES reads): the first step converges, and every arc of the second
// reaches the residual's round-off floor and creeps there. Without stall_iterations each arc
// spends all 25 iterations; with 3, each ends a few iterations after reaching the floor and says
// why.
TEST(SolverFailure, TheArcLengthCorrectorGivesAStalledSolveUpEarly) {
  const auto arcs = [](int stall) {
    const CaseRun r = run_example(
        "arc-stall-" + std::to_string(stall), "shell-balloon-arc-length.yaml",
        "--set solver.newton.rtol=1e-17 --set solver.newton.atol=0 --set solver.min_step=0.01 "
        "--set solver.newton.stall_iterations=" +
            std::to_string(stall) + " --petsc '-snes_rtol 1e-10'");
    EXPECT_EQ(r.status, 1) << r.log;
    // "failed after N iterations: ..." of each arc cut back (the log's warnings)
    std::vector<std::string> attempts;
    std::istringstream lines(r.log);
    for (std::string line; std::getline(lines, line);) {
      const std::size_t failed = line.find("failed after ");
      if (line.rfind("warning:", 0) == 0 && line.find(": arc ") != std::string::npos &&
          failed != std::string::npos)
        attempts.push_back(line.substr(failed));
    }
    return attempts;
  };
  const auto plain = arcs(0), stalled = arcs(3);
  ASSERT_FALSE(plain.empty());
  ASSERT_FALSE(stalled.empty());
  for (const std::string& a : plain)
    EXPECT_EQ(a.rfind("failed after 25 iterations: Newton did not converge (no convergence in 25 "
                      "iterations",
                      0),
              0u)
        << a;
  for (const std::string& a : stalled) {
    int iterations = 0;
    ASSERT_EQ(std::sscanf(a.c_str(), "failed after %d iterations", &iterations), 1) << a;
    EXPECT_LT(iterations, 15) << a;
    EXPECT_NE(a.find("Newton did not converge (stalled: 3 iterations in a row"), std::string::npos)
        << a;
  }
}

// Requirement: a run in which no step converges from the start does not call the start a limit
// load. The shell strip under its weight, with the back-tracking line search and 8 iterations a
// step, fails every attempt (each full step raises the residual: see the test above); the
// message says that no step converged from the start and points to the attempts' reason.
TEST(SolverFailure, NoStepConvergedFromTheStartIsNotCalledALimitLoad) {
  const CaseRun run = run_yaml(
      "no-first-step",
      strip_under_its_weight("5.0",
                             "{steps: 1, min_step: 0.2, newton: {line_search: bt, rtol: 1.0e-10,"
                             " atol: 1.0e-15, max_iterations: 8}}"));
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.log.find("no step converged from the start"), std::string::npos) << run.log;
  EXPECT_EQ(run.log.find("this is its limit load"), std::string::npos) << run.log;
}

}  // namespace
}  // namespace plisse
