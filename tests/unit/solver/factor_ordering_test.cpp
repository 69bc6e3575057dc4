// The fill-reducing ordering of MUMPS on a shell's tangent (solver/linear_solver.hpp,
// choose_factor_ordering): a shell run analyses its first tangent with the approximate minimum
// degree ordering (ICNTL(7) = 0) and with MUMPS's own choice (PORD: Debian's MUMPS has neither
// METIS nor SCOTCH inside it), and factorises with the one MUMPS estimates fewer operations for,
// unless the user chose an ordering.
//
// Models, at their state after the first load (no solve: the tangent's pattern, which decides
// the ordering, is that of any state):
//  - the stretched sheet of shell triangles (validation/sheet-tension-wrinkling-shell.yaml), a
//    structured mesh, on h = 0.25 mm (12 159 free unknowns), where minimum degree wins, and on
//    0.5 mm (3 079), where MUMPS's own choice for so small a matrix wins;
//  - the thin balloon's octant of bench/thin-shell (bench/cases/thin-shell-pressure.yaml), a Gmsh
//    mesh, on h = 0.66 mm (32 169 unknowns), where PORD wins.
// MUMPS's own estimates of the elimination's operations (RINFOG(1)) are compared and printed
// (docs/performance.md, "The ordering of a shell's factorisation", quotes them): the test
// asserts the choice, and the page's percentages within 3 points.
#include <gtest/gtest.h>
#include <petscksp.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/model_builder.hpp"
#include "case/case.hpp"
#include "solver/linear_solver.hpp"
#include "solver/mixed_model.hpp"
#include "solver/petsc_call.hpp"

namespace plisse {
namespace {

const char* const kPrefixes[] = {"", "stability_", "arc_length_", "st_"};

void clear_ordering_options() {
  for (const char* prefix : kPrefixes) {
    const std::string name = std::string("-") + prefix + "mat_mumps_icntl_7";
    PLISSE_PETSC(PetscOptionsClearValue(nullptr, name.c_str()));
  }
}

/// The value of option `name`, or "" when it is not set.
std::string option_value(const std::string& name) {
  char value[64] = "";
  PetscBool set = PETSC_FALSE;
  PLISSE_PETSC(PetscOptionsGetString(nullptr, nullptr, name.c_str(), value, sizeof value, &set));
  return set ? value : "";
}

struct ShellModel {
  Case c;
  Mesh mesh;
  std::unique_ptr<MixedModel> model;
};

/// The case file `path` (under the source tree) with `overrides`, at time t.
std::unique_ptr<ShellModel> shell_model(const std::string& path,
                                        const std::vector<std::string>& overrides, double t) {
  auto m = std::make_unique<ShellModel>();
  m->c = parse_case_file(std::string(PLISSE_SOURCE_DIR) + "/" + path, overrides);
  m->mesh = load_case_mesh(m->c);
  EXPECT_TRUE(m->mesh.is_shell());
  m->model = app::make_model(m->mesh, app::build_model_parts(m->c, m->mesh));
  m->model->set_time(t);
  return m;
}

/// choose_factor_ordering on `m` gives `expected` for every solver, and the chosen ordering
/// needs `percent` % fewer operations than the other (within 3 points).
void expect_choice(ShellModel& m, int expected, double percent) {
  Mat K = m.model->create_matrix();
  ASSERT_TRUE(m.model->assemble_tangent(K).ok);
  PLISSE_PETSC(MatSetOption(K, MAT_SYMMETRIC, PETSC_TRUE));
  const double minimum_degree = estimated_factor_operations(K, 0);
  const double own = estimated_factor_operations(K, 7);
  MatDestroy(&K);
  clear_ordering_options();
  const int chosen = choose_factor_ordering(*m.model);
  const std::string value = std::to_string(chosen);
  for (const char* prefix : kPrefixes)
    EXPECT_EQ(option_value(std::string("-") + prefix + "mat_mumps_icntl_7"), value) << prefix;
  clear_ordering_options();
  const double fewer =
      100.0 * (1.0 - std::min(minimum_degree, own) / std::max(minimum_degree, own));
  std::printf(
      "%d unknowns: minimum degree %.3g operations, MUMPS's own choice %.3g; chosen %d, "
      "%.0f %% fewer than the other\n",
      m.model->n_free(), minimum_degree, own, chosen, fewer);
  EXPECT_EQ(chosen, expected);
  EXPECT_NEAR(fewer, percent, 3.0);
}

TEST(FactorOrdering, TheSheetsLargerMeshTakesMinimumDegree) {
  auto m = shell_model("validation/sheet-tension-wrinkling-shell.yaml", {"mesh.element_size=0.25"},
                       0.02);
  expect_choice(*m, 0, 16.0);
}

TEST(FactorOrdering, TheSheetsCoarseMeshAndTheBalloonKeepMumpsOwnChoice) {
  auto sheet =
      shell_model("validation/sheet-tension-wrinkling-shell.yaml", {"mesh.element_size=0.5"}, 0.02);
  expect_choice(*sheet, 7, 7.0);
  auto balloon =
      shell_model("bench/cases/thin-shell-pressure.yaml", {"mesh.element_size=0.66"}, 0.1);
  expect_choice(*balloon, 7, 25.0);
}

TEST(FactorOrdering, TheUsersOrderingStays) {
  auto m =
      shell_model("validation/sheet-tension-wrinkling-shell.yaml", {"mesh.element_size=0.5"}, 0.02);
  clear_ordering_options();
  PLISSE_PETSC(PetscOptionsSetValue(nullptr, "-st_mat_mumps_icntl_7", "4"));
  const int chosen = choose_factor_ordering(*m->model);
  EXPECT_EQ(option_value("-stability_mat_mumps_icntl_7"), std::to_string(chosen));
  EXPECT_EQ(option_value("-st_mat_mumps_icntl_7"), "4");
  clear_ordering_options();
}

}  // namespace
}  // namespace plisse
