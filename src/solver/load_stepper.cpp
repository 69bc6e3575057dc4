#include "solver/load_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace plisse {

std::string LoadStepper::describe_failure(const NewtonResult& newton) const {
  const AssemblyStatus& status = newton.status;
  std::string why = status.ok ? "Newton did not converge (" + newton.reason + ")"
                              : "an element inverted or its bubble did not converge";
  if (status.worst_element >= 0) {
    const auto& tet = model_.mesh().tets[status.worst_element];
    Vec3d centroid = Vec3d::Zero();
    for (int v : tet) centroid += 0.25 * model_.mesh().nodes[v];
    char where[160];
    std::snprintf(where, sizeof where, "; worst element %d (reference centroid %.4g, %.4g, %.4g), min J %.3g",
                  status.worst_element, centroid[0], centroid[1], centroid[2], status.min_J);
    why += where;
  }
  return why;
}

LoadStepper::LoadStepper(MixedModel& model, const SolverSettings& settings)
    : model_(model), settings_(settings), newton_(model, settings.newton) {}

SteppingResult LoadStepper::run(const std::function<void(const StepInfo&)>& on_step,
                                const std::function<void(const std::string&)>& log) {
  SteppingResult result;
  const double end = settings_.end_time;
  const double min_dt = settings_.min_step * end;
  const double max_dt = settings_.max_step * end;
  StepperState& st = current_;
  if (resume_) {
    // The model already holds the checkpoint's converged state.
    st = *resume_;
    resume_.reset();
  } else {
    st = StepperState{};
    st.dt = std::min(end / settings_.steps, max_dt);
    model_.set_time(0.0);
    model_.save_converged();
    st.previous_state = model_.converged_state();
  }
  double& dt = st.dt;
  double& t = st.time;
  double& previous_dt = st.previous_dt;
  std::vector<double>& previous_state = st.previous_state;
  result.steps = st.steps;
  int cutbacks_this_step = 0;
  char line[256];
  while (t < end * (1.0 - 1e-12)) {
    if (result.steps >= settings_.max_steps) {
      result.failure = "reached solver.max_steps = " + std::to_string(settings_.max_steps) +
                       " at time " + std::to_string(t);
      return result;
    }
    // Land on end_time without a sliver: take the rest when it fits, halve it when it is less
    // than two steps.
    const double remaining = end - t;
    if (remaining > dt && remaining < 2.0 * dt) dt = 0.5 * remaining;
    const double t_new = (remaining <= dt * (1.0 + 1e-9)) ? end : t + dt;
    const double step = t_new - t;
    // Predictor: extrapolate the last increment (secant), then impose the new boundary values.
    if (previous_dt > 0.0) {
      const double s = step / previous_dt;
      const auto& now = model_.converged_state();
      auto& x = model_.state();
      for (size_t i = 0; i < x.size(); ++i) x[i] = now[i] + s * (now[i] - previous_state[i]);
    }
    model_.set_time(t_new);
    NewtonResult newton;
    std::string failure;
    int augmentations = 0;
    try {
      // Newton, then (augmented Lagrangian terms) multiplier updates and re-solves until every
      // constraint meets its tolerance.
      while (true) {
        newton = newton_.solve();
        result.newton_iterations += newton.iterations;
        if (!newton.converged) {
          failure = describe_failure(newton);
          break;
        }
        if (!model_.update_multipliers()) break;
        if (++augmentations > settings_.max_augmentations) {
          failure = "constraints not met after " + std::to_string(settings_.max_augmentations) +
                    " multiplier updates";
          break;
        }
      }
    } catch (const Error& e) {
      failure = e.what();
    }
    if (!failure.empty()) {
      model_.restore_converged();
      ++result.cutbacks;
      ++cutbacks_this_step;
      const double new_dt = step * settings_.cutback;
      std::snprintf(line, sizeof line, "step %d: t = %.6g failed after %d iterations: ",
                    result.steps + 1, t_new, newton.iterations);
      if (new_dt < min_dt) {
        result.failure = std::string(line) + failure + "; step " + std::to_string(new_dt) +
                         " below the minimum " + std::to_string(min_dt);
        return result;
      }
      log("  " + std::string(line) + failure + "; cutting the step to " + std::to_string(new_dt));
      dt = new_dt;
      continue;
    }
    previous_state = model_.converged_state();
    model_.save_converged();
    previous_dt = step;
    t = t_new;
    ++result.steps;
    st.steps = result.steps;
    if (newton.iterations <= settings_.easy_iterations) dt = std::min(step * settings_.growth, max_dt);
    else dt = step;
    StepInfo info;
    info.step = result.steps;
    info.time = t;
    info.dt = step;
    info.load_factor = t / end;
    info.newton_iterations = newton.iterations;
    info.residual_norm = newton.residual_norm;
    info.residual_history = newton.residual_history;
    info.cutbacks = cutbacks_this_step;
    cutbacks_this_step = 0;
    on_step(info);
    if (stop_requested_ && t < end * (1.0 - 1e-12)) {
      result.interrupted = true;
      result.failure = "interrupted at step " + std::to_string(result.steps);
      return result;
    }
  }
  result.completed = true;
  return result;
}

}  // namespace plisse
