#pragma once
/// Quasi-static load stepping: time runs from 0 to solver.end_time; each step applies the loads and
/// prescribed motions at the new time and solves with Newton. A failed step (Newton divergence,
/// an inverted element, a failed bubble solve) is retried with a smaller step (cut-back); after
/// easy steps the step grows. Below the minimum step the run stops.
#include <functional>
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
};

class LoadStepper {
 public:
  LoadStepper(MixedModel& model, const SolverSettings& settings);

  /// Runs to the end. `on_step` is called after every converged step with the model holding it;
  /// `log` receives progress lines.
  SteppingResult run(const std::function<void(const StepInfo&)>& on_step,
                     const std::function<void(const std::string&)>& log);
  PhaseTimes times() const { return newton_.times(); }

 private:
  MixedModel& model_;
  SolverSettings settings_;
  NewtonSolver newton_;
};

}  // namespace plisse
