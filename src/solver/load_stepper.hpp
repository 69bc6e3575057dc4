#pragma once
/// Quasi-static load stepping: time runs from 0 to solver.end_time; each step applies the loads and
/// prescribed motions at the new time and solves with Newton. A failed step (Newton divergence,
/// an inverted element, a failed bubble solve) is retried with a smaller step (cut-back); after
/// easy steps the step grows. Below the minimum step the run stops.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/case.hpp"
#include "solver/mixed_model.hpp"
#include "solver/newton_solver.hpp"

namespace plisse {

/// One converged step, as reported to the caller.
struct StepInfo {
  int step = 0;  ///< 1-based count of converged steps
  double time = 0.0;
  double dt = 0.0;
  double load_factor = 0.0;  ///< time / end_time
  int newton_iterations = 0;
  double residual_norm = 0.0;
  std::vector<double> residual_history;
  int cutbacks = 0;  ///< failed attempts before this step converged
};

struct SteppingResult {
  bool completed = false;  ///< reached end_time
  int steps = 0;
  int newton_iterations = 0;  ///< total over converged and failed attempts
  int cutbacks = 0;
  std::string failure;  ///< why the run stopped early (empty when completed)
  bool interrupted = false;  ///< stopped on request (request_stop), not by a failure
};

/// Where the stepping is, so that a run can continue from a checkpoint.
struct StepperState {
  int steps = 0;             ///< converged steps so far
  double time = 0.0;         ///< time of the last converged step
  double dt = 0.0;           ///< next step size (0: start from end_time / steps)
  double previous_dt = 0.0;  ///< size of the last converged step (0: none yet)
  std::vector<double> previous_state;  ///< converged state before the last one (predictor)
};

class LoadStepper {
 public:
  LoadStepper(MixedModel& model, const SolverSettings& settings);

  /// Continue from `state` (the model must hold the matching converged state) instead of t = 0.
  void resume(StepperState state) { resume_ = std::move(state); }
  /// The state after the last converged step (valid inside the on_step callback and after run).
  const StepperState& state() const { return current_; }
  /// Asks run() to return after the current step (e.g. from a signal handler's flag check).
  void request_stop() { stop_requested_ = true; }

  /// Runs to the end. `on_step` is called after every converged step with the model holding it;
  /// `log` receives progress lines.
  SteppingResult run(const std::function<void(const StepInfo&)>& on_step,
                     const std::function<void(const std::string&)>& log);
  PhaseTimes times() const { return newton_.times(); }

 private:
  /// The reason of a failed Newton solve, naming the worst element and where it is.
  std::string describe_failure(const NewtonResult& newton) const;

  MixedModel& model_;
  SolverSettings settings_;
  NewtonSolver newton_;
  std::optional<StepperState> resume_;
  StepperState current_;
  bool stop_requested_ = false;
};

}  // namespace plisse
