#pragma once
/// `plisse run`: the whole job from a case file to a finished run directory.
#include <string>
#include <vector>

#include "io/case.hpp"

namespace plisse::app {

struct RunOptions {
  std::string case_file;
  std::string output_directory;            ///< empty: runs/<case file stem>
  std::vector<std::string> overrides;      ///< --set key.path=value
  std::vector<std::string> petsc_options;  ///< --petsc "-snes_monitor ..."
  std::string resume_directory;            ///< --resume DIR: continue from DIR/checkpoint.bin
  /// --from DIR: start from the last state of the run in DIR (a second step with this case's loads)
  std::string from_directory;
  bool overwrite = false;  ///< --overwrite: replace an earlier run in the directory
  int ranks = 0;           ///< -n N: MPI ranks (run under mpiexec); 0: not given
};

/// Checks the PETSc options of the case (solver.petsc_options) and of the command line (--petsc)
/// against plisse's solver set-up; PETSc's refusal becomes an InputError at that key. Needs a
/// live PetscSession that holds the options.
void check_solver_options(const Case& c, const std::vector<std::string>& command_line_options);

/// Runs the case. Returns normally when the run reached its end time; throws InputError for bad
/// input (nothing is solved) and SolverError when the solver stopped early or SIGINT/SIGTERM
/// interrupted it (the last converged step and a checkpoint are written first).
void run_case(const RunOptions& options);

}  // namespace plisse::app
