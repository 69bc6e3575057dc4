#include "solver/newton_solver.hpp"

#include <algorithm>
#include <string>

#include "core/wall_clock.hpp"
#include "solver/linear_solver.hpp"
#include "solver/petsc_call.hpp"

namespace plisse {
namespace {

/// A reuse iteration is kept when it cuts ||R|| at least this much (newton_solver.hpp): at this
/// rate the factor's ten or so solves to rtol 1e-8 cost less than two factorisations.
constexpr double kReuseContraction = 0.1;
/// A Newton step the line search cut below this fraction is a short step; a failed solve of at
/// least kCrawlIterations iterations (or fewer, given up as stalled), three quarters of them short
/// under bt, says why and what to change (read_snes_outcome): its full steps kept raising the
/// residual.
constexpr double kShortStep = 0.5;
constexpr int kCrawlIterations = 4;
/// A failed solve whose residual fell this far below ||R(x_0)|| has converged as far as round-off
/// lets it: its tolerance lies below the problem's round-off floor (read_snes_outcome says so).
constexpr double kFloorReduction = 1e-6;
/// Reuse iterations per solve at most (chord and Krylov steps together).
constexpr int kReuseMaxIterations = 12;
/// A Krylov step solves K dx = -R to this relative residual: its iterate then cuts ||R|| by
/// about as much as Newton's exact step wherever that cut is less than a thousandfold.
constexpr double kKrylovRtol = 1e-3;
/// A Krylov step is kept when it cuts ||R|| at least this much; a smaller cut means the step
/// wants a line search, which SNES does.
constexpr double kKrylovContraction = 0.5;

/// The factored matrix of the SNES's preconditioner when it is a factorisation (LU or
/// Cholesky) that has been set up, else null.
Mat factor_of(SNES snes) {
  KSP ksp = nullptr;
  PC pc = nullptr;
  PLISSE_PETSC(SNESGetKSP(snes, &ksp));
  PLISSE_PETSC(KSPGetPC(ksp, &pc));
  PetscBool is_factor = PETSC_FALSE;
  PLISSE_PETSC(PetscObjectTypeCompareAny(reinterpret_cast<PetscObject>(pc), &is_factor, PCLU,
                                         PCCHOLESKY, ""));
  Mat F = nullptr;
  if (!is_factor || PCFactorGetMatrix(pc, &F) != 0) return nullptr;
  return F;
}

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

NewtonSolver::NewtonSolver(MixedModel& model, const NewtonSettings& settings)
    : model_(model), stall_(settings) {
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
  backtracking_ = settings.line_search == LineSearch::bt;
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
  // The tolerances after the options database (-snes_rtol, -snes_atol), for the reuse iterations.
  PetscReal atol = 0.0, rtol = 0.0;
  PLISSE_PETSC(SNESGetTolerances(snes_, &atol, &rtol, nullptr, nullptr, nullptr));
  atol_ = atol;
  rtol_ = rtol;
  reuse_enabled_ = settings.reuse_factor && settings.linear.type == LinearSolverType::direct;
  // A lag given in the PETSc options (-snes_lag_jacobian) is the user's: no chord steps then.
  PetscInt lag = 1;
  PLISSE_PETSC(SNESGetLagJacobian(snes_, &lag));
  chord_enabled_ = reuse_enabled_ && lag == 1;
  krylov_iterations_ = reuse_enabled_ ? settings.reuse_krylov_iterations : 0;
  PLISSE_PETSC(VecDuplicate(x_, &dx_));
  PLISSE_PETSC(VecDuplicate(x_, &r_kept_));
}

NewtonSolver::~NewtonSolver() {
  KSPDestroy(&krylov_);
  MatDestroy(&reuse_);
  VecDestroy(&r_kept_);
  VecDestroy(&dx_);
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
  // Relative to where solve() started, before any reuse iterations and before a refine(): the
  // test of a plain solve, at this solve's tolerance.
  if (it == 0 && self->reference_norm_ == 0.0) self->reference_norm_ = fnorm;
  if (*reason == SNES_CONVERGED_ITERATING && fnorm <= self->pass_rtol_ * self->reference_norm_)
    *reason = SNES_CONVERGED_FNORM_RELATIVE;
  if (it > 0 && self->chord_next_) ++self->chord_iterations_;  // iteration `it` was a chord step
  if (it > 0) {
    SNESLineSearch line_search = nullptr;
    PetscReal lambda = 1.0;
    PetscCall(SNESGetLineSearch(snes, &line_search));
    PetscCall(SNESLineSearchGetLambda(line_search, &lambda));
    if (lambda < kShortStep) ++self->short_steps_;
  }
  // A solve that crept for stall_iterations in a row is given up; the stepper cuts back. PETSc
  // 3.18 has no user reason: DIVERGED_DTOL ends it, and `stalled_` says why.
  if (self->stall_.stalled(fnorm) && *reason == SNES_CONVERGED_ITERATING) {
    self->stalled_ = true;
    *reason = SNES_DIVERGED_DTOL;
  }
  // The next iteration keeps the factor when this one cut ||R|| tenfold (newton_solver.hpp).
  self->chord_next_ = self->chord_enabled_ && self->reuse_allowed_ && it > 0 &&
                      fnorm <= kReuseContraction * self->previous_fnorm_;
  self->previous_fnorm_ = fnorm;
  if (self->chord_enabled_) PetscCall(SNESSetLagJacobian(snes, self->chord_next_ ? -1 : 1));
  self->passed_test_ =
      *reason == SNES_CONVERGED_FNORM_ABS || *reason == SNES_CONVERGED_FNORM_RELATIVE;
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
    ++self->jacobians_;
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
  const Mat F = factor_of(snes_);
  if (!is_mumps_factor(F)) return -1.0;
  PetscInt entries = 0;
  if (MatMumpsGetInfog(F, 29, &entries) != 0) return -1.0;
  return mumps_count(entries);  // INFOG(29): entries of the factor
}

void NewtonSolver::offer_factor(Mat factor) {
  factor_stale_ = false;
  if (factor == reuse_) return;
  if (factor) PLISSE_PETSC(PetscObjectReference(reinterpret_cast<PetscObject>(factor)));
  MatDestroy(&reuse_);
  reuse_ = factor;
}

Mat NewtonSolver::own_factor() const {
  const Mat F = factor_of(snes_);
  if (F == nullptr) return nullptr;
  MatFactorError error = MAT_FACTOR_NOERROR;
  PLISSE_PETSC(MatFactorGetError(F, &error));
  return error == MAT_FACTOR_NOERROR ? F : nullptr;
}

PetscErrorCode NewtonSolver::apply_reuse(PC pc, Vec r, Vec y) {
  void* context = nullptr;
  PetscCall(PCShellGetContext(pc, &context));
  return MatSolve(static_cast<NewtonSolver*>(context)->reuse_, r, y);
}

bool NewtonSolver::krylov_step(NewtonResult& result) {
  const auto t0 = WallClock::now();
  model_.set_free(x_);
  const AssemblyStatus status = model_.assemble_tangent(K_);
  times_.assembly += seconds_since(t0);
  if (!status.ok) return false;
  if (!krylov_) {
    // GMRES on the true residual (right preconditioning), preconditioned by the kept factor; no
    // restart within a step. Not in the options database: -ksp_* options are SNES's.
    PLISSE_PETSC(KSPCreate(model_.comm(), &krylov_));
    PLISSE_PETSC(KSPSetType(krylov_, KSPGMRES));
    PLISSE_PETSC(KSPSetPCSide(krylov_, PC_RIGHT));
    PLISSE_PETSC(KSPSetNormType(krylov_, KSP_NORM_UNPRECONDITIONED));
    PLISSE_PETSC(KSPSetTolerances(krylov_, kKrylovRtol, 0.0, PETSC_DEFAULT, krylov_iterations_));
    PLISSE_PETSC(KSPGMRESSetRestart(krylov_, krylov_iterations_));
    PC pc = nullptr;
    PLISSE_PETSC(KSPGetPC(krylov_, &pc));
    PLISSE_PETSC(PCSetType(pc, PCSHELL));
    PLISSE_PETSC(PCShellSetContext(pc, this));
    PLISSE_PETSC(PCShellSetApply(pc, &NewtonSolver::apply_reuse));
  }
  PLISSE_PETSC(KSPSetOperators(krylov_, K_, K_));
  PLISSE_PETSC(KSPSolve(krylov_, r_, dx_));
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  PLISSE_PETSC(KSPGetConvergedReason(krylov_, &reason));
  PetscInt its = 0;
  PLISSE_PETSC(KSPGetIterationNumber(krylov_, &its));
  result.reused_solves += static_cast<int>(its);
  if (reason <= 0) return false;
  ++result.krylov_steps;
  return true;
}

NewtonSolver::ReuseOutcome NewtonSolver::iterate_with_factor(NewtonResult& result) {
  const auto residual = [&](Vec x, double& norm) {
    const auto t0 = WallClock::now();
    model_.set_free(x);
    last_status_ = model_.assemble_residual(r_);
    times_.assembly += seconds_since(t0);
    PetscReal n = 0.0;
    PLISSE_PETSC(VecNorm(r_, NORM_2, &n));
    norm = n;
    return last_status_.ok;
  };
  if (!reuse_) return ReuseOutcome::not_started;
  MatFactorError error = MAT_FACTOR_NOERROR;
  PLISSE_PETSC(MatFactorGetError(reuse_, &error));  // its owner factorised it again and failed
  if (error != MAT_FACTOR_NOERROR) return ReuseOutcome::not_started;
  double norm = 0.0;
  // An inverted element: SNES meets it again and reports it.
  if (!residual(x_, norm)) return ReuseOutcome::not_started;
  if (reference_norm_ == 0.0) reference_norm_ = norm;
  const double target = tolerance();
  if (norm <= target) return ReuseOutcome::handed_over;  // SNES converges at once
  result.residual_history.push_back(norm);
  bool converged = false;
  // Chord steps while they cut ||R|| tenfold; from the first that does not (F's tangent is too
  // far from this one: a load step that moved it, contact nodes that changed state), Krylov
  // steps, which F only preconditions, while they halve ||R||. A factor that needed Krylov
  // steps once is not tried in chord steps again.
  bool krylov = krylov_iterations_ > 0 && factor_stale_;
  for (int k = 0; k < kReuseMaxIterations && !converged; ++k) {
    if (krylov) {
      if (!krylov_step(result)) break;  // dx_ = K^-1 R(x), or GMRES did not get there
    } else {
      PLISSE_PETSC(MatSolve(reuse_, r_, dx_));  // dx_ = F^-1 R(x)
      ++result.reused_solves;
    }
    PLISSE_PETSC(VecAYPX(dx_, -1.0, x_));  // dx_ = x - dx_, the trial iterate
    PLISSE_PETSC(VecCopy(r_, r_kept_));    // R(x), for SNES's start if the trial is refused
    const AssemblyStatus kept_status = last_status_;
    double trial = 0.0;
    // A trial that meets the tolerance is kept whatever its rate: near the round-off floor the
    // rate is noise, and refusing there would make the outcome depend on the last bits.
    const double rate = krylov ? kKrylovContraction : kReuseContraction;
    if (!residual(dx_, trial) || !(trial <= std::max(target, rate * norm))) {
      PLISSE_PETSC(VecCopy(r_kept_, r_));
      last_status_ = kept_status;
      if (krylov || krylov_iterations_ == 0) break;
      krylov = true;  // the same iterate again, with a Krylov step
      factor_stale_ = true;
      continue;
    }
    PLISSE_PETSC(VecCopy(dx_, x_));
    norm = trial;
    result.residual_history.push_back(norm);
    converged = norm <= target;
  }
  // Back to the last kept iterate (after a refused trial the model holds the trial).
  model_.set_free(x_);
  if (converged) return ReuseOutcome::converged;
  result.residual_history.pop_back();  // SNES's history starts with the same norm
  return ReuseOutcome::handed_over;
}

bool NewtonSolver::grow_factor_workspace(NewtonResult& result) {
  SNESConvergedReason reason;
  PLISSE_PETSC(SNESGetConvergedReason(snes_, &reason));
  if (reason != SNES_DIVERGED_LINEAR_SOLVE) return false;
  const Mat F = factor_of(snes_);
  const FactorMemory memory = factor_memory(F);
  if (memory.workspace_too_small) {
    if (reuse_ == F) offer_factor(nullptr);  // a failed factor is no use to reuse
    KSP ksp = nullptr;
    PC pc = nullptr;
    PLISSE_PETSC(SNESGetKSP(snes_, &ksp));
    PLISSE_PETSC(KSPGetPC(ksp, &pc));
    return plisse::grow_factor_workspace(pc, memory);
  }
  if (memory.out_of_memory) {
    result.out_of_memory = true;
    result.reason = memory.message();
  }
  return false;
}

NewtonResult NewtonSolver::solve(double rtol) {
  pass_rtol_ = std::max(rtol, rtol_);
  reference_norm_ = 0.0;  // the first residual of run()
  return run();
}

NewtonResult NewtonSolver::refine() {
  pass_rtol_ = rtol_;  // reference_norm_ stays the last solve's
  return run();
}

PetscErrorCode NewtonSolver::snes_solve() {
  // Every SNES solve starts with a fresh tangent; converged() lets later iterations keep it.
  chord_next_ = false;
  previous_fnorm_ = 0.0;
  stall_.restart();
  if (chord_enabled_) PLISSE_PETSC(SNESSetLagJacobian(snes_, 1));
  return SNESSolve(snes_, nullptr, x_);
}

bool NewtonSolver::chord_step_failed() const {
  // converged() is not called for an iteration whose line search failed: chord_next_ still says
  // how that iteration's direction was solved.
  SNESConvergedReason reason;
  PLISSE_PETSC(SNESGetConvergedReason(snes_, &reason));
  return reason == SNES_DIVERGED_LINE_SEARCH && chord_next_;
}

NewtonResult NewtonSolver::run() {
  NewtonResult result;
  error_ = nullptr;
  interrupted_ = false;
  passed_test_ = false;
  jacobians_ = 0;
  chord_iterations_ = 0;
  short_steps_ = 0;
  stalled_ = false;
  model_.get_free(x_);
  // The tangent's sparsity grew (contact pairs): a new matrix, which the factorisation analyses
  // anew; a factor of the old pattern is not reused.
  if (model_.pattern_version() != pattern_version_) {
    make_matrix();
    offer_factor(nullptr);
  }
  int earlier_iterations = 0;  // of solves ended by a workspace too small
  const bool reuse_converged = solve_timed(result, earlier_iterations);
  model_.set_free(x_);
  if (reuse_converged) {
    result.converged = last_status_.ok;
    result.residual_norm = result.residual_history.back();
    result.reason = "CONVERGED_FNORM_RELATIVE with a reused factorisation";
    result.reference_norm = reference_norm_;
    result.status = last_status_;
    return result;
  }
  read_snes_outcome(result, earlier_iterations);
  return result;
}

bool NewtonSolver::solve_timed(NewtonResult& result, int& earlier_iterations) {
  const double assembly_before = times_.assembly;
  const auto t0 = WallClock::now();
  bool reuse_converged = false;
  PetscErrorCode code = 0;
  try {
    const ReuseOutcome reuse =
        reuse_enabled_ && reuse_allowed_ ? iterate_with_factor(result) : ReuseOutcome::not_started;
    reuse_converged = reuse == ReuseOutcome::converged;
    // Handed over with R(x_) in r_: SNES starts from it instead of evaluating it again (the
    // model's bubbles may be the refused trial's; the next assembly solves them anew from there).
    if (reuse == ReuseOutcome::handed_over) PLISSE_PETSC(SNESSetInitialFunction(snes_, r_));
    if (!reuse_converged) code = snes_solve();
    if (!reuse_converged && code == 0 && !error_ && !interrupted_ && chord_step_failed()) {
      PetscInt its = 0;
      PLISSE_PETSC(SNESGetIterationNumber(snes_, &its));
      earlier_iterations += static_cast<int>(its);
      code = snes_solve();
    }
    while (!reuse_converged && code == 0 && !error_ && !interrupted_ &&
           grow_factor_workspace(result)) {
      PetscInt its = 0;
      PLISSE_PETSC(SNESGetIterationNumber(snes_, &its));
      earlier_iterations += static_cast<int>(its);
      code = snes_solve();
    }
  } catch (...) {
    times_.linear_solve += seconds_since(t0) - (times_.assembly - assembly_before);
    throw;
  }
  const double elapsed = seconds_since(t0);
  times_.linear_solve += elapsed - (times_.assembly - assembly_before);
  if (error_) std::rethrow_exception(error_);
  PLISSE_PETSC(code);
  return reuse_converged;
}

void NewtonSolver::read_snes_outcome(NewtonResult& result, int earlier_iterations) {
  SNESConvergedReason reason;
  PLISSE_PETSC(SNESGetConvergedReason(snes_, &reason));
  PetscInt its = 0, n_history = 0;
  PLISSE_PETSC(SNESGetIterationNumber(snes_, &its));
  PetscReal* h = nullptr;
  PLISSE_PETSC(SNESGetConvergenceHistory(snes_, &h, nullptr, &n_history));
  result.residual_history.insert(result.residual_history.end(), h, h + n_history);
  // An interrupted solve has reason < 0. A converged reason counts when it is a residual test:
  // plisse's (converged()), or PETSc's own ||F|| reasons (it sets FNORM_ABS itself on some
  // paths); CONVERGED_ITS after one linear step (-snes_type ksponly) or a step-length reason is
  // not a residual test.
  const bool residual_test =
      passed_test_ || reason == SNES_CONVERGED_FNORM_ABS || reason == SNES_CONVERGED_FNORM_RELATIVE;
  result.converged = reason > 0 && residual_test && last_status_.ok;
  result.reference_norm = reference_norm_;
  // The freshest factor is now SNES's own, when it factorised in a solve that converged; one made
  // at the iterates of a failed solve is not reused.
  if (reuse_enabled_ && jacobians_ > 0) {
    const Mat own = own_factor();
    if (result.converged)
      offer_factor(own);
    else if (reuse_ == own)
      offer_factor(nullptr);
  }
  // Chord steps factorise nothing: they count as reused solves, not as Newton iterations.
  result.iterations = earlier_iterations + static_cast<int>(its) - chord_iterations_;
  result.reused_solves += chord_iterations_;
  result.residual_norm = result.residual_history.empty() ? 0.0 : result.residual_history.back();
  if (!result.out_of_memory) {  // else its reason says how much memory was asked for
    result.reason = interrupted_ ? "interrupted"
                    : stalled_   ? stall_.describe()
                                 : SNESConvergedReasons[reason];
    if (reason > 0 && !residual_test)
      result.reason +=
          " without plisse's residual test (a PETSc option such as -snes_type ksponly "
          "skips it): the state is not accepted";
    const double lowest =
        result.residual_history.empty()
            ? 0.0
            : *std::min_element(result.residual_history.begin(), result.residual_history.end());
    const double target = tolerance();
    if (!result.converged && !interrupted_ && last_status_.ok && lowest > target &&
        lowest <= kFloorReduction * reference_norm_) {
      char floor[320];
      std::snprintf(floor, sizeof floor,
                    "; the residual fell from %.3g to %.3g but no step took it to the tolerance "
                    "%.3g: the round-off floor of this problem lies above its tolerance; a looser "
                    "solver.newton.rtol or atol accepts the state",
                    reference_norm_, lowest, target);
      result.reason += floor;
    } else if (!result.converged && !interrupted_ && backtracking_ &&
               (its >= kCrawlIterations || stalled_) &&
               4 * short_steps_ >= 3 * static_cast<int>(its))
      result.reason += "; the line search shortened " + std::to_string(short_steps_) + " of " +
                       std::to_string(its) +
                       " steps: each full Newton step raised the residual, as a small load "
                       "carried in bending from a flat start or a cap's turn does (second-order "
                       "membrane forces, a rotation's second-order gap); "
                       "solver.newton.line_search: cp, which minimises along the step, takes it";
  }
  result.interrupted = interrupted_;
  result.status = last_status_;
}

}  // namespace plisse
