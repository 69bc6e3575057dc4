#include "solver/newton_solver.hpp"

#include <string>

#include "core/wall_clock.hpp"
#include "solver/linear_solver.hpp"
#include "solver/petsc_call.hpp"

namespace plisse {
namespace {

const char* line_search_type(LineSearch ls) {
  switch (ls) {
    case LineSearch::bt:
      return SNESLINESEARCHBT;
    case LineSearch::basic:
      return SNESLINESEARCHBASIC;
    case LineSearch::l2:
      return SNESLINESEARCHL2;
    case LineSearch::cp:
      return SNESLINESEARCHCP;
  }
  return SNESLINESEARCHBT;
}
}  // namespace

void configure_snes(SNES snes, const NewtonSettings& settings, bool symmetric) {
  // stol = 0: convergence is judged on the residual only.
  PLISSE_PETSC(SNESSetTolerances(snes, settings.atol, settings.rtol, 0.0, settings.max_iterations,
                                 PETSC_DEFAULT));
  SNESLineSearch ls = nullptr;
  PLISSE_PETSC(SNESGetLineSearch(snes, &ls));
  PLISSE_PETSC(SNESLineSearchSetType(ls, line_search_type(settings.line_search)));
  KSP ksp = nullptr;
  PC pc = nullptr;
  PLISSE_PETSC(SNESGetKSP(snes, &ksp));
  if (settings.linear.type == LinearSolverType::iterative) {
    configure_iterative(ksp, nullptr, nullptr, settings.linear);  // fields: NewtonSolver
    return;
  }
  PLISSE_PETSC(KSPSetType(ksp, KSPPREONLY));
  PLISSE_PETSC(KSPGetPC(ksp, &pc));
  // A symmetric tangent is indefinite (saddle point): MUMPS LDL^T (sym = 2). Follower loads on
  // open surfaces make it unsymmetric: LU.
  PLISSE_PETSC(PCSetType(pc, symmetric ? PCCHOLESKY : PCLU));
  PLISSE_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
}

void check_petsc_options(const NewtonSettings& settings) {
  SNES snes = nullptr;
  PLISSE_PETSC(SNESCreate(PETSC_COMM_SELF, &snes));
  try {
    PLISSE_PETSC(SNESSetType(snes, SNESNEWTONLS));
    configure_snes(snes, settings, true);
    PLISSE_PETSC(SNESSetFromOptions(snes));
  } catch (...) {
    SNESDestroy(&snes);
    throw;
  }
  SNESDestroy(&snes);
}

NewtonSolver::NewtonSolver(MixedModel& model, const NewtonSettings& settings) : model_(model) {
  // The event log splits the linear-solver time into factorisation and triangular solves.
  PetscBool logging = PETSC_FALSE;
  PLISSE_PETSC(PetscLogIsActive(&logging));
  if (!logging) PLISSE_PETSC(PetscLogDefaultBegin());
  x_ = model.create_vector();
  PLISSE_PETSC(VecDuplicate(x_, &r_));
  PLISSE_PETSC(SNESCreate(model.comm(), &snes_));
  PLISSE_PETSC(SNESSetType(snes_, SNESNEWTONLS));
  PLISSE_PETSC(SNESSetFunction(snes_, r_, &NewtonSolver::form_function, this));
  make_matrix();
  configure_snes(snes_, settings, model.symmetric());
  if (settings.linear.type == LinearSolverType::iterative) {
    KSP ksp = nullptr;
    PLISSE_PETSC(SNESGetKSP(snes_, &ksp));
    const FieldIndexSets fields = make_field_index_sets(
        model.comm(), model.dofs(), model.first_owned_equation(), model.end_owned_equation());
    configure_iterative(ksp, fields.u(), fields.p(), settings.linear);
  }
  history_.assign(settings.max_iterations + 1, 0.0);
  PLISSE_PETSC(SNESSetConvergenceHistory(snes_, history_.data(), nullptr,
                                         static_cast<PetscInt>(history_.size()), PETSC_TRUE));
  PLISSE_PETSC(SNESSetFromOptions(snes_));
  PLISSE_PETSC(SNESSetConvergenceTest(snes_, &NewtonSolver::converged, this, nullptr));
}

NewtonSolver::~NewtonSolver() {
  SNESDestroy(&snes_);
  MatDestroy(&K_);
  VecDestroy(&r_);
  VecDestroy(&x_);
}

void NewtonSolver::make_matrix() {
  MatDestroy(&K_);
  K_ = model_.create_matrix();
  pattern_version_ = model_.pattern_version();
  PLISSE_PETSC(SNESSetJacobian(snes_, K_, K_, &NewtonSolver::form_jacobian, this));
}

PetscErrorCode NewtonSolver::form_function(SNES snes, Vec x, Vec f, void* context) {
  auto* self = static_cast<NewtonSolver*>(context);
  try {
    const auto t0 = WallClock::now();
    self->model_.set_free(x);
    self->last_status_ = self->model_.assemble_residual(f);
    self->times_.assembly += seconds_since(t0);
    // An inverted element: let the line search backtrack, or SNES stop with a domain error.
    if (!self->last_status_.ok) PetscCall(SNESSetFunctionDomainError(snes));
  } catch (...) {
    self->error_ = std::current_exception();
    return PETSC_ERR_LIB;
  }
  return 0;
}

PetscErrorCode NewtonSolver::converged(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm,
                                       PetscReal fnorm, SNESConvergedReason* reason,
                                       void* context) {
  PetscCall(SNESConvergedDefault(snes, it, xnorm, snorm, fnorm, reason, nullptr));
  auto* self = static_cast<NewtonSolver*>(context);
  if (*reason != SNES_CONVERGED_ITERATING || !self->interrupt_) return 0;
  try {
    self->interrupted_ = self->interrupt_();
  } catch (...) {
    self->error_ = std::current_exception();
    return PETSC_ERR_LIB;
  }
  // PETSc 3.18 has no user reason; any diverged one ends the solve, and `interrupted` says why.
  if (self->interrupted_) *reason = SNES_DIVERGED_FUNCTION_COUNT;
  return 0;
}

PetscErrorCode NewtonSolver::form_jacobian(SNES, Vec x, Mat J, Mat, void* context) {
  auto* self = static_cast<NewtonSolver*>(context);
  try {
    const auto t0 = WallClock::now();
    self->model_.set_free(x);
    self->model_.assemble_tangent(J);
    self->times_.assembly += seconds_since(t0);
  } catch (...) {
    self->error_ = std::current_exception();
    return PETSC_ERR_LIB;
  }
  return 0;
}

PhaseTimes NewtonSolver::times() const {
  PhaseTimes t = times_;
  const auto event_time = [](const char* name, int* count) {
    PetscLogEvent event = 0;
    PetscEventPerfInfo info{};
    if (PetscLogEventGetId(name, &event) != 0 || PetscLogEventGetPerfInfo(0, event, &info) != 0)
      return 0.0;
    if (count) *count += info.count;
    return static_cast<double>(info.time);
  };
  for (const char* name : {"MatCholFctrSym", "MatCholFctrNum", "MatLUFactorSym", "MatLUFactorNum"})
    t.factorisation += event_time(
        name, std::string(name).find("Num") != std::string::npos ? &t.factorisations : nullptr);
  t.triangular_solve = event_time("MatSolve", nullptr);
  return t;
}

double NewtonSolver::factor_entries() const {
  KSP ksp = nullptr;
  PC pc = nullptr;
  PLISSE_PETSC(SNESGetKSP(snes_, &ksp));
  PLISSE_PETSC(KSPGetPC(ksp, &pc));
  PetscBool is_factor = PETSC_FALSE;
  PLISSE_PETSC(PetscObjectTypeCompareAny(reinterpret_cast<PetscObject>(pc), &is_factor, PCLU,
                                         PCCHOLESKY, ""));
  if (!is_factor) return -1.0;
  MatSolverType type = nullptr;
  PLISSE_PETSC(PCFactorGetMatSolverType(pc, &type));
  if (type == nullptr || std::string(type) != MATSOLVERMUMPS) return -1.0;
  Mat F = nullptr;
  if (PCFactorGetMatrix(pc, &F) != 0 || F == nullptr) return -1.0;
  PetscInt entries = 0;
  if (MatMumpsGetInfog(F, 29, &entries) != 0) return -1.0;
  // INFOG(29) counts entries; a negative value is the count in millions (MUMPS user guide).
  return entries < 0 ? -1e6 * static_cast<double>(entries) : static_cast<double>(entries);
}

NewtonResult NewtonSolver::solve() {
  NewtonResult result;
  error_ = nullptr;
  interrupted_ = false;
  model_.get_free(x_);
  // The tangent's sparsity grew (contact pairs): a new matrix, which the factorisation analyses
  // anew.
  if (model_.pattern_version() != pattern_version_) make_matrix();
  const double assembly_before = times_.assembly;
  const auto t0 = WallClock::now();
  const PetscErrorCode code = SNESSolve(snes_, nullptr, x_);
  const double elapsed = seconds_since(t0);
  times_.linear_solve += elapsed - (times_.assembly - assembly_before);
  if (error_) std::rethrow_exception(error_);
  PLISSE_PETSC(code);
  model_.set_free(x_);
  SNESConvergedReason reason;
  PLISSE_PETSC(SNESGetConvergedReason(snes_, &reason));
  PetscInt its = 0, n_history = 0;
  PLISSE_PETSC(SNESGetIterationNumber(snes_, &its));
  PetscReal* h = nullptr;
  PLISSE_PETSC(SNESGetConvergenceHistory(snes_, &h, nullptr, &n_history));
  result.residual_history.assign(h, h + n_history);
  result.converged = reason > 0 && last_status_.ok;  // an interrupted solve has reason < 0
  result.iterations = static_cast<int>(its);
  result.residual_norm = result.residual_history.empty() ? 0.0 : result.residual_history.back();
  result.reason = interrupted_ ? "interrupted" : SNESConvergedReasons[reason];
  result.interrupted = interrupted_;
  result.status = last_status_;
  return result;
}

}  // namespace plisse
