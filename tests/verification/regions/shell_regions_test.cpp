// Regions of a shell (`regions:` with `element: shell`), through `plisse run`: triangles with a
// material and a wall thickness of their own, and rigid triangles glued to the shell.
//
// A sheet of two regions side by side, each its own model and thickness, pulled along x with its
// long edges free: incompressible isotropic plane stress in uniaxial tension takes the stretches
// (λ, λ^-1/2) in the plane and λ^-1/2 through the thickness whatever the model, so both regions
// deform alike, their interface (along x, on a line of the mesh) carries no traction, and the pull
// is W₁ t₁ P₁(λ) + W₂ t₂ P₂(λ), each region's width, reference thickness and nominal uniaxial
// stress: neo-Hookean P = 2 c1 (λ − λ⁻²), Mooney-Rivlin P = 2 (c1 + c2 / λ)(λ − λ⁻²) (Ogden,
// Non-linear Elastic Deformations, 1984, 7.2). Exact on any mesh whose lines follow the interface:
// the solver's tolerance.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "output/history_writer.hpp"
#include "support/printed_errors.hpp"
#include "support/run_case.hpp"

namespace plisse {
namespace {

using test::history_column;
using test::run_case_text;

constexpr double kLength = 20.0, kWidth = 10.0;  // the half sheet: y in [0, W], mirrored at y = 0
constexpr double kThin = 0.5, kThick = 1.2;      // [mm]: y < 5 and y > 5
constexpr double kStretch = 1.4;

double neo_hookean_nominal(double c1, double l) { return 2.0 * c1 * (l - 1.0 / (l * l)); }
double mooney_rivlin_nominal(double c1, double c2, double l) {
  return 2.0 * (c1 + c2 / l) * (l - 1.0 / (l * l));
}

/// The sheet pulled to kStretch; `regions` is the case's `regions:` line (empty: none).
HistoryTable pulled_sheet(const std::string& label, const std::string& regions) {
  const auto dir = test::scratch_directory("shell-regions-" + label);
  // element_size 2.5: 8 x 4 cells, a mesh line at y = 5.
  std::string text =
      "element: shell\n"
      "mesh: {generate: sheet, length: 20.0, width: 10.0, thickness: 0.5, element_size: 2.5}\n"
      "material: {model: neo-hookean, c1: 0.2}\n" +
      regions +
      "boundary:\n"
      "  - {type: displacement, surface: left, value: [0, null, 0]}\n"
      "  - {type: displacement, name: pull, surface: right, value: [8.0, null, 0]}\n"
      "  - {type: symmetry, surface: front}\n"
      "probes:\n"
      "  - {name: thin, point: [10.0, 2.5, 0.25], fields: [displacement, thickness, cauchy]}\n"
      "  - {name: thick, point: [10.0, 7.5, 0.25], fields: [displacement, thickness, cauchy]}\n"
      "solver: {steps: 2, newton: {rtol: 1.0e-12, atol: 1.0e-13}}\n";
  return run_case_text(dir, text);
}

TEST(ShellRegions, TwoModelsAndThicknessesSideBySideCarryTheSumOfTheirUniaxialForces) {
  const HistoryTable h = pulled_sheet("side-by-side",
                                      "regions: [{box: [[-1, 5, -1], [21, 11, 1]], thickness: 1.2,"
                                      " material: {model: mooney-rivlin, c1: 0.3, c2: 0.1}}]\n");
  ASSERT_EQ(h.rows.size(), 2u);
  const double half = 0.5 * kWidth;
  const double expected = half * kThin * neo_hookean_nominal(0.2, kStretch) +
                          half * kThick * mooney_rivlin_nominal(0.3, 0.1, kStretch);
  const std::vector<double>& last = h.rows.back();
  const double force = last[history_column(h, "force_x:pull")];
  std::printf("two regions: pull %.12f N, closed form %.12f N (%.1e)\n", force, expected,
              force / expected - 1.0);
  EXPECT_NEAR(force, expected, 1e-9 * expected);
  // Each region's wall thins as λ^-1/2 from its own thickness, and its Cauchy stress is its own
  // model's: σ = λ P.
  const double thinning = 1.0 / std::sqrt(kStretch);
  EXPECT_NEAR(last[history_column(h, "thickness:thin")], kThin * thinning, 1e-10);
  EXPECT_NEAR(last[history_column(h, "thickness:thick")], kThick * thinning, 1e-10);
  const double s_thin = kStretch * neo_hookean_nominal(0.2, kStretch);
  const double s_thick = kStretch * mooney_rivlin_nominal(0.3, 0.1, kStretch);
  EXPECT_NEAR(last[history_column(h, "cauchy_xx:thin")], s_thin, 1e-9 * s_thin);
  EXPECT_NEAR(last[history_column(h, "cauchy_xx:thick")], s_thick, 1e-9 * s_thick);
  // Both contract alike across: the probes move the same way in y, by (λ^-1/2 - 1) y.
  EXPECT_NEAR(last[history_column(h, "uy:thin")], (thinning - 1.0) * 2.5, 1e-10);
  EXPECT_NEAR(last[history_column(h, "uy:thick")], (thinning - 1.0) * 7.5, 1e-10);
}

// A region of the sheet's own material and thickness under another name (one-term Ogden with
// α = 2, μ = 2 c1 is neo-Hookean) changes nothing: a wrong index in the per-triangle materials or
// thicknesses would.
TEST(ShellRegions, ARegionOfTheSameMaterialAndThicknessChangesNothing) {
  const HistoryTable uniform = pulled_sheet("uniform", "");
  const HistoryTable split =
      pulled_sheet("same",
                   "regions: [{box: [[-1, 5, -1], [21, 11, 1]], thickness: 0.5,"
                   " material: {model: ogden, mu1: 0.4, alpha1: 2}}]\n");
  ASSERT_EQ(uniform.rows.size(), 2u);
  ASSERT_EQ(split.rows.size(), 2u);
  const std::size_t f = history_column(uniform, "force_x:pull");
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_NEAR(split.rows[k][f], uniform.rows[k][f], 1e-10 * std::abs(uniform.rows[k][f]))
        << "step " << k + 1;
  const double expected = kWidth * kThin * neo_hookean_nominal(0.2, kStretch);
  EXPECT_NEAR(uniform.rows.back()[f], expected, 1e-9 * expected);
}

// --- A rigid region ---------------------------------------------------------------------------

// A cantilever glued to a rigid grip: the sheet is 110 mm along x, 10 mm wide, 1 mm thick
// (neo-Hookean μ = 1 MPa, incompressible: E = 3 μ, ν = 1/2), its first 10 mm a rigid region,
// its long edges symmetry planes (plane strain: D = μ t³/3 per unit width), under its weight.
// The grip only translates, so it clamps the 100 mm beyond it (docs/theory/shell.md, KL8a, the
// side between the two clamped): the free end deflects q L⁴ / (8 D) (Timoshenko & Gere 1972,
// Mechanics of Materials, table of cantilever deflections), the same closed form and the same
// errors as the clamped edge's (tests/verification/shell/gravity_test.cpp: 1.58e-4 at 1.25 mm
// cells), second order. Measured here: 6.6e-4, 1.6e-4, 3.9e-5 with 2.5, 1.25 and 0.625 mm cells.
// The grip holds the weight of the 100 mm it carries (a rigid region weighs nothing). The load
// is small (w/L ~ 1e-3) and carried in bending: the line search is cp (docs/case-file.md,
// "Cavities that start flat"), since with the back-tracking search the first full step's
// second-order membrane forces (~ (w/L)² E t) outweigh this load's residual and the search
// shortens every step.
HistoryTable glued_cantilever(const std::string& label, double element_size, double lift) {
  char size[32], up[32];
  std::snprintf(size, sizeof size, "%g", element_size);
  std::snprintf(up, sizeof up, "%g", lift);
  return run_case_text(
      test::scratch_directory("shell-rigid-grip-" + label),
      std::string("element: shell\n"
                  "mesh: {generate: sheet, length: 110.0, width: 10.0, thickness: 1.0, "
                  "element_size: ") +
          size +
          "}\n"
          "material: {model: neo-hookean, c1: 0.5, density: 2.5e-13}\n"
          "regions: [{box: [[-1, -1, -1], [10, 11, 1]], rigid: true, name: grip, "
          "displacement: [0, 0, " +
          up +
          "]}]\n"
          "boundary:\n"
          "  - {type: symmetry, surface: front}\n"
          "  - {type: symmetry, surface: back}\n"
          "loads: [{type: gravity, name: g, acceleration: [0, 0, -9810]}]\n"
          "probes: [{name: tip, point: [110, 5, 0]}]\n"
          "solver:\n  steps: 1\n"
          "  newton: {line_search: cp, atol: 1.0e-13}\n");
}

TEST(ShellRegions, ARigidGripClampsTheShellItHolds) {
  const double q = 2.5e-13 * 9810.0 * 1.0;                          // ρ g t [MPa]
  const double exact = q * std::pow(100.0, 4) / (8.0 * 1.0 / 3.0);  // [mm]
  const double weight = q * 100.0 * 10.0;                           // of the free 100 mm [N]
  std::vector<double> errors;
  for (double h : {2.5, 1.25, 0.625}) {
    const HistoryTable t = glued_cantilever("h" + std::to_string(errors.size()), h, 0.0);
    ASSERT_EQ(t.rows.size(), 1u) << h;
    const double w = -t.rows.back()[history_column(t, "uz:tip")];
    errors.push_back(std::abs(w - exact) / exact);
    std::printf("cells %.3g mm: w = %.6e mm, exact %.6e, error %.2e\n", h, w, exact, errors.back());
    EXPECT_NEAR(t.rows.back()[history_column(t, "force_z:grip")], weight, 1e-8 * weight) << h;
  }
  // The numbers docs/case-file.md and docs/theory/shell.md print, to their last digit (a guard
  // on plisse's own discretisation error, against the closed form).
  test::expect_printed_second_order(errors, std::array{6.6e-4, 1.6e-4, 3.9e-5},
                                    std::array{5e-6, 5e-6, 5e-7});
}

// The grip lifted by 2 mm carries the strip up rigidly: the tip sits 2 mm higher, less the same
// deflection, to the solver's tolerance (a translation strains nothing): within 1e-6 of the
// deflection (measured 6e-8).
TEST(ShellRegions, ARigidGripMovedCarriesTheShellAlong) {
  const HistoryTable held = glued_cantilever("held", 2.5, 0.0);
  const HistoryTable lifted = glued_cantilever("lifted", 2.5, 2.0);
  ASSERT_EQ(held.rows.size(), 1u);
  ASSERT_FALSE(lifted.rows.empty());  // the lift's first try may be cut in two
  ASSERT_DOUBLE_EQ(lifted.rows.back()[history_column(lifted, "time")], 1.0);
  const double w = held.rows.back()[history_column(held, "uz:tip")];
  EXPECT_NEAR(lifted.rows.back()[history_column(lifted, "uz:tip")], 2.0 + w, 1e-6 * std::abs(w));
}

// examples/sheet-patch-grips.yaml as a shell (`--set element=shell`, as its header says): the
// boxes select mid-surface triangles, the grips clamp the sheet, their forces balance and the
// stiff patch stretches far less than the sheet beside it (as the solid's, DistributedRun's test).
TEST(ShellRegions, ThePatchAndGripsExampleRunsAsAShell) {
  std::ifstream file(std::string(PLISSE_SOURCE_DIR) + "/examples/sheet-patch-grips.yaml");
  std::stringstream text;
  text << file.rdbuf();
  const HistoryTable h =
      run_case_text(test::scratch_directory("shell-patch-grips"), "element: shell\n" + text.str());
  ASSERT_FALSE(h.rows.empty());
  const auto& row = h.rows.back();
  const double pull = row[history_column(h, "force_x:right_grip")];
  EXPECT_GT(pull, 0.0);
  EXPECT_NEAR(row[history_column(h, "force_x:left_grip")], -pull, 1e-8 * pull);
  EXPECT_LT(row[history_column(h, "stretch_1:patch")] - 1.0,
            0.2 * (row[history_column(h, "stretch_1:sheet")] - 1.0));
}

}  // namespace
}  // namespace plisse
