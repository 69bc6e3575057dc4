#include "solver/stability.hpp"

#include <chrono>

#include "solver/linear_solver.hpp"
#include "solver/petsc_call.hpp"

namespace plisse {

int expected_negative_pivots(const MixedModel& model) {
  int n = model.dofs().n_free_pressure();                                   // (stability.md, S4)
  for (const auto& term : model.terms()) n += term->negative_directions();  // (S5)-(S6)
  return n;
}

InertiaCheck::InertiaCheck(MixedModel& model) : model_(model), symmetric_(model.symmetric()) {
  K_ = model.create_matrix();
  pattern_version_ = model.pattern_version();
  PLISSE_PETSC(PetscLogStageGetId("Stability check", &stage_));
  if (stage_ < 0) PLISSE_PETSC(PetscLogStageRegister("Stability check", &stage_));
  PLISSE_PETSC(PCCreate(model.comm(), &pc_));
  PLISSE_PETSC(PCSetOptionsPrefix(pc_, "stability_"));
  PLISSE_PETSC(PCSetType(pc_, PCCHOLESKY));
  PLISSE_PETSC(PCFactorSetMatSolverType(pc_, MATSOLVERMUMPS));
}

InertiaCheck::~InertiaCheck() {
  PCDestroy(&pc_);
  MatDestroy(&S_);
  MatDestroy(&Kt_);
  MatDestroy(&K_);
}

Mat InertiaCheck::symmetric_operator() {
  if (symmetric_) return K_;
  // (stability.md, S8): S = 0.5 (K + K^T). S_ keeps the union of the patterns of K and K^T, so
  // that the factor's symbolic analysis stays valid; it is rebuilt when K gains nonzeros.
  PetscObjectState state = 0;
  PLISSE_PETSC(MatGetNonzeroState(K_, &state));
  if (!S_ || state != pattern_) {
    MatDestroy(&S_);
    MatDestroy(&Kt_);
    PLISSE_PETSC(MatTranspose(K_, MAT_INITIAL_MATRIX, &Kt_));
    PLISSE_PETSC(MatDuplicate(K_, MAT_COPY_VALUES, &S_));
    PLISSE_PETSC(MatAXPY(S_, 1.0, Kt_, DIFFERENT_NONZERO_PATTERN));
    pattern_ = state;
  } else {
    PLISSE_PETSC(MatTranspose(K_, MAT_REUSE_MATRIX, &Kt_));
    PLISSE_PETSC(MatCopy(K_, S_, SUBSET_NONZERO_PATTERN));
    PLISSE_PETSC(MatAXPY(S_, 1.0, Kt_, SUBSET_NONZERO_PATTERN));
  }
  PLISSE_PETSC(MatScale(S_, 0.5));
  PLISSE_PETSC(MatSetOption(S_, MAT_SYMMETRIC, PETSC_TRUE));
  return S_;
}

Mat InertiaCheck::factor() const {
  if (!symmetric_ || calls_ == 0) return nullptr;
  Mat F = nullptr;
  if (PCFactorGetMatrix(pc_, &F) != 0) return nullptr;
  return F;
}

Inertia InertiaCheck::compute() {
  const auto t0 = std::chrono::steady_clock::now();
  // Pops the log stage on every way out.
  struct StageGuard {
    explicit StageGuard(PetscLogStage stage) { PLISSE_PETSC(PetscLogStagePush(stage)); }
    ~StageGuard() { PetscLogStagePop(); }
  } stage_guard(stage_);
  if (model_.pattern_version() != pattern_version_) {
    // The tangent's sparsity grew: new matrices (S_ and Kt_ follow K_).
    MatDestroy(&S_);
    MatDestroy(&Kt_);
    MatDestroy(&K_);
    K_ = model_.create_matrix();
    pattern_version_ = model_.pattern_version();
  }
  const AssemblyStatus status = model_.assemble_tangent(K_);
  PLISSE_CHECK(status.ok,
               "stability check: the tangent cannot be assembled at the converged state "
               "(element "
                   << status.worst_element << ", min J " << status.min_J << ")");
  Mat A = symmetric_operator();
  assembly_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Mat F = nullptr;
  MatFactorError error = MAT_FACTOR_NOERROR;
  while (true) {
    PLISSE_PETSC(PCSetOperators(pc_, A, A));
    if (!configured_) {
      PLISSE_PETSC(PCSetFromOptions(pc_));
      PLISSE_PETSC(PCFactorSetUpMatSolverType(pc_));
      PLISSE_PETSC(PCFactorGetMatrix(pc_, &F));
      // ICNTL(24) = 1: null-pivot detection, so that a singular tangent (a critical point) is
      // factorised and its null pivots are counted in INFOG(28) instead of failing.
      PLISSE_PETSC(MatMumpsSetIcntl(F, 24, 1));
      // In parallel the root front must not go to ScaLAPACK (ICNTL(13) = 1), which computes no
      // inertia.
      PetscMPIInt size = 1;
      PLISSE_PETSC(MPI_Comm_size(PetscObjectComm(reinterpret_cast<PetscObject>(A)), &size));
      if (size > 1) PLISSE_PETSC(MatMumpsSetIcntl(F, 13, 1));
      configured_ = true;
    }
    PLISSE_PETSC(PCSetUp(pc_));
    PLISSE_PETSC(PCFactorGetMatrix(pc_, &F));
    PLISSE_PETSC(MatFactorGetError(F, &error));
    if (error == MAT_FACTOR_NOERROR) break;
    const FactorMemory memory = factor_memory(F);
    if (memory.out_of_memory) throw SolverError("stability check: " + memory.message());
    if (!grow_factor_workspace(pc_, memory)) break;
    configured_ = false;  // the new factor needs its settings again
  }
  PLISSE_CHECK(error == MAT_FACTOR_NOERROR,
               "stability check: the LDL^T factorisation of the tangent failed (MatFactorError "
                   << static_cast<int>(error) << ")");
  PetscInt negative = 0, zero = 0, positive = 0;
  PLISSE_PETSC(MatGetInertia(F, &negative, &zero, &positive));
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ++calls_;
  return {static_cast<int>(negative), static_cast<int>(zero), static_cast<int>(positive)};
}

}  // namespace plisse
