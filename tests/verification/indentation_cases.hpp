#pragma once
/// An indented block solved to a finite indentation with the real solver (MixedModel, LoadStepper,
/// NewtonSolver), and the smoothness check of its pressure (docs/verification/inf_sup.md, IS3-IS4).
///
/// Unit cube, exact incompressibility (neo-Hookean, mu = 1 MPa), bottom fixed, a rigid sticking
/// punch on the half x <= 1/2 of the top pressed down by kIndentation (nodes under it prescribed
/// (0, 0, -d)), sides and the other half of the top free. The punch edge x = 1/2 carries a pressure
/// singularity, the hardest place for spurious pressure modes to hide.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "mesh/generate.hpp"
#include "solver/load_stepper.hpp"
#include "verification/fixtures/saddle_point.hpp"

namespace plisse::test {

inline constexpr double kIndentation = 0.15;  ///< punch travel [mm], 15 % of the block height

struct IndentationLevel {
  int divisions = 0;
  bool completed = false;
  int steps = 0, newton_iterations = 0;
  double eta = 0.0;          ///< checkerboard indicator of the nodal pressure (IS3)
  double punch_force = 0.0;  ///< vertical reaction on the punch [N]
  double p_min = 0.0, p_max = 0.0;
};

inline IndentationLevel solve_indentation(int divisions) {
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.edge = 1.0;
  spec.divisions = divisions;
  const Mesh mesh = generate_mesh(spec);
  std::set<int> bottom, punch;
  for (int t : mesh.surface_tags.at("bottom"))
    for (int v : mesh.triangles[t]) bottom.insert(v);
  for (int t : mesh.surface_tags.at("top"))
    for (int v : mesh.triangles[t])
      if (mesh.nodes[v].x() <= 0.5 + 1e-12) punch.insert(v);
  std::vector<ConstrainedComponent> constraints;
  for (int v : bottom)
    for (int k = 0; k < 3; ++k) constraints.push_back({v, k, 0.0, Ramp{0.0, 1.0}});
  for (int v : punch)
    for (int k = 0; k < 3; ++k)
      constraints.push_back({v, k, k == 2 ? -kIndentation : 0.0, Ramp{0.0, 1.0}});
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 0.0, constraints);
  SteppingSettings settings;
  settings.steps = 4;
  settings.max_step = 0.25;
  settings.newton.rtol = 1e-10;
  settings.newton.atol = 1e-13;
  LoadStepper stepper(model, settings);
  const SteppingResult run = stepper.run([](const StepInfo&) {}, [](const std::string&) {});
  IndentationLevel level;
  level.divisions = divisions;
  level.completed = run.completed;
  level.steps = run.steps;
  level.newton_iterations = run.newton_iterations;
  std::vector<double> p(mesh.n_nodes());
  for (int v = 0; v < mesh.n_nodes(); ++v) p[v] = model.state()[DofMap::dof(v, 3)];
  level.eta = checkerboard_indicator(mesh, p);
  level.p_min = *std::min_element(p.begin(), p.end());
  level.p_max = *std::max_element(p.begin(), p.end());
  // The reaction of the constrained z dofs of the punch nodes (top triangles touch only punch
  // nodes among the constrained ones).
  level.punch_force = model.reaction(mesh.surface_tags.at("top")).z();
  return level;
}

/// η of the P1/P1 spurious pressure modes measured by inf_sup_test on these meshes: 1.24 to 1.41.
inline constexpr double kSpuriousModeEta = 1.24;

/// Solves on each mesh, prints the table and asserts (inf_sup.md, IS4): every run completes; η
/// falls by at least 10 % at each refinement (a spurious mode keeps η = O(1), a resolved field has
/// η -> 0); on the finest mesh η is below half the smallest η of a spurious mode.
inline void expect_smooth_pressure(const std::vector<int>& divisions) {
  std::vector<IndentationLevel> levels;
  for (int n : divisions) {
    levels.push_back(solve_indentation(n));
    ASSERT_TRUE(levels.back().completed) << "indentation did not complete on n = " << n;
  }
  std::cout << "indented block, punch travel " << kIndentation << " mm\n";
  char line[200];
  std::snprintf(line, sizeof line, "%4s %6s %8s %11s %11s %11s %9s\n", "n", "steps", "newton",
                "punch F/N", "p min", "p max", "eta");
  std::cout << line;
  for (const IndentationLevel& l : levels) {
    std::snprintf(line, sizeof line, "%4d %6d %8d %11.4e %11.4e %11.4e %9.5f\n", l.divisions,
                  l.steps, l.newton_iterations, l.punch_force, l.p_min, l.p_max, l.eta);
    std::cout << line;
  }
  for (std::size_t i = 1; i < levels.size(); ++i)
    EXPECT_LE(levels[i].eta, 0.9 * levels[i - 1].eta) << "n = " << levels[i].divisions;
  EXPECT_LT(levels.back().eta, 0.5 * kSpuriousModeEta);
}

}  // namespace plisse::test
