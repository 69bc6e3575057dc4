#include <memory>

#include "app/commands.hpp"
#include "app/run_case.hpp"
#include "app/run_session.hpp"

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
  cmd->add_option("--from", options->from_directory,
                  "Start from the last converged state of the run in DIR (its checkpoint.bin) "
                  "under this case's loads, in a new run directory: a second load step, e.g. "
                  "unloading, on the same mesh and element");
  cmd->add_flag("--from-unfinished", options->from_unfinished,
                "With --from: accept a run that did not complete (killed, interrupted or failed) "
                "and start from its last checkpoint, which the log then says");
  cmd->add_flag("--overwrite", options->overwrite,
                "Replace the earlier run in the output directory (its files are removed once the "
                "case has passed every check); without it, such a directory is refused");
  cmd->add_option("-n,--ranks", options->ranks,
                  "Run on N MPI ranks (distributed; the same as mpiexec -n N plisse run ...). "
                  "Results do not depend on N beyond the solver tolerance")
      ->check(CLI::Range(1, 65536));
  auto oversubscribe = std::make_shared<bool>(false);
  cmd->add_flag("--oversubscribe", *oversubscribe,
                "With -n: allow more ranks than the CPUs this process may use");
  cmd->callback([options, oversubscribe] {
    launch_ranks(options->ranks, *oversubscribe, *options);
    run_case(*options);
  });
}

}  // namespace plisse::app
