#include <memory>

#include "app/commands.hpp"
#include "app/run_case.hpp"

namespace plisse::app {

void add_run_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "Run a case: solve and write the run directory");
  auto options = std::make_shared<RunOptions>();
  cmd->add_option("case", options->case_file, "Case file (YAML)")->required();
  cmd->add_option("-o,--output", options->output_directory,
                  "Run directory (default: runs/<case file name without .yaml>)");
  cmd->add_option("--set", options->overrides,
                  "Override a case value, e.g. --set mesh.layers=4 (repeatable)")
      ->take_all()
      ->allow_extra_args(false);
  cmd->add_option("--petsc", options->petsc_options,
                  "PETSc options, e.g. --petsc \"-snes_monitor -ksp_view\" (repeatable)")
      ->allow_extra_args(false);
  cmd->add_option("--resume", options->resume_directory,
                  "Continue an interrupted run from DIR/checkpoint.bin (same case and --set "
                  "values; DIR is also the output directory)");
  cmd->callback([options] { run_case(*options); });
}

}  // namespace plisse::app
