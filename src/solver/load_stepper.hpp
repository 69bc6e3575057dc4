#pragma once
/// Quasi-static load stepping: time runs from 0 to solver.end_time; each step applies the loads and
/// prescribed motions at the new time and solves with Newton. A failed step (Newton divergence,
/// an inverted element, a failed bubble solve) is retried with a smaller step (cut-back); after
/// easy steps the step grows. Below the minimum step the run stops.
/// Optionally (set_stability) every converged step is checked for stability from the inertia of
/// its tangent, and at a new instability the stepper computes the lowest eigenmodes and may switch
/// to the bifurcated branch (docs/theory/stability.md, sections 4 and 5).
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "solver/arc_length.hpp"
#include "solver/eigenmodes.hpp"
#include "solver/mixed_model.hpp"
#include "solver/newton_solver.hpp"
#include "solver/stability.hpp"
#include "solver/stepping_settings.hpp"

namespace plisse {

/// What the stepper does about stability (the app maps solver.stability.* to it).
struct StabilityCheckSettings {
  bool check = false;            ///< inertia of the tangent at every converged step
  bool branch_switch = false;    ///< at a new instability: perturb along mode 1 and re-solve
  int modes = 4;                 ///< eigenmodes computed at a new instability, >= 1
  double perturbation_mm = 0.0;  ///< amplitude a of u += a φ1 [mm] (relative amplitude x wall
                                 ///< thickness, computed by the caller), > 0 with branch_switch
  /// Start the branch switch's Newton from Koiter's estimate before the perturbations
  /// (stability.md, S10a); false: the perturbations only.
  bool koiter_start = true;
  /// End the run, completed, at the first checked step that is unstable after any branch switch.
  bool stop_when_unstable = false;
};

/// One converged step, as reported to the caller.
struct StepInfo {
  int step = 0;  ///< 1-based count of converged steps
  double time = 0.0;
  double dt = 0.0;
  double load_factor = 0.0;  ///< time / end_time
  /// Newton iterations (tangents and factorisations) of the accepted attempt, over all its contact
  /// passes (failed attempts before it are in SteppingResult only)
  int newton_iterations = 0;
  /// Solves with a factorisation already at hand in the accepted attempt, over all its contact
  /// passes (NewtonResult::reused_solves: chord steps and the GMRES iterations of Krylov steps;
  /// no factorisation)
  int reused_solves = 0;
  double residual_norm = 0.0;
  /// The ||R|| the last pass's relative test refers to: its first residual (before any reuse
  /// iterations, and of the loose solve that a refinement continued)
  double reference_norm = 0.0;
  std::vector<double> residual_history;  ///< of the last Newton solve of the step
  int cutbacks = 0;                      ///< failed attempts before this step converged
  // Stability (StabilityCheckSettings::check; stability.md, S7):
  int negative_pivots = -1;          ///< of the accepted state's tangent; -1: not checked
  int zero_pivots = 0;               ///< null pivots (a critical point)
  int expected_negative_pivots = 0;  ///< of a stable state (expected_negative_pivots)
  bool stable = true;                ///< negative == expected and no zero pivot (true unchecked)
  /// First step with more negative pivots than the step before (of the unperturbed state).
  bool new_instability = false;
  int unstable_negative_pivots = -1;  ///< at a new instability: count of the unperturbed state
  /// At a new instability: the lowest `modes` eigenmodes of the unperturbed converged state,
  /// ascending (for the VTU output); empty otherwise.
  std::vector<Eigenmode> modes;
  bool branch_switched = false;  ///< the accepted state is the re-solve from u + a φ1
  double perturbation_mm = 0.0;  ///< the amplitude a that switched (may exceed the option's)
};

struct SteppingResult {
  bool completed = false;  ///< reached end_time
  int steps = 0;
  int newton_iterations = 0;  ///< total over converged and failed attempts
  int reused_solves = 0;      ///< solves with a reused factorisation, same count
  int krylov_steps = 0;       ///< Newton steps solved by GMRES with a reused factorisation
  int cutbacks = 0;
  std::string failure;  ///< why the run stopped early (empty when completed)
  /// Stopped because no step past the last converged one went through down to solver.min_step:
  /// the load could not be raised there (a limit load, under load control).
  bool smallest_step = false;
  bool interrupted = false;  ///< stopped because set_interrupt's test said so, not by a failure
  /// Completed because the load factor fell below SteppingSettings::stop_load_factor past a limit
  /// load (arc-length control), not at end_time.
  bool stopped_after_limit = false;
  /// Completed at a step the stability check found unstable
  /// (StabilityCheckSettings::stop_when_unstable), not at end_time.
  bool stopped_unstable = false;
};

/// Where the stepping is, so that a run can continue from a checkpoint.
struct StepperState {
  int steps = 0;      ///< converged steps so far
  double time = 0.0;  ///< time of the last converged step
  /// Next step size (0: start from end_time / steps); under arc-length control from the second
  /// converged step on, the next arc length [mm] (A2)
  double dt = 0.0;
  double previous_dt = 0.0;  ///< size |t_n - t_{n-1}| of the last converged step (0: none yet)
  std::vector<double> previous_state;  ///< converged state before the last one (predictor)
  int negative_pivots = -1;  ///< of the last converged step (-1: not checked); a rise above it is
                             ///< a new instability
};

class LoadStepper {
 public:
  LoadStepper(MixedModel& model, const SteppingSettings& settings);
  ~LoadStepper();

  /// Stability check and branch switching (off by default). Throws plisse::Error when
  /// branch_switch is set without check, modes < 1 or a non-positive amplitude.
  void set_stability(const StabilityCheckSettings& options);

  /// Continue from `state` (the model must hold the matching converged state) instead of t = 0.
  void resume(StepperState state) { resume_ = std::move(state); }
  /// The state after the last converged step (valid inside the on_step callback and after run).
  const StepperState& state() const { return current_; }
  /// `stop` is asked before every attempt at a step and after every Newton iteration (on every
  /// rank at once); when it says true, run() returns `interrupted` at once, the model back at the
  /// last converged step: a signal is answered within one Newton iteration, also while steps
  /// fail and are cut back.
  void set_interrupt(std::function<bool()> stop);

  /// Runs to the end. `on_step` is called after every converged step with the model holding it;
  /// `log` receives progress lines.
  SteppingResult run(const std::function<void(const StepInfo&)>& on_step,
                     const std::function<void(const std::string&)>& log);
  /// Newton's, with the arc-length steps' assemblies and linear solves added (the factorisations
  /// and triangular solves come from PETSc's event log and count both already).
  PhaseTimes times() const;
  /// Entries of the last MUMPS factor of Newton (NewtonSolver::factor_entries).
  double factor_entries() const { return newton_.factor_entries(); }
  /// Wall time of the stability checks [s] (assembly + LDL^T factorisation) and their number;
  /// eigenmode computations are not included (eigenmode_seconds).
  double stability_seconds() const;
  double stability_assembly_seconds() const;  ///< the assembly part of stability_seconds
  int stability_checks() const;
  double eigenmode_seconds() const { return eigenmode_seconds_; }

 private:
  /// The reason of a failed Newton solve, naming the worst element and where it is.
  std::string describe_failure(const NewtonResult& newton) const;
  /// Newton, then multiplier updates and re-solves; empty on success, else why it failed.
  std::string solve_step(NewtonResult& newton, SteppingResult& result);
  using Log = std::function<void(const std::string&)>;
  /// The stability part of a converged, saved step: inertia, modes, branch switching. The model
  /// holds the step's accepted state on return. Sets `switched` when the predictor must restart.
  void check_stability(StepInfo& info, SteppingResult& result, const Log& log, bool& switched);
  /// True, with `result` completed and stopped_unstable, when stop_when_unstable is on and the
  /// check found the reported step `info` unstable.
  bool ends_unstable(const StepInfo& info, SteppingResult& result) const;
  /// The inertia of the model's tangent into `out`; false when the check failed (said in the
  /// log for `step`, which is then reported unchecked).
  bool compute_inertia(Inertia& out, int step, const Log& log);
  /// A new instability of `info`'s step (`inertia` above `baseline`): marks it, computes the
  /// lowest eigenmodes into info.modes and logs the line; returns the lowest eigenvalue as text
  /// ("not computed" without one).
  std::string report_instability(StepInfo& info, const Inertia& inertia, int expected, int baseline,
                                 const Log& log);
  /// Branch switching along the first mode (stability.md, S10) with growing amplitudes. On a
  /// switch, sets `switched`, updates `info` and `inertia` (the new state's) and returns false
  /// when the new state's inertia could not be computed; else the model keeps the unperturbed
  /// state and `inertia`, and it returns true.
  bool switch_branch(StepInfo& info, SteppingResult& result, const Log& log,
                     const std::string& lowest, int expected, Inertia& inertia, bool& switched);
  /// The state run() starts from: the resumed one, or t = 0 with the first step size.
  void start();
  /// The predictor of a step of size `step` from the last converged state (secant).
  void predict(double step);
  /// A failed attempt at the step to `t_new` (of size `step`), the model back at the last
  /// converged state: cuts the step back (said in the log) and returns true, or returns false
  /// with result.failure set when the run must stop (out of memory, step below the minimum).
  bool cut_back(const NewtonResult& newton, const std::string& failure, double t_new, double step,
                SteppingResult& result, const Log& log);
  /// Accepts the converged step to `t_new` (of size `step`): saves it, chooses the next step
  /// size and returns the step's record (its cut-backs and stability not yet filled in).
  StepInfo accept_step(const NewtonResult& newton, double t_new, double step,
                       SteppingResult& result);
  /// What an attempt at a step came to.
  enum class Attempt { accepted, retry, stop };
  /// One attempt at an arc-length step (StepControl::arc_length, from the second step on): the
  /// arc continuation from the last converged state; a step that ends past end_time is taken
  /// again under load control to end_time. On `accepted`, `info` is the step's record and the
  /// model holds it; on `retry` the arc was cut back; on `stop`, `result` says why.
  Attempt arc_length_attempt(SteppingResult& result, const Log& log, StepInfo& info);
  /// Logs, once, that a factorisation's workspace had to grow since the last report.
  void report_workspace_growth(int step, const Log& log);

  MixedModel& model_;
  SteppingSettings settings_;
  NewtonSolver newton_;
  std::unique_ptr<ArcLengthSolver> arc_;  ///< with StepControl::arc_length
  /// current_.dt holds the arc length (from the first arc-length step on), not a time step.
  bool arc_length_set_ = false;
  std::optional<StepperState> resume_;
  StepperState current_;
  std::function<bool()> interrupt_;
  StabilityCheckSettings stability_;
  std::unique_ptr<InertiaCheck> inertia_;
  bool told_symmetric_part_ = false;
  int attempt_reused_ = 0;          ///< reused solves of the current solve_step, all passes
  int attempt_newton_ = 0;          ///< Newton iterations of the current solve_step, all passes
  bool last_step_updated_ = false;  ///< the last converged solve_step updated multipliers
  int reported_growths_ = 0;        ///< factor workspace growths already in the log
  double eigenmode_seconds_ = 0.0;
};

}  // namespace plisse
