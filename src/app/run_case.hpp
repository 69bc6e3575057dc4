#pragma once
/// `plisse run`: the whole job from a case file to a finished run directory, as numbered steps
/// (run_case.cpp): the plan (app/run_plan), the mesh and the model's parts, the session
/// (app/run_session), then the model, the run directory, the recorder (app/run_recorder) and the
/// stepping.
#include "app/run_plan.hpp"

namespace plisse::app {

/// Runs the case. Returns normally when the run reached its end time; throws InputError for bad
/// input (nothing is solved) and SolverError when the solver stopped early or SIGINT/SIGTERM
/// interrupted it (the last converged step and a checkpoint are written first).
void run_case(const RunOptions& options);

}  // namespace plisse::app
