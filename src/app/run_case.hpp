#pragma once
/// `plisse run`: the whole job from a case file to a finished run directory.
#include <string>
#include <vector>

namespace plisse::app {

struct RunOptions {
  std::string case_file;
  std::string output_directory;          ///< empty: runs/<case file stem>
  std::vector<std::string> overrides;    ///< --set key.path=value
  std::vector<std::string> petsc_options;  ///< --petsc "-snes_monitor ..."
};

/// Runs the case. Returns normally when the run reached its end time; throws InputError for bad
/// input (nothing is solved) and SolverError when the solver stopped early (the last converged
/// step is written first).
void run_case(const RunOptions& options);

}  // namespace plisse::app
