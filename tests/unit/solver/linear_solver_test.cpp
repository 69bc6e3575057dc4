// The iterative Newton solver (solver/linear_solver.hpp): FGMRES with a Schur-complement field
// split (BoomerAMG on the displacement block, Jacobi on the selfp Schur approximation) against
// MUMPS on a real tangent, and the field index sets against the dof map.
//
// Model: a unit cube of n^3 Kuhn cells, neo-Hookean (c1 = 0.5 MPa, mu = 1 MPa), symmetry planes
// x = 0, y = 0, z = 0 and the top face pulled to the stretch lambda = 1.3 (isochoric uniaxial
// stretch, lateral stretch lambda^-1/2), plus a random perturbation of 2 % of the cell size on the
// free displacements and random pressures of 0.1 MPa: the state is prestressed and off
// equilibrium, so the tangent has material, geometric and pressure parts and the residual is
// O(1). Near incompressibility takes kappa = 1000 mu; exact incompressibility 1/kappa = 0.
//
// Tolerances: GMRES is asked for rtol = 1e-10 on the true residual (FGMRES preconditions on the
// right, so its residual is the unpreconditioned one); the test allows 10 rtol for the
// recomputed residual (round-off in the Arnoldi recurrence). The solutions then differ by at
// most cond(K) times that residual: the bound 1e-5 on the relative difference admits cond(K) up
// to 1e4 (measured: the difference is about 100 times the residual, 8e-9 against 9e-11, for both
// bulk moduli). Iteration counts are printed (47 for both at 6^3 cells).
#include "solver/linear_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "mesh/box_mesh.hpp"
#include "solver/mixed_model.hpp"
#include "solver/petsc_call.hpp"
#include "support/cube_tension.hpp"

namespace plisse {
namespace {

constexpr double kStretch = 1.3;
constexpr double kC1 = 0.5;  // [MPa], mu = 2 c1 = 1 MPa

/// Symmetry planes x = 0, y = 0, z = 0 and the top face's uz prescribed to (lambda - 1) Lz.
std::vector<ConstrainedComponent> tension_constraints(const Mesh& mesh) {
  return test::cube_tension_constraints(mesh, kStretch - 1.0);
}

/// The assembled tangent K and residual r of the tension cube at a perturbed stretched state.
class TensionCube {
 public:
  TensionCube(int cells, double inverse_bulk_modulus)
      : mesh_(make_box_mesh(Vec3d(1.0, 1.0, 1.0), {cells, cells, cells})),
        model_(mesh_, make_material("neo-hookean", {{"c1", kC1}}), inverse_bulk_modulus,
               tension_constraints(mesh_)) {
    model_.set_time(1.0);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const double lateral = 1.0 / std::sqrt(kStretch) - 1.0, h = 1.0 / cells;
    for (int v = 0; v < mesh_.n_nodes(); ++v) {
      const Vec3d& X = mesh_.nodes[v];
      const Vec3d u(lateral * X.x(), lateral * X.y(), (kStretch - 1.0) * X.z());
      for (int k = 0; k < 4; ++k) {
        const int d = DofMap::dof(v, k);
        if (model_.dofs().equation(d) < 0) continue;  // constrained: set_time's value
        model_.state()[d] = k < 3 ? u(k) + 0.02 * h * uniform(random) : 0.1 * uniform(random);
      }
    }
    K_ = model_.create_matrix();
    EXPECT_TRUE(model_.assemble_tangent(K_).ok);
    PLISSE_PETSC(MatCreateVecs(K_, nullptr, &r_));
    EXPECT_TRUE(model_.assemble_residual(r_).ok);
  }
  ~TensionCube() {
    MatDestroy(&K_);
    VecDestroy(&r_);
  }
  TensionCube(const TensionCube&) = delete;
  TensionCube& operator=(const TensionCube&) = delete;

  const MixedModel& model() const { return model_; }
  Mat K() const { return K_; }
  Vec r() const { return r_; }
  /// The matrix's communicator (several processes when the model distributes its equations).
  MPI_Comm comm() const {
    MPI_Comm c = MPI_COMM_NULL;
    PLISSE_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(K_), &c));
    return c;
  }
  FieldIndexSets fields() const {
    PetscInt first = 0, end = 0;
    PLISSE_PETSC(MatGetOwnershipRange(K_, &first, &end));
    return make_field_index_sets(comm(), model_.dofs(), first, end);
  }

 private:
  Mesh mesh_;
  MixedModel model_;
  Mat K_ = nullptr;
  Vec r_ = nullptr;
};

struct SolveResult {
  Vec x = nullptr;  ///< the caller destroys it
  PetscInt iterations = 0;
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  double seconds = 0.0;
};

/// Solves K x = r with MUMPS as configure_snes does (LDL^T for a symmetric K).
SolveResult solve_direct(const TensionCube& cube) {
  SolveResult s;
  KSP ksp = nullptr;
  PC pc = nullptr;
  PLISSE_PETSC(KSPCreate(cube.comm(), &ksp));
  PLISSE_PETSC(KSPSetOperators(ksp, cube.K(), cube.K()));
  PLISSE_PETSC(KSPSetType(ksp, KSPPREONLY));
  PLISSE_PETSC(KSPGetPC(ksp, &pc));
  PLISSE_PETSC(PCSetType(pc, cube.model().symmetric() ? PCCHOLESKY : PCLU));
  PLISSE_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PLISSE_PETSC(VecDuplicate(cube.r(), &s.x));
  PLISSE_PETSC(KSPSolve(ksp, cube.r(), s.x));
  PLISSE_PETSC(KSPGetConvergedReason(ksp, &s.reason));
  KSPDestroy(&ksp);
  return s;
}

/// Solves K x = r with configure_iterative; `prefix` isolates the test's options.
SolveResult solve_iterative(const TensionCube& cube, const LinearSolverSettings& settings,
                            const char* prefix = "lst_") {
  SolveResult s;
  KSP ksp = nullptr;
  PLISSE_PETSC(KSPCreate(cube.comm(), &ksp));
  PLISSE_PETSC(KSPSetOptionsPrefix(ksp, prefix));
  PLISSE_PETSC(KSPSetOperators(ksp, cube.K(), cube.K()));
  {
    const FieldIndexSets fields = cube.fields();  // the PC keeps its own references
    configure_iterative(ksp, fields.u(), fields.p(), settings);
  }
  PLISSE_PETSC(KSPSetFromOptions(ksp));
  PLISSE_PETSC(VecDuplicate(cube.r(), &s.x));
  const auto t0 = std::chrono::steady_clock::now();
  PLISSE_PETSC(KSPSolve(ksp, cube.r(), s.x));
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  PLISSE_PETSC(KSPGetConvergedReason(ksp, &s.reason));
  PLISSE_PETSC(KSPGetIterationNumber(ksp, &s.iterations));
  KSPDestroy(&ksp);
  return s;
}

/// ||K x - r|| / ||r||.
double relative_residual(const TensionCube& cube, Vec x) {
  Vec Kx = nullptr;
  PLISSE_PETSC(VecDuplicate(cube.r(), &Kx));
  PLISSE_PETSC(MatMult(cube.K(), x, Kx));
  PLISSE_PETSC(VecAXPY(Kx, -1.0, cube.r()));
  PetscReal residual = 0.0, rhs = 0.0;
  PLISSE_PETSC(VecNorm(Kx, NORM_2, &residual));
  PLISSE_PETSC(VecNorm(cube.r(), NORM_2, &rhs));
  VecDestroy(&Kx);
  return residual / rhs;
}

/// ||a - b|| / ||b||.
double relative_difference(Vec a, Vec b) {
  Vec d = nullptr;
  PLISSE_PETSC(VecDuplicate(a, &d));
  PLISSE_PETSC(VecWAXPY(d, -1.0, b, a));
  PetscReal diff = 0.0, norm = 0.0;
  PLISSE_PETSC(VecNorm(d, NORM_2, &diff));
  PLISSE_PETSC(VecNorm(b, NORM_2, &norm));
  VecDestroy(&d);
  return diff / norm;
}

void expect_iterative_matches_direct(int cells, double inverse_bulk_modulus) {
  const TensionCube cube(cells, inverse_bulk_modulus);
  LinearSolverSettings settings;
  settings.type = LinearSolverType::iterative;
  settings.rtol = 1e-10;
  settings.max_iterations = 500;
  SolveResult direct = solve_direct(cube);
  SolveResult iterative = solve_iterative(cube, settings);
  const double residual = relative_residual(cube, iterative.x);
  const double difference = relative_difference(iterative.x, direct.x);
  int n_processes = 1;
  MPI_Comm_size(cube.comm(), &n_processes);
  std::cout << cells << "^3 cells, " << cube.model().n_free() << " equations on " << n_processes
            << " process(es), 1/kappa = " << inverse_bulk_modulus << ": FGMRES "
            << iterative.iterations << " iterations (" << KSPConvergedReasons[iterative.reason]
            << ", " << iterative.seconds << " s), residual " << residual << ", difference to MUMPS "
            << difference << "\n";
  EXPECT_GT(direct.reason, 0);
  EXPECT_GT(iterative.reason, 0) << KSPConvergedReasons[iterative.reason];
  EXPECT_LT(relative_residual(cube, direct.x), 1e-12);
  EXPECT_LT(residual, 10.0 * settings.rtol);
  EXPECT_LT(difference, 1e-5);
  // A preconditioner worth its name: far fewer iterations than unknowns.
  EXPECT_LT(iterative.iterations, 100);
  VecDestroy(&direct.x);
  VecDestroy(&iterative.x);
}

TEST(IterativeSolver, MatchesMumpsNearlyIncompressible) {
  expect_iterative_matches_direct(6, 1.0 / (1000.0 * 2.0 * kC1));
}

TEST(IterativeSolver, MatchesMumpsExactlyIncompressible) {
  expect_iterative_matches_direct(6, 0.0);
}

/// Each free equation in [first, end) is in exactly one set, u holds exactly the displacement
/// equations, p the pressure and global ones, both ascending; nothing outside the range.
void expect_partition(const DofMap& dofs, PetscInt first, PetscInt end) {
  const FieldIndexSets fields = make_field_index_sets(PETSC_COMM_SELF, dofs, first, end);
  std::vector<int> seen(dofs.n_free(), 0);
  const auto check = [&](IS is, bool displacement) {
    PetscInt n = 0;
    const PetscInt* indices = nullptr;
    PLISSE_PETSC(ISGetLocalSize(is, &n));
    PLISSE_PETSC(ISGetIndices(is, &indices));
    EXPECT_TRUE(std::is_sorted(indices, indices + n));
    std::vector<PetscInt> expected;
    for (int d = 0; d < dofs.n_dofs(); ++d) {
      const int eq = dofs.equation(d);
      const bool is_u = d < DofMap::kPerNode * dofs.n_nodes() && d % DofMap::kPerNode < 3;
      if (eq >= first && eq < end && is_u == displacement) expected.push_back(eq);
    }
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(std::vector<PetscInt>(indices, indices + n), expected);
    for (PetscInt i = 0; i < n; ++i) ++seen[indices[i]];
    PLISSE_PETSC(ISRestoreIndices(is, &indices));
  };
  check(fields.u(), true);
  check(fields.p(), false);
  for (int eq = 0; eq < dofs.n_free(); ++eq)
    EXPECT_EQ(seen[eq], eq >= first && eq < end ? 1 : 0) << "equation " << eq;
}

TEST(FieldIndexSets, PartitionTheOwnedFreeEquations) {
  // 6 nodes, 2 global unknowns (e.g. two cavity pressures), some displacement components fixed.
  const std::vector<ConstrainedComponent> constrained{
      {0, 0, 0.0, {}}, {0, 1, 0.0, {}}, {0, 2, 0.0, {}}, {3, 1, 0.0, {}}, {5, 2, 0.0, {}}};
  const DofMap dofs(6, 2, constrained);
  ASSERT_EQ(dofs.n_free(), 6 * 4 + 2 - 5);
  expect_partition(dofs, 0, dofs.n_free());  // one process
  expect_partition(dofs, 0, 7);              // the ranges of three processes
  expect_partition(dofs, 7, 15);
  expect_partition(dofs, 15, dofs.n_free());
  expect_partition(dofs, 4, 4);  // a process without equations
  EXPECT_THROW(make_field_index_sets(PETSC_COMM_SELF, dofs, 3, dofs.n_free() + 1), Error);
  EXPECT_THROW(make_field_index_sets(PETSC_COMM_SELF, dofs, 5, 4), Error);

  const TensionCube cube(2, 0.0);
  expect_partition(cube.model().dofs(), 0, cube.model().n_free());
}

TEST(IterativeSolver, UserOptionsOverrideTheDefaults) {
  const TensionCube cube(3, 0.0);
  PLISSE_PETSC(PetscOptionsSetValue(nullptr, "-ovr_fieldsplit_p_pc_type", "none"));
  PLISSE_PETSC(PetscOptionsSetValue(nullptr, "-ovr_ksp_rtol", "1e-3"));
  KSP ksp = nullptr;
  PLISSE_PETSC(KSPCreate(cube.comm(), &ksp));
  PLISSE_PETSC(KSPSetOptionsPrefix(ksp, "ovr_"));
  PLISSE_PETSC(KSPSetOperators(ksp, cube.K(), cube.K()));
  LinearSolverSettings settings;
  settings.type = LinearSolverType::iterative;
  const FieldIndexSets fields = cube.fields();
  configure_iterative(ksp, fields.u(), fields.p(), settings);
  configure_iterative(ksp, fields.u(), fields.p(), settings);  // again: still two splits
  PLISSE_PETSC(KSPSetFromOptions(ksp));
  PLISSE_PETSC(KSPSetUp(ksp));
  PetscReal rtol = 0.0;
  PetscInt max_iterations = 0;
  PLISSE_PETSC(KSPGetTolerances(ksp, &rtol, nullptr, nullptr, &max_iterations));
  EXPECT_EQ(rtol, 1e-3);                               // the user's option
  EXPECT_EQ(max_iterations, settings.max_iterations);  // plisse's setting
  PC pc = nullptr;
  PLISSE_PETSC(KSPGetPC(ksp, &pc));
  KSP* sub = nullptr;
  PetscInt n_splits = 0;
  PLISSE_PETSC(PCFieldSplitSchurGetSubKSP(pc, &n_splits, &sub));
  ASSERT_EQ(n_splits, 2);
  PC pc_u = nullptr, pc_p = nullptr;
  PLISSE_PETSC(KSPGetPC(sub[0], &pc_u));
  PLISSE_PETSC(KSPGetPC(sub[1], &pc_p));
  PetscBool is_hypre = PETSC_FALSE, is_none = PETSC_FALSE;
  PLISSE_PETSC(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc_u), PCHYPRE, &is_hypre));
  PLISSE_PETSC(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc_p), PCNONE, &is_none));
  EXPECT_TRUE(is_hypre) << "plisse's default for the displacement block";
  EXPECT_TRUE(is_none) << "the user's -fieldsplit_p_pc_type";
  PLISSE_PETSC(PetscFree(sub));
  KSPDestroy(&ksp);
}

}  // namespace
}  // namespace plisse
