#include "solver/arc_length.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/error.hpp"
#include "solver/linear_solver.hpp"
#include "solver/petsc_call.hpp"
#include "solver/stall_watch.hpp"

namespace plisse {
namespace {

/// The step of the one-sided difference dR/dt ≈ (R(x, t + δ) - R(x, t)) / δ, as a fraction of
/// end_time: loads and motions that follow linear ramps make R affine in t, where the difference
/// is exact up to round-off, about 1e-16 / 1e-7 of ||q|| (A3).
constexpr double kTimeDifference = 1e-7;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double dot(Vec a, Vec b) {
  PetscScalar value = 0.0;
  PLISSE_PETSC(VecDot(a, b, &value));
  return PetscRealPart(value);
}

double norm(Vec v) {
  PetscReal value = 0.0;
  PLISSE_PETSC(VecNorm(v, NORM_2, &value));
  return value;
}

}  // namespace

ArcLengthSolver::ArcLengthSolver(MixedModel& model, const NewtonSettings& settings, double end_time)
    : model_(model), settings_(settings), end_time_(end_time) {
  PLISSE_PETSC(PCCreate(model.comm(), &pc_));
  PLISSE_PETSC(PCSetOptionsPrefix(pc_, "arc_length_"));
  PLISSE_PETSC(PCSetType(pc_, model.symmetric() ? PCCHOLESKY : PCLU));
  PLISSE_PETSC(PCFactorSetMatSolverType(pc_, MATSOLVERMUMPS));
}

ArcLengthSolver::~ArcLengthSolver() {
  PCDestroy(&pc_);
  MatDestroy(&K_);
  for (Vec* v : {&x_, &r_, &q_, &a_, &b_, &x_n_, &last_, &increment_}) VecDestroy(v);
}

void ArcLengthSolver::prepare() {
  if (!x_) {
    x_ = model_.create_vector();
    for (Vec* v : {&r_, &q_, &a_, &b_, &x_n_, &last_, &increment_})
      PLISSE_PETSC(VecDuplicate(x_, v));
  }
  if (!K_ || pattern_version_ != model_.pattern_version()) {
    MatDestroy(&K_);
    K_ = model_.create_matrix();
    pattern_version_ = model_.pattern_version();
    PLISSE_PETSC(PCReset(pc_));
    PLISSE_PETSC(PCSetType(pc_, model_.symmetric() ? PCCHOLESKY : PCLU));
    PLISSE_PETSC(PCFactorSetMatSolverType(pc_, MATSOLVERMUMPS));
  }
}

void ArcLengthSolver::free_of(const std::vector<double>& full, Vec out) {
  std::vector<double> kept = model_.state();
  model_.state() = full;
  model_.get_free(out);
  model_.state() = std::move(kept);
}

bool ArcLengthSolver::residual(double t, NewtonResult& result) {
  const auto start = std::chrono::steady_clock::now();
  model_.set_time(t);
  model_.set_free(x_);
  result.status = model_.assemble_residual(r_);
  assembly_seconds_ += seconds_since(start);
  return result.status.ok;
}

bool ArcLengthSolver::tangent(double t, bool have_residual, NewtonResult& result) {
  auto start = std::chrono::steady_clock::now();
  // q = dR/dt: forward in t, backward at the ramps' end (a ramp may stop there).
  const double step = kTimeDifference * end_time_;
  const double shifted = t + step <= end_time_ ? t + step : t - step;
  model_.set_time(shifted);
  model_.set_free(x_);
  AssemblyStatus status = model_.assemble_residual(q_);
  model_.set_time(t);  // the constrained values only: the free ones stay x_
  // The reactions the model keeps are then those of (x, t + δ) until the next residual: the
  // corrector assembles one at every iterate, the converged one last.
  if (status.ok && !have_residual) status = model_.assemble_residual(r_);
  if (status.ok) status = model_.assemble_tangent(K_);
  assembly_seconds_ += seconds_since(start);
  if (!status.ok) {
    result.status = status;
    return false;
  }
  PLISSE_PETSC(VecAXPY(q_, -1.0, r_));
  PLISSE_PETSC(VecScale(q_, 1.0 / (shifted - t)));
  start = std::chrono::steady_clock::now();
  PLISSE_PETSC(PCSetOperators(pc_, K_, K_));
  const PetscErrorCode error = PCSetUp(pc_);
  PCFailedReason failed = PC_NOERROR;
  if (error == 0) PLISSE_PETSC(PCGetFailedReason(pc_, &failed));
  if (error != 0 || failed != PC_NOERROR) {
    Mat F = nullptr;
    if (PCFactorGetMatrix(pc_, &F) == 0) {
      const FactorMemory memory = factor_memory(F);
      if (memory.out_of_memory) {
        result.out_of_memory = true;
        result.reason = memory.message();
      } else if (memory.workspace_too_small && grow_factor_workspace(pc_, memory)) {
        solve_seconds_ += seconds_since(start);
        return tangent(t, true, result);
      }
    }
    if (result.reason.empty()) result.reason = "the factorisation of the tangent failed";
    solve_seconds_ += seconds_since(start);
    return false;
  }
  solve_seconds_ += seconds_since(start);
  return true;
}

void ArcLengthSolver::apply_inverse(Vec v, Vec y) {
  const auto start = std::chrono::steady_clock::now();
  PLISSE_PETSC(PCApply(pc_, v, y));
  solve_seconds_ += seconds_since(start);
}

double ArcLengthSolver::distance_from(const std::vector<double>& state) {
  prepare();
  model_.restore_converged();
  model_.get_free(x_n_);
  free_of(state, last_);
  PLISSE_PETSC(VecAXPY(last_, -1.0, x_n_));
  return norm(last_);
}

ArcLengthPredictor ArcLengthSolver::predict(double t_n, double arc,
                                            const std::vector<double>& previous_state,
                                            NewtonResult& result) {
  prepare();
  model_.restore_converged();
  model_.get_free(x_n_);
  PLISSE_PETSC(VecCopy(x_n_, x_));
  ArcLengthPredictor p;
  if (!tangent(t_n, false, result)) {
    model_.restore_converged();
    model_.set_time(t_n);
    return p;
  }
  // (A1) b = -K^-1 q; dt = ±s / ||b||, signed so that the increment goes on the way the last
  // one went (b · (x_n - x_{n-1}) > 0), forward in t at the first step.
  PLISSE_PETSC(VecScale(q_, -1.0));
  apply_inverse(q_, b_);
  p.rate = norm(b_);
  double sign = 1.0;
  if (!previous_state.empty()) {
    free_of(previous_state, last_);
    PLISSE_PETSC(VecAYPX(last_, -1.0, x_n_));  // x_n - x_{n-1}
    if (norm(last_) > 0.0 && dot(b_, last_) < 0.0) sign = -1.0;
  }
  p.load_step = p.rate > 0.0 ? sign * arc / p.rate : 0.0;
  model_.restore_converged();
  model_.set_time(t_n);
  return p;
}

NewtonResult ArcLengthSolver::solve(double t_n, double arc,
                                    const std::vector<double>& previous_state, double& t,
                                    ArcLengthPredictor& predictor) {
  NewtonResult result;
  t = t_n;
  left_ramps_ = false;
  predictor = predict(t_n, arc, previous_state, result);
  if (predictor.rate <= 0.0 || !std::isfinite(predictor.load_step)) {
    // The tangent at the converged state failed (result says why), or the load moves nothing.
    if (result.reason.empty())
      result.reason = predictor.rate <= 0.0
                          ? "at the last converged state the load does not move the free "
                            "unknowns (dR/dt = 0: no load changes with t there)"
                          : "the predictor is not finite";
    return result;
  }
  // A predictor past end_time (or below 0), where the ramps hold, is shortened to end there: the
  // corrector then finds the point of the path at the bound, or a limit point before it (A8).
  const double t_p = t_n + predictor.load_step;
  if (t_p > end_time_ || t_p < 0.0) {
    const double f = ((t_p > end_time_ ? end_time_ : 0.0) - t_n) / predictor.load_step;
    if (f > 0.0) {
      arc *= f;
      predictor.load_step *= f;
    }
  }
  used_arc_ = arc;
  // x_p = x_n + dt b, t_p = t_n + dt (b_ still holds the converged state's direction).
  PLISSE_PETSC(VecWAXPY(x_, predictor.load_step, b_, x_n_));
  t = t_n + predictor.load_step;
  // ||q|| |t_p - t_n| (A6): q_ holds -q at the converged state since the predictor.
  reference_ = norm(q_) * std::abs(predictor.load_step);
  return correct(arc, t, result);
}

NewtonResult ArcLengthSolver::correct(double arc, double& t) {
  NewtonResult result;
  return correct(arc, t, result);
}

NewtonResult ArcLengthSolver::correct(double arc, double& t, NewtonResult& result) {
  result.reference_norm = reference_;
  StallWatch stall(settings_);
  for (int k = 0;; ++k) {
    // Beyond [0, end_time] the ramps hold their end values and dR/dt = 0: the caller lands on the
    // bound by load control (A8).
    if (t > end_time_ || t < 0.0) {
      left_ramps_ = true;
      model_.set_time(t);
      model_.set_free(x_);
      result.reason = "the load parameter left [0, end_time]";
      return result;
    }
    if (!residual(t, result)) {
      result.reason = "an element could not be evaluated";
      return result;
    }
    result.residual_norm = norm(r_);
    result.residual_history.push_back(result.residual_norm);
    if (!std::isfinite(result.residual_norm)) {
      result.reason = "the residual is not finite";
      return result;
    }
    if (result.residual_norm <= std::max(settings_.atol, settings_.rtol * reference_)) {
      result.converged = true;
      result.reason = "converged";
      return result;
    }
    if (stall.stalled(result.residual_norm)) {
      result.reason = stall.describe();
      return result;
    }
    if (k >= settings_.max_iterations) {
      result.reason = "no convergence in " + std::to_string(settings_.max_iterations) +
                      " iterations (solver.newton.max_iterations)";
      return result;
    }
    if (interrupt_ && interrupt_()) {
      result.interrupted = true;
      result.reason = "interrupted";
      return result;
    }
    if (!tangent(t, true, result)) {
      if (result.reason.empty()) result.reason = "an element could not be evaluated";
      return result;
    }
    ++result.iterations;
    // (A3) a = -K^-1 R, b = -K^-1 q.
    PLISSE_PETSC(VecScale(r_, -1.0));
    apply_inverse(r_, a_);
    PLISSE_PETSC(VecScale(q_, -1.0));
    apply_inverse(q_, b_);
    // (A4) ||d + a + dt b||^2 = s^2 with d = x - x_n: c1 dt^2 + c2 dt + c3 = 0.
    PLISSE_PETSC(VecWAXPY(increment_, -1.0, x_n_, x_));  // d
    PLISSE_PETSC(VecWAXPY(last_, 1.0, a_, increment_));  // d + a
    const double c1 = dot(b_, b_);
    const double c2 = 2.0 * dot(b_, last_);
    const double c3 = dot(last_, last_) - arc * arc;
    const double discriminant = c2 * c2 - 4.0 * c1 * c3;
    if (!(c1 > 0.0) || discriminant < 0.0) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "the correction leaves the arc (no real root of the constraint, "
                    "discriminant %.3g): the arc length is too long for the path's curvature",
                    discriminant);
      result.reason = text;
      return result;
    }
    // (A5) Of the two roots, the one whose increment d + a + dt b turns least from d: the larger
    // (d + a + dt b) · d = (d + a) · d + dt (b · d).
    const double root = std::sqrt(discriminant);
    const double q_sign = c2 >= 0.0 ? 1.0 : -1.0;
    const double big = -0.5 * (c2 + q_sign * root);  // cancellation-free pair of roots
    const double dt1 = big / c1;
    const double dt2 = big != 0.0 ? c3 / big : dt1;
    const double along = dot(b_, increment_);
    const double base = dot(last_, increment_);
    const double dt = (base + dt1 * along >= base + dt2 * along) ? dt1 : dt2;
    // x += a + dt b, t += dt.
    PLISSE_PETSC(VecAXPY(x_, 1.0, a_));
    PLISSE_PETSC(VecAXPY(x_, dt, b_));
    t += dt;
  }
}

}  // namespace plisse
