// The fast assembly paths of MixedModel give the same numbers as the plain ones, bit for bit:
//  - threaded element loops (4 threads) against one thread: the residual vector and every tangent
//    entry equal exactly (tolerance 0: the contributions are added in element order whatever the
//    thread count, so the sums are the same floating-point operations);
//  - the direct fill of a create_matrix() matrix through precomputed positions against
//    MatSetValues into a matrix of another layout: same entries, same values (tolerance 0), and
//    the layout of create_matrix holds every entry MatSetValues creates.
// Models: the paper's indentation case (follower pressure, frictionless and sticking dies), a
// volume-controlled balloon (a cavity with its global pressure unknown, whose row and column lie
// outside the node blocks), and the stretched sheet of shell triangles (12-node patches with
// missing slots on the free edges, mirrored slots on the clamped and symmetry edges, constrained
// columns inside a patch), all coarse, at a deterministic non-trivial state (random nodal
// displacements of 2 % of the element size and random pressures) so that every term is active and
// the bubbles need several local Newton iterations.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "app/model_builder.hpp"
#include "case/case.hpp"
#include "material/registry.hpp"
#include "physics/dirichlet.hpp"
#include "solver/mixed_model.hpp"

namespace plisse {
namespace {

struct TestModel {
  Case c;
  Mesh mesh;
  std::unique_ptr<MixedModel> model;
};

/// The case file `name` (under the source tree) with `overrides`, at time t, nodal values perturbed
/// with a fixed seed.
std::unique_ptr<TestModel> make_model(const std::string& name, std::vector<std::string> overrides,
                                      double t, double displacement, double pressure) {
  auto m = std::make_unique<TestModel>();
  m->c = parse_case_file(std::string(PLISSE_SOURCE_DIR) + "/" + name, overrides);
  m->mesh = load_case_mesh(m->c);
  app::ModelParts parts = app::build_model_parts(m->c, m->mesh);
  // Exact incompressibility, whatever the case says.
  std::fill(parts.materials.inverse_bulk_moduli.begin(), parts.materials.inverse_bulk_moduli.end(),
            0.0);
  m->model = app::make_model(m->mesh, std::move(parts));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto& x = m->model->state();
  for (int v = 0; v < m->mesh.n_nodes(); ++v) {
    for (int k = 0; k < 3; ++k) x[DofMap::dof(v, k)] = displacement * unit(rng);
    x[DofMap::dof(v, 3)] = pressure * unit(rng);
  }
  m->model->set_time(t);  // constrained components take their values at t
  m->model->save_converged();
  return m;
}

/// Tangent entries (row, column) -> value of an assembled matrix.
std::map<std::pair<int, int>, double> entries(Mat K) {
  std::map<std::pair<int, int>, double> out;
  PetscInt n = 0;
  MatGetSize(K, &n, nullptr);
  for (PetscInt i = 0; i < n; ++i) {
    PetscInt n_cols = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* values = nullptr;
    MatGetRow(K, i, &n_cols, &cols, &values);
    for (PetscInt j = 0; j < n_cols; ++j) out[{int(i), int(cols[j])}] = values[j];
    MatRestoreRow(K, i, &n_cols, &cols, &values);
  }
  return out;
}

std::vector<double> residual(MixedModel& model) {
  Vec f = nullptr;
  VecCreateSeq(PETSC_COMM_SELF, model.n_free(), &f);
  model.restore_converged();  // same bubble warm start for every evaluation
  EXPECT_TRUE(model.assemble_residual(f).ok);
  const PetscScalar* a = nullptr;
  VecGetArrayRead(f, &a);
  std::vector<double> out(a, a + model.n_free());
  VecRestoreArrayRead(f, &a);
  VecDestroy(&f);
  return out;
}

std::map<std::pair<int, int>, double> tangent(MixedModel& model, Mat K) {
  model.restore_converged();
  EXPECT_TRUE(model.assemble_tangent(K).ok);
  return entries(K);
}

/// A matrix with room for every entry but not create_matrix's layout: assemble_tangent then
/// takes the MatSetValues path.
Mat plain_matrix(const MixedModel& model) {
  Mat K = nullptr;
  MatCreateSeqAIJ(PETSC_COMM_SELF, model.n_free(), model.n_free(), 200, nullptr, &K);
  MatSetOption(K, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE);  // the cavity row is wider
  return K;
}

void expect_same_assembly_at_any_thread_count(MixedModel& model) {
  ASSERT_GT(model.n_free(), 0);
  Mat K = model.create_matrix();
  model.set_assembly_threads(1);
  const std::vector<double> r1 = residual(model);
  const auto k1 = tangent(model, K);
  model.set_assembly_threads(4);
  EXPECT_EQ(model.assembly_threads(), 4);
  const std::vector<double> r4 = residual(model);
  const auto k4 = tangent(model, K);
  ASSERT_EQ(r1.size(), r4.size());
  int differ = 0;
  for (size_t i = 0; i < r1.size(); ++i) differ += r1[i] != r4[i];
  EXPECT_EQ(differ, 0) << "residual entries that differ between 1 and 4 threads";
  ASSERT_EQ(k1.size(), k4.size());
  differ = 0;
  for (const auto& [ij, v] : k1) differ += k4.at(ij) != v;
  EXPECT_EQ(differ, 0) << "tangent entries that differ between 1 and 4 threads";
  MatDestroy(&K);
}

void expect_direct_fill_equals_mat_set_values(MixedModel& model) {
  model.set_assembly_threads(2);
  Mat direct = model.create_matrix();
  Mat plain = plain_matrix(model);
  const auto kd = tangent(model, direct);
  const auto kp = tangent(model, plain);
  int missing = 0, differ = 0, nonzero_extra = 0;
  for (const auto& [ij, v] : kp) {
    const auto it = kd.find(ij);
    if (it == kd.end())
      ++missing;
    else
      differ += it->second != v;
  }
  // create_matrix may hold explicit zeros MatSetValues never created (whole node blocks).
  for (const auto& [ij, v] : kd) nonzero_extra += !kp.count(ij) && v != 0.0;
  EXPECT_EQ(missing, 0) << "entries MatSetValues creates outside the create_matrix layout";
  EXPECT_EQ(differ, 0) << "entries whose value differs between the two paths";
  EXPECT_EQ(nonzero_extra, 0);
  MatDestroy(&direct);
  MatDestroy(&plain);
}

// Indentation: pressure on `inner`, frictionless punch pressed 0.5 mm into the top at t = 0.26,
// sticking floor; 3 layers, element size 4 mm.
std::unique_ptr<TestModel> indentation() {
  return make_model("examples/sphere-indentation.yaml", {"mesh.element_size=4"}, 0.26, 0.08, 1e-4);
}

// Balloon: volume-controlled cavity (global unknown p_c) on `inner`, octant, element size 4 mm.
std::unique_ptr<TestModel> balloon() {
  auto m =
      make_model("examples/balloon-limit-point.yaml", {"mesh.element_size=4"}, 0.1, 0.08, 1e-2);
  m->model->state().back() = 0.02;  // the cavity pressure p_c [MPa]
  m->model->save_converged();
  return m;
}

// Shell sheet: clamped ends pulled by 1.2 mm at t = 0.08, symmetry edges, free edges; element
// size 1 mm, displacements of 2 % of it.
std::unique_ptr<TestModel> shell_sheet() {
  return make_model("validation/sheet-tension-wrinkling-shell.yaml", {"mesh.element_size=1"}, 0.08,
                    0.02, 0.0);
}

TEST(ThreadedAssembly, IndentationSameBitsAtAnyThreadCount) {
  auto m = indentation();
  expect_same_assembly_at_any_thread_count(*m->model);
}

TEST(ThreadedAssembly, BalloonSameBitsAtAnyThreadCount) {
  auto m = balloon();
  expect_same_assembly_at_any_thread_count(*m->model);
}

TEST(DirectTangentFill, IndentationEqualsMatSetValues) {
  auto m = indentation();
  expect_direct_fill_equals_mat_set_values(*m->model);
}

TEST(ThreadedAssembly, ShellSheetSameBitsAtAnyThreadCount) {
  auto m = shell_sheet();
  expect_same_assembly_at_any_thread_count(*m->model);
}

TEST(DirectTangentFill, ShellSheetEqualsMatSetValues) {
  auto m = shell_sheet();
  ASSERT_LT(m->model->n_free(), 3 * m->mesh.n_nodes());  // the clamps' columns are constrained
  expect_direct_fill_equals_mat_set_values(*m->model);
}

TEST(DirectTangentFill, BalloonEqualsMatSetValuesIncludingCavityRowAndColumn) {
  auto m = balloon();
  const int cavity = m->model->dofs().equation(m->model->dofs().n_dofs() - 1);
  ASSERT_GE(cavity, 0);
  expect_direct_fill_equals_mat_set_values(*m->model);
  // The cavity couples to every free displacement of the wall: its row is far wider than a node's.
  Mat K = m->model->create_matrix();
  const auto k = tangent(*m->model, K);
  int row = 0;
  for (const auto& [ij, v] : k) row += ij.first == cavity && v != 0.0;
  EXPECT_GT(row, 100);
  MatDestroy(&K);
}

}  // namespace
}  // namespace plisse
