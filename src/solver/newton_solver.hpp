#pragma once
/// Newton-Raphson with line search on a MixedModel through PETSc's SNES, with a direct solver
/// (MUMPS; Cholesky-type LDL^T for the symmetric tangent) by default. Every option can be
/// overridden with PETSc's own options (-snes_*, -ksp_*, -pc_*, -mat_mumps_*).
///
/// Factor reuse (NewtonSettings::reuse_factor, direct solver). A factorisation costs several
/// residual evaluations and triangular solves. Before SNES factorises anew, solve() iterates
///
///   x_{k+1} = x_k - F^-1 R(x_k)
///
/// with the freshest factor F at hand: Newton's own last one (from the previous step, or from
/// the solve before a contact multiplier update, whose tangent barely differs), or one offered
/// by the caller (the stability check's LDL^T of the last converged state). An iterate is kept
/// only when ||R(x_{k+1})|| <= kReuseContraction ||R(x_k)|| and the assembly succeeded; at the
/// first iterate that is not, SNES's Newton continues from x_k. The convergence test stays the
/// one of a plain Newton solve: ||R|| <= max(atol, rtol ||R(x_0)||) with x_0 the state solve()
/// started from, so the answer differs from a solve without reuse only within that tolerance.
///
/// When a chord step x_k - F^-1 R(x_k) does not cut ||R|| tenfold (F's tangent is too far from
/// the current one: the load moved, contact nodes changed state), the iteration goes on with
/// Krylov steps from x_k instead of handing over: the tangent K(x_k) is assembled and
///
///   K(x_k) dx = -R(x_k)
///
/// solved by GMRES preconditioned with F (F^-1 K = I plus a low-rank part for the nodes that
/// changed state, plus a small part for the load step) to kKrylovRtol; x_k + dx is kept when it
/// halves ||R||. A Krylov step costs a tangent assembly and a few triangular solves, against a
/// factorisation for a Newton iteration. NewtonSettings::reuse_krylov_iterations bounds GMRES;
/// when it does not converge, or the step is not kept, SNES's Newton takes over from x_k.
///
/// Within SNES, the same rule: after an iteration that cut ||R|| at least kReuseContraction-fold,
/// the next one keeps the tangent and its factor (a chord step, through SNES's Jacobian lag);
/// after one that did not, Newton assembles and factorises anew. A chord step is taken, not
/// refused, since its line search still asks ||R|| to decrease; when the line search finds no
/// decrease along a chord direction, Newton starts again from there with a new tangent (once per
/// solve). Not done when the user gives -snes_lag_jacobian, nor while reuse is suspended
/// (allow_reuse).
#include <petscsnes.h>

#include <algorithm>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "solver/mixed_model.hpp"
#include "solver/newton_settings.hpp"
#include "solver/stall_watch.hpp"

namespace plisse {

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  double residual_norm = 0.0;
  std::vector<double> residual_history;  ///< ||R|| at the start and after each iteration
  int reused_solves = 0;  ///< solves with a factor already at hand, kept or not: chord steps and
                          ///< the GMRES iterations of Krylov steps (not counted in `iterations`:
                          ///< no factorisation)
  int krylov_steps = 0;   ///< Newton steps solved by GMRES with a factor already at hand
  double reference_norm = 0.0;  ///< ||R(x_0)|| of the relative test (of the solve refined)
  std::string reason;           ///< PETSc's converged/diverged reason, in words
  AssemblyStatus status;        ///< of the last residual evaluation
  bool interrupted = false;     ///< stopped because set_interrupt's test said so
  /// The factorisation could not allocate its memory (MUMPS INFOG(1) = -13 or -19): `reason`
  /// says how much it asked for. A smaller load step needs as much: not worth a cut-back.
  bool out_of_memory = false;
};

/// Wall time spent per phase [s], accumulated over all solves.
struct PhaseTimes {
  double assembly = 0.0;  ///< residual and tangent assembly
  double linear_solve =
      0.0;  ///< everything in SNES but assembly: factorisation, solves, line search
  double factorisation = 0.0;     ///< symbolic and numeric factorisation (PETSc's event log)
  double triangular_solve = 0.0;  ///< forward/backward substitution (PETSc's event log)
  int factorisations = 0;         ///< numeric factorisations
};

/// Sets plisse's defaults on `snes` (tolerances, line search, direct solve with MUMPS: LDL^T when
/// `symmetric`, else LU); PETSc's options database may override them afterwards.
void configure_snes(SNES snes, const NewtonSettings& settings, bool symmetric);

/// Applies the options database to a solver configured as plisse's: throws plisse::Error when
/// PETSc refuses them (unknown types, bad values), before any model is built.
void check_petsc_options(const NewtonSettings& settings);

class NewtonSolver {
 public:
  NewtonSolver(MixedModel& model, const NewtonSettings& settings);
  ~NewtonSolver();
  NewtonSolver(const NewtonSolver&) = delete;
  NewtonSolver& operator=(const NewtonSolver&) = delete;

  /// Solves R(x) = 0 from the model's current state (constrained values already applied), to
  /// ||R|| <= max(atol, rtol ||R(x_0)||); `rtol` > settings' rtol loosens this solve (0: the
  /// settings'). On return the model holds the last iterate, converged or not.
  NewtonResult solve(double rtol = 0.0);
  /// Continues the last solve, from the model's state, to the settings' rtol relative to that
  /// solve's ||R(x_0)||: a loose solve made tight, as if it had been tight from the start.
  NewtonResult refine();
  /// `stop` is asked after every Newton iteration, on every rank at once (it may be collective);
  /// when it says true, the solve ends unconverged with `interrupted` set (a signal arrived).
  /// Installed as SNES's convergence test around SNESConvergedDefault.
  void set_interrupt(std::function<bool()> stop) { interrupt_ = std::move(stop); }
  /// Wall time per phase; the factorisation and solve parts read PETSc's event log.
  PhaseTimes times() const;
  /// Entries of the last MUMPS factorisation (INFOG(29)); -1 when the linear solver is not a
  /// MUMPS factorisation (e.g. changed by PETSc options) or nothing was factorised yet.
  double factor_entries() const;
  /// A factorisation of a tangent near the next solve's start (a factored Mat of the same free
  /// equations, e.g. InertiaCheck::factor), used by the next solve's reuse iterations until a
  /// fresher one exists; null forgets it. Referenced, not copied: its owner may factorise it
  /// again later, which is then what the next solve uses.
  void offer_factor(Mat factor);
  /// Suspends (false) or resumes factor reuse. The stepper suspends it at states its stability
  /// check finds unstable: there the modified iteration multiplies the error along a direction
  /// of negative stiffness by 1 - lambda/lambda_F > 1 (lambda_F, the factor's eigenvalue, of the
  /// other sign or far smaller), and would push a perfect branch off by amplified round-off,
  /// which Newton's exact tangent leaves alone.
  void allow_reuse(bool allowed) { reuse_allowed_ = allowed; }

 private:
  static PetscErrorCode form_function(SNES snes, Vec x, Vec f, void* context);
  static PetscErrorCode form_jacobian(SNES snes, Vec x, Mat J, Mat P, void* context);
  static PetscErrorCode converged(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm,
                                  PetscReal fnorm, SNESConvergedReason* reason, void* context);
  /// (Re)makes K_ with the model's current sparsity and hands it to SNES.
  void make_matrix();
  /// SNES's own factor of K_ when its preconditioner is a factorisation, else null.
  Mat own_factor() const;
  /// How the reuse iterations ended.
  enum class ReuseOutcome {
    not_started,  ///< no factor to use, or R(x_) could not be assembled: r_ says nothing
    handed_over,  ///< Newton's turn: r_ holds R(x_), the last kept iterate's residual
    converged,    ///< the last kept iterate meets the tolerance
  };
  /// The reuse iterations from the model's state; return with the model at the last kept iterate
  /// and reference_norm_ set. Counts into `result`.
  ReuseOutcome iterate_with_factor(NewtonResult& result);
  /// A Krylov step's correction: dx_ = K(x_)^-1 r_ by GMRES preconditioned with reuse_, the
  /// tangent assembled at x_ into K_. False when the tangent could not be assembled or GMRES
  /// did not reach kKrylovRtol in krylov_iterations_. Counts into `result`.
  bool krylov_step(NewtonResult& result);
  /// PCSHELL's apply: y = reuse_^-1 r.
  static PetscErrorCode apply_reuse(PC pc, Vec r, Vec y);
  /// solve() and refine() with pass_rtol_ and reference_norm_ set (0: the first ||R||).
  NewtonResult run();
  /// The solve of run(), timed into times_: the reuse iterations, then SNES (again after each
  /// growth of the factor's workspace, counting the iterations before it into
  /// `earlier_iterations`). Returns true when the reuse iterations converged. Rethrows an error
  /// of the model's callbacks or PETSc's.
  bool solve_timed(NewtonResult& result, int& earlier_iterations);
  /// After SNES ended: its reason, iterations and residual history into `result`, and which
  /// factor the next solve may reuse.
  void read_snes_outcome(NewtonResult& result, int earlier_iterations);
  /// SNESSolve from x_, its first iteration with a new tangent.
  PetscErrorCode snes_solve();
  /// After snes_solve(): its line search failed in a chord step. A kept tangent can be far
  /// enough from the current one in some direction that the chord direction does not lower
  /// ||R|| at all, even where Newton's own converges; solve_timed() then solves again from the
  /// iterate reached, with a new tangent, once.
  bool chord_step_failed() const;
  /// After a failed linear solve: when MUMPS's workspace, sized from its analysis's estimate and
  /// ICNTL(14) percent more, proved too small, grows it for a new factor (plisse::
  /// grow_factor_workspace) and returns true (the solve goes on from the iterate reached); when
  /// MUMPS could not allocate memory at all, sets `result.out_of_memory` and its reason.
  bool grow_factor_workspace(NewtonResult& result);

  MixedModel& model_;
  SNES snes_ = nullptr;
  Vec x_ = nullptr, r_ = nullptr;
  Mat K_ = nullptr;
  int pattern_version_ = 0;  ///< the model's pattern_version when K_ was made
  std::vector<PetscReal> history_;
  std::exception_ptr error_;
  AssemblyStatus last_status_;
  PhaseTimes times_;
  std::function<bool()> interrupt_;
  bool interrupted_ = false;  ///< the current solve was stopped by interrupt_
  /// plisse's residual test (converged()) declared the current solve converged: a converged
  /// reason from SNES without it (an option such as -snes_type ksponly skips the test) is not
  /// accepted.
  bool passed_test_ = false;
  bool reuse_enabled_ = false;
  bool reuse_allowed_ = true;
  double rtol_ = 0.0, atol_ = 0.0;
  Mat reuse_ = nullptr;          ///< the factor of the reuse iterations (referenced), or null
  Vec dx_ = nullptr;             ///< scratch of the reuse iterations
  Vec r_kept_ = nullptr;         ///< R at the last kept reuse iterate (scratch)
  double reference_norm_ = 0.0;  ///< ||R|| where the current solve started (convergence test)
  double pass_rtol_ = 0.0;       ///< relative tolerance of the current solve
  /// The ||R|| the current solve must reach: max(atol, pass_rtol_ ||R(x_0)||).
  double tolerance() const { return std::max(atol_, pass_rtol_ * reference_norm_); }
  int jacobians_ = 0;            ///< tangent assemblies in the current solve
  bool chord_enabled_ = false;   ///< SNES may keep its factor between iterations (chord steps)
  bool chord_next_ = false;      ///< the coming SNES iteration keeps the factor
  double previous_fnorm_ = 0.0;  ///< ||R|| at the last SNES iteration
  int chord_iterations_ = 0;     ///< SNES iterations in the current solve that kept the factor
  StallWatch stall_;             ///< gives a stalled solve up (converged())
  bool stalled_ = false;         ///< the current solve was given up by stall_
  int short_steps_ = 0;  ///< SNES iterations in the current solve whose line search cut the step
                         ///< below half (failure_hint)
  bool backtracking_ = false;  ///< the line search is bt (NewtonSettings::line_search)
  KSP krylov_ = nullptr;       ///< GMRES of the Krylov steps, made at the first one
  int krylov_iterations_ = 0;  ///< GMRES iterations per Krylov step at most; 0: none
  /// A chord step with reuse_ was refused: its solves start with Krylov steps.
  bool factor_stale_ = false;
};

}  // namespace plisse
