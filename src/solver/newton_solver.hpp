#pragma once
/// Newton-Raphson with line search on a MixedModel through PETSc's SNES, with a direct solver
/// (MUMPS; Cholesky-type LDL^T for the symmetric tangent) by default. Every option can be
/// overridden with PETSc's own options (-snes_*, -ksp_*, -pc_*, -mat_mumps_*).
#include <petscsnes.h>

#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "solver/mixed_model.hpp"
#include "solver/newton_settings.hpp"

namespace plisse {

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  double residual_norm = 0.0;
  std::vector<double> residual_history;  ///< ||R|| at the start and after each iteration
  std::string reason;                    ///< PETSc's converged/diverged reason, in words
  AssemblyStatus status;                 ///< of the last residual evaluation
  bool interrupted = false;              ///< stopped because set_interrupt's test said so
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

  /// Solves R(x) = 0 from the model's current state (constrained values already applied).
  /// On return the model holds the last iterate, converged or not.
  NewtonResult solve();
  /// `stop` is asked after every Newton iteration, on every rank at once (it may be collective);
  /// when it says true, the solve ends unconverged with `interrupted` set (a signal arrived).
  /// Installed as SNES's convergence test around SNESConvergedDefault.
  void set_interrupt(std::function<bool()> stop) { interrupt_ = std::move(stop); }
  /// Wall time per phase; the factorisation and solve parts read PETSc's event log.
  PhaseTimes times() const;
  /// Entries of the last MUMPS factorisation (INFOG(29)); -1 when the linear solver is not a
  /// MUMPS factorisation (e.g. changed by PETSc options) or nothing was factorised yet.
  double factor_entries() const;

 private:
  static PetscErrorCode form_function(SNES snes, Vec x, Vec f, void* context);
  static PetscErrorCode form_jacobian(SNES snes, Vec x, Mat J, Mat P, void* context);
  static PetscErrorCode converged(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm,
                                  PetscReal fnorm, SNESConvergedReason* reason, void* context);
  /// (Re)makes K_ with the model's current sparsity and hands it to SNES.
  void make_matrix();

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
};

}  // namespace plisse
