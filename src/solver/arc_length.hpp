#pragma once
/// Arc-length continuation of one step (solver.control: arc-length): the load parameter t (the
/// pseudo-time, which every load and prescribed motion follows through its ramp) becomes an
/// unknown beside the free state x, and the step is bounded by the length of its increment
/// instead of by its load. The path R(x, t) = 0 is then followed past a limit point (a maximum of
/// the load, where load control stops) and through a snap-back.
///
/// Crisfield's cylindrical constraint (Crisfield 1981: his spherical constraint with the load
/// term left out, so that the step's size does not depend on the load's units):
///
///   ||x - x_n||^2 = s^2                                          (docs/theory/arc_length.md, A2)
///
/// over the free unknowns (displacements in mm, pressures weighted into mm as every free vector
/// is, docs/theory/mixed_up.md X1). Each iteration solves two systems with one factorisation of
/// the tangent K = dR/dx (Batoz & Dhatt 1979):
///
///   K a = -R,  K b = -q,  q = dR/dt (by a one-sided difference in t),     (A3)
///
/// takes the correction dx = a + dt b with the root dt of the constraint's quadratic that keeps
/// the increment closest to the last one (A4, A5), and stops when ||R|| <= max(atol, rtol
/// ||q|| |t_p - t_n|), the out-of-balance force measured against the one the predictor's load
/// increment makes (A6). Beyond [0, end_time] the ramps hold and q = 0: an iterate there ends the
/// corrector (left_ramps), and the stepper lands on the bound by load control (A8).
#include <petscpc.h>

#include <functional>
#include <vector>

#include "solver/mixed_model.hpp"
#include "solver/newton_settings.hpp"
#include "solver/newton_solver.hpp"

namespace plisse {

/// The step's predictor at the converged state (A1).
struct ArcLengthPredictor {
  double load_step = 0.0;  ///< dt of the predictor: the arc length along b, signed (A1)
  double rate = 0.0;       ///< ||b|| = ||K^-1 dR/dt|| at the converged state [mm per unit of t]
};

class ArcLengthSolver {
 public:
  /// `end_time` [s] scales the difference step of dR/dt (A3).
  ArcLengthSolver(MixedModel& model, const NewtonSettings& settings, double end_time);
  ~ArcLengthSolver();
  ArcLengthSolver(const ArcLengthSolver&) = delete;
  ArcLengthSolver& operator=(const ArcLengthSolver&) = delete;

  /// One step of arc length `arc` [mm] from the model's converged state at time `t_n`;
  /// `previous_state` is the converged full state before it (the last step's start), whose
  /// increment orients the predictor (A1). On return the model holds the last iterate and `t`
  /// its load parameter; `predictor` the step's predictor. A failed step leaves the model at
  /// its last iterate, as NewtonSolver does.
  NewtonResult solve(double t_n, double arc, const std::vector<double>& previous_state, double& t,
                     ArcLengthPredictor& predictor);
  /// Goes on with the iterations of the last solve from the model's state (its last iterate, at
  /// `t`), on the same arc: after an update of contact multipliers moved the equilibrium.
  NewtonResult correct(double arc, double& t);
  /// The arc length the last solve used [mm]: the one asked for, or shorter when its predictor
  /// passed end_time or 0 (A8).
  double used_arc() const { return used_arc_; }
  /// The last solve or correct stopped because its load parameter left [0, end_time], where the
  /// ramps hold: the model holds that iterate (A8).
  bool left_ramps() const { return left_ramps_; }
  /// ||x_n - free(state)|| [mm]: the length of the increment from the full state `state` to the
  /// model's converged state.
  double distance_from(const std::vector<double>& state);
  /// The predictor alone (A1) at the model's converged state at `t_n`: what `solve` would start
  /// with (rate 0 when the tangent there failed: `result` says why). The model is back at its
  /// converged state on return.
  ArcLengthPredictor predict(double t_n, double arc, const std::vector<double>& previous_state,
                             NewtonResult& result);
  /// `stop` is asked after every iteration; when it says true the solve ends unconverged with
  /// `interrupted` set.
  void set_interrupt(std::function<bool()> stop) { interrupt_ = std::move(stop); }
  /// Wall time of the assemblies and of the factorisations with their solves [s].
  double assembly_seconds() const { return assembly_seconds_; }
  double solve_seconds() const { return solve_seconds_; }

 private:
  /// The free vectors sized for the model's current layout (and K_ for its sparsity).
  void prepare();
  /// R at the model's state and time `t` into r_; false when an element could not be evaluated.
  bool residual(double t, NewtonResult& result);
  /// K and q = dR/dt at the free state x_ and time `t` (q by a one-sided difference of step
  /// kTimeDifference * end_time), K factorised; r_ holds R(x_, t) already when `have_residual`,
  /// else it is assembled. False when the assembly or the factorisation failed (result says why).
  bool tangent(double t, bool have_residual, NewtonResult& result);
  /// The iterations of solve() and correct(), counted into `result`.
  NewtonResult correct(double arc, double& t, NewtonResult& result);
  /// y = K^-1 v with the last factorisation.
  void apply_inverse(Vec v, Vec y);
  /// The free vector of a full state (the model keeps its own state).
  void free_of(const std::vector<double>& full, Vec out);

  MixedModel& model_;
  NewtonSettings settings_;
  double end_time_ = 1.0;
  std::function<bool()> interrupt_;
  Mat K_ = nullptr;
  int pattern_version_ = -1;
  PC pc_ = nullptr;
  Vec x_ = nullptr, r_ = nullptr, q_ = nullptr, a_ = nullptr, b_ = nullptr;
  Vec x_n_ = nullptr, last_ = nullptr, increment_ = nullptr;
  bool left_ramps_ = false;
  double used_arc_ = 0.0;
  double reference_ = 0.0;  ///< ||q|| |t_p - t_n| of the current step (A6)
  double assembly_seconds_ = 0.0;
  double solve_seconds_ = 0.0;
};

}  // namespace plisse
