// `solver.newton.linear`: the linear solver of the Newton iterations (direct MUMPS or iterative
// FGMRES + field split), its defaults, `--set` overrides and every error path.
#include <gtest/gtest.h>

#include "case_test_util.hpp"

namespace plisse {
namespace {

using test::case_error;
using test::kMinimalCase;

/// kMinimalCase (lines 1-2), then `solver:` (3), `  newton:` (4), `    linear: <value>` (5).
std::string with_linear(const std::string& value) {
  return kMinimalCase + "solver:\n  newton:\n    linear: " + value + "\n";
}

TEST(CaseLinearSolver, DefaultIsDirect) {
  const Case c = parse_case_string(kMinimalCase, "case.yaml");
  const LinearSolverSettings& l = c.solver.newton.linear;
  EXPECT_EQ(l.type, LinearSolverType::direct);
  EXPECT_EQ(l.rtol, 1e-6);
  EXPECT_EQ(l.max_iterations, 1000);
  EXPECT_EQ(l.restart, 50);
  EXPECT_EQ(l.place.line, 0);
  // An empty map or a null value keeps the defaults, like any empty section.
  EXPECT_EQ(parse_case_string(with_linear("{}"), "case.yaml").solver.newton.linear.type,
            LinearSolverType::direct);
  EXPECT_EQ(parse_case_string(with_linear("~"), "case.yaml").solver.newton.linear.type,
            LinearSolverType::direct);
  EXPECT_EQ(parse_case_string(with_linear("{type: direct}"), "case.yaml").solver.newton.linear.type,
            LinearSolverType::direct);
}

TEST(CaseLinearSolver, IterativeWithItsSettings) {
  const Case c = parse_case_string(
      with_linear("{type: iterative, rtol: 1.0e-8, max_iterations: 300, restart: 80}"),
      "case.yaml");
  const LinearSolverSettings& l = c.solver.newton.linear;
  EXPECT_EQ(l.type, LinearSolverType::iterative);
  EXPECT_EQ(l.rtol, 1e-8);
  EXPECT_EQ(l.max_iterations, 300);
  EXPECT_EQ(l.restart, 80);
  EXPECT_EQ(l.place.line, 5);
  EXPECT_EQ(l.place.key, "solver.newton.linear");
  // Block style, beside the other Newton keys; unset iterative keys take their defaults.
  const Case block = parse_case_string(kMinimalCase +
                                           "solver:\n"
                                           "  newton:\n"
                                           "    rtol: 1.0e-9\n"
                                           "    linear:\n"
                                           "      type: iterative\n"
                                           "      restart: 30\n",
                                       "case.yaml");
  EXPECT_EQ(block.solver.newton.rtol, 1e-9);
  EXPECT_EQ(block.solver.newton.linear.type, LinearSolverType::iterative);
  EXPECT_EQ(block.solver.newton.linear.restart, 30);
  EXPECT_EQ(block.solver.newton.linear.rtol, 1e-6);
  EXPECT_EQ(block.solver.newton.linear.max_iterations, 1000);
}

TEST(CaseLinearSolver, SetOverrides) {
  const Case c = parse_case_string(
      kMinimalCase, "case.yaml",
      {"solver.newton.linear.type=iterative", "solver.newton.linear.rtol=1e-4",
       "solver.newton.linear.max_iterations=50", "solver.newton.linear.restart=20"});
  const LinearSolverSettings& l = c.solver.newton.linear;
  EXPECT_EQ(l.type, LinearSolverType::iterative);
  EXPECT_EQ(l.rtol, 1e-4);
  EXPECT_EQ(l.max_iterations, 50);
  EXPECT_EQ(l.restart, 20);
  // Back to direct from a case that asks for the iterative solver.
  EXPECT_EQ(parse_case_string(with_linear("{type: iterative}"), "case.yaml",
                              {"solver.newton.linear.type=direct"})
                .solver.newton.linear.type,
            LinearSolverType::direct);
  // Errors in an override are placed at --set.
  EXPECT_INPUT_ERROR(case_error(kMinimalCase, {"solver.newton.linear.type=iterative",
                                               "solver.newton.linear.restart=0"}),
                     "--set", 0, 0, "solver.newton.linear.restart", "must be >= 1 (got 0)");
  EXPECT_INPUT_ERROR(case_error(kMinimalCase, {"solver.newton.linear.type=gmres"}), "--set", 0, 0,
                     "solver.newton.linear.type", "must be one of: direct, iterative");
}

TEST(CaseLinearSolver, Errors) {
  EXPECT_INPUT_ERROR(case_error(with_linear("{type: gmres}")), "case.yaml", 5, 20,
                     "solver.newton.linear.type", "must be one of: direct, iterative");
  EXPECT_INPUT_ERROR(case_error(with_linear("{type: iterative, rtol: 0}")), "case.yaml", 5, 37,
                     "solver.newton.linear.rtol", "(got 0)");
  EXPECT_INPUT_ERROR(case_error(with_linear("{type: iterative, rtol: 1}")), "case.yaml", 5, 37,
                     "solver.newton.linear.rtol", "(got 1)");
  EXPECT_INPUT_ERROR(case_error(with_linear("{type: iterative, rtol: -1e-6}")), "case.yaml", 5, 37,
                     "solver.newton.linear.rtol", "(got -1e-06)");
  EXPECT_INPUT_ERROR(case_error(with_linear("{type: iterative, max_iterations: 0}")), "case.yaml",
                     5, 47, "solver.newton.linear.max_iterations", "must be >= 1 (got 0)");
  EXPECT_INPUT_ERROR(case_error(with_linear("{type: iterative, max_iterations: 2.5}")), "case.yaml",
                     5, 47, "solver.newton.linear.max_iterations", "integer");
  EXPECT_INPUT_ERROR(case_error(with_linear("{type: iterative, restart: -3}")), "case.yaml", 5, 40,
                     "solver.newton.linear.restart", "must be >= 1 (got -3)");
  EXPECT_INPUT_ERROR(case_error(with_linear("{type: iterative, rtol: .nan}")), "case.yaml", 5, 37,
                     "solver.newton.linear.rtol", "");
  // The iterative solver's keys do not apply to the direct one (they would be silently unused).
  EXPECT_INPUT_ERROR(case_error(with_linear("{type: direct, rtol: 1e-6}")), "case.yaml", 5, 28,
                     "solver.newton.linear.rtol", "'rtol' does not apply to type 'direct'");
  EXPECT_INPUT_ERROR(case_error(with_linear("{restart: 30}")), "case.yaml", 5, 14,
                     "solver.newton.linear.restart", "'restart' does not apply to type 'direct'");
  // Unknown keys, with a suggestion.
  const InputError typo = case_error(with_linear("{type: iterative, max_iteration: 10}"));
  EXPECT_INPUT_ERROR(typo, "case.yaml", 5, 31, "solver.newton.linear.max_iteration",
                     "did you mean 'max_iterations'?");
  // Not a map.
  EXPECT_INPUT_ERROR(case_error(with_linear("iterative")), "case.yaml", 5, 13,
                     "solver.newton.linear", "");
  EXPECT_INPUT_ERROR(case_error(with_linear("[iterative]")), "case.yaml", 5, 13,
                     "solver.newton.linear", "");
}

}  // namespace
}  // namespace plisse
