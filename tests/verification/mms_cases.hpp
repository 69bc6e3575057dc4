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
/// table and asserts the rates between the two finest levels, and that every error falls at every
/// refinement. Optimal rates: MINI (P1 displacement, P1 pressure) 2, 1, 1 for u in L2, u in H1
/// and p in L2, asserted as >= 1.9, 0.9, 0.9; Taylor-Hood (P2, P1) 3, 2, 2, asserted as >= 2.8,
/// 1.85, 1.8 (the margins are those of a still slightly pre-asymptotic pair of levels).
inline void expect_optimal_rates(const std::string& title, const MmsProblem& problem,
                                 const std::vector<int>& divisions) {
  const bool p2 = problem.element == ElementFamily::taylor_hood;
  const double u_L2_rate = p2 ? 2.8 : 1.9, u_H1_rate = p2 ? 1.85 : 0.9, p_L2_rate = p2 ? 1.8 : 0.9;
  std::vector<MmsLevel> levels;
  for (int n : divisions) {
    levels.push_back(solve_manufactured(problem, n));
    ASSERT_TRUE(levels.back().converged) << title << ": Newton did not converge on n = " << n;
  }
  std::cout << convergence_table(title, levels);
  const std::size_t last = levels.size() - 1;
  EXPECT_GE(observed_rate(levels, last, &FieldErrors::u_L2), u_L2_rate) << title;
  EXPECT_GE(observed_rate(levels, last, &FieldErrors::u_H1), u_H1_rate) << title;
  EXPECT_GE(observed_rate(levels, last, &FieldErrors::p_L2), p_L2_rate) << title;
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

/// The same problem on second-order meshes with the Taylor-Hood element.
inline MmsProblem with_taylor_hood(MmsProblem problem) {
  problem.element = ElementFamily::taylor_hood;
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
