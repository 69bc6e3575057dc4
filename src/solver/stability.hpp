#pragma once
/// Stability of a converged state from the inertia of its tangent (docs/theory/stability.md).
/// The tangent of the mixed u-p problem is a saddle-point matrix; by Sylvester's law of inertia a
/// state is stable (the displacement block is positive definite on the constraints) exactly when
/// an LDL^T factorisation has as many negative pivots as there are free pressure unknowns plus the
/// negative directions of the terms' global unknowns (S4-S6), and no zero pivot.
#include <petscmat.h>
#include <petscpc.h>

#include "solver/mixed_model.hpp"

namespace plisse {

/// Counts of negative, zero and positive pivots of an LDL^T factorisation (= eigenvalue signs).
struct Inertia {
  int negative = 0;
  int zero = 0;  ///< null pivots detected by MUMPS (ICNTL(24) = 1): a critical point
  int positive = 0;
};

/// Negative pivots of a stable tangent of `model`: its free pressure unknowns plus
/// ModelTerm::negative_directions of every term (stability.md, S4-S6).
int expected_negative_pivots(const MixedModel& model);

/// The inertia of the tangent of one model at its current state, by a MUMPS LDL^T factorisation
/// (PCCHOLESKY with MATSOLVERMUMPS, sym = 2). The matrix, the factor and MUMPS's symbolic analysis
/// are kept between calls: the nonzero pattern does not change, so each call costs one assembly
/// and one numeric factorisation. PETSc options with the prefix `stability_` reach this factor
/// (e.g. -stability_mat_mumps_cntl_3 for the null-pivot threshold). The factorisations are logged
/// in their own PETSc log stage "Stability check", so that NewtonSolver::times() (main stage)
/// counts Newton's alone.
class InertiaCheck {
 public:
  /// Borrows `model` (must outlive the check). Requires a live PetscSession.
  explicit InertiaCheck(MixedModel& model);
  ~InertiaCheck();
  InertiaCheck(const InertiaCheck&) = delete;
  InertiaCheck& operator=(const InertiaCheck&) = delete;

  /// Assembles the tangent at the model's current state (the state is not changed) and returns
  /// the inertia of K, or of its symmetric part 0.5 (K + K^T) when the model's tangent is not
  /// symmetric (stability.md, S8). Throws plisse::Error on a failed assembly or factorisation.
  Inertia compute();
  /// The LDL^T factor of the tangent from the last successful compute(), for NewtonSolver's
  /// factor reuse (NewtonSolver::offer_factor); null when the tangent is unsymmetric (the factor
  /// is then of its symmetric part, not of the tangent) or nothing was factorised.
  Mat factor() const;
  /// True when compute() factorises 0.5 (K + K^T) because the tangent is unsymmetric.
  bool uses_symmetric_part() const { return !symmetric_; }
  /// Wall time spent in compute() [s] (assembly + factorisation) and the number of calls.
  double seconds() const { return seconds_; }
  /// The part of seconds() spent assembling the tangent (and forming 0.5 (K + K^T)) [s].
  double assembly_seconds() const { return assembly_seconds_; }
  int calls() const { return calls_; }

 private:
  /// The symmetric matrix to factorise: K itself, or 0.5 (K + K^T) in S_.
  Mat symmetric_operator();

  MixedModel& model_;
  bool symmetric_ = true;
  Mat K_ = nullptr;                ///< tangent over the free dofs
  int pattern_version_ = 0;        ///< the model's pattern_version when K_ was made
  Mat Kt_ = nullptr;               ///< K^T (unsymmetric models only)
  Mat S_ = nullptr;                ///< 0.5 (K + K^T) (unsymmetric models only)
  PetscObjectState pattern_ = -1;  ///< nonzero state of K_ when S_ was built
  PC pc_ = nullptr;
  PetscLogStage stage_ = -1;  ///< PETSc log stage of the checks, apart from Newton's main stage
  bool configured_ = false;
  double seconds_ = 0.0, assembly_seconds_ = 0.0;
  int calls_ = 0;
};

}  // namespace plisse
