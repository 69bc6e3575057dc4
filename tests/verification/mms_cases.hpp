#pragma once
/// The two manufactured-solution cases and the rate check shared by the fast and the slow
/// convergence tests (docs/verification/mms.md).
#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

#include "verification/fixtures/mms_problem.hpp"

namespace plisse::test {

/// Solves on the cube with each number of divisions (h halved each time), prints the convergence
/// table and asserts the rates between the two finest levels: u L2 >= 1.9, u H1 >= 0.9, p L2 >= 0.9
/// (optimal: 2, 1, 1), and that every error falls at every refinement.
inline void expect_optimal_rates(const std::string& title, const MmsProblem& problem,
                                 const std::vector<int>& divisions) {
  std::vector<MmsLevel> levels;
  for (int n : divisions) {
    levels.push_back(solve_manufactured(problem, n));
    ASSERT_TRUE(levels.back().converged) << title << ": Newton did not converge on n = " << n;
  }
  std::cout << convergence_table(title, levels);
  const std::size_t last = levels.size() - 1;
  EXPECT_GE(observed_rate(levels, last, &FieldErrors::u_L2), 1.9) << title;
  EXPECT_GE(observed_rate(levels, last, &FieldErrors::u_H1), 0.9) << title;
  EXPECT_GE(observed_rate(levels, last, &FieldErrors::p_L2), 0.9) << title;
  // The errors fall at every refinement (no pre-asymptotic growth hidden by the last pair).
  for (std::size_t i = 1; i <= last; ++i) {
    EXPECT_LT(levels[i].errors.u_L2, levels[i - 1].errors.u_L2) << title << ", level " << i;
    EXPECT_LT(levels[i].errors.u_H1, levels[i - 1].errors.u_H1) << title << ", level " << i;
    EXPECT_LT(levels[i].errors.p_L2, levels[i - 1].errors.p_L2) << title << ", level " << i;
  }
}

inline MmsProblem exact_incompressible_neo_hookean() {
  MmsProblem problem;
  problem.material = make_material("neo-hookean", {{"c1", 0.5}});  // mu = 1 MPa
  problem.inverse_bulk_modulus = 0.0;
  problem.solution.epsilon = 0.0;  // J = 1 exactly
  return problem;
}

inline MmsProblem near_incompressible_mooney_rivlin() {
  MmsProblem problem;
  problem.material = make_material("mooney-rivlin", {{"c1", 0.4}, {"c2", 0.1}});  // mu = 1 MPa
  problem.inverse_bulk_modulus = 1.0 / 100.0;                                     // kappa = 100 mu
  problem.solution.epsilon = 0.02;  // J - 1 up to about 0.06
  return problem;
}

}  // namespace plisse::test
