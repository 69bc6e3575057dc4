#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/run_case.hpp"
#include "core/error.hpp"
#include "io/case.hpp"
#include "solver/thread_counts.hpp"

namespace plisse::app {
namespace {

/// The number of ranks of the MPI job this process belongs to, from the launcher's environment
/// (Open MPI, PMIx, MPICH/Hydra), or 0 when it was not started by an MPI launcher.
int launcher_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(name)) return std::atoi(value);
  return 0;
}

/// `-n N` outside an MPI job: starts the same command line under `mpiexec -n N` in place of this
/// process. Inside a job (mpirun, mpiexec or srun started this process) -n may be left out; when
/// given, it must be the job's size. More ranks than CPUs only with --oversubscribe: the ranks
/// would take turns on the cores and wait for each other at every collective call.
void launch_ranks(int ranks, bool oversubscribe, const RunOptions& options) {
  const int size = launcher_size();
  if (size > 0) {
    if (ranks != 0 && size != ranks)
      throw InputError({"command line", 0, 0, "-n"},
                       "-n " + std::to_string(ranks) + " inside an MPI job of " +
                           std::to_string(size) + " ranks; give the same number or leave -n out");
    return;
  }
  if (ranks <= 1) return;
  if (const int cpus = affinity_cpus(); ranks > cpus && !oversubscribe)
    throw InputError({"command line", 0, 0, "-n"},
                     "-n " + std::to_string(ranks) + " is more ranks than the " +
                         std::to_string(cpus) +
                         " CPUs this process may use: the ranks would wait for each other's "
                         "cores at every step; give at most " +
                         std::to_string(cpus) + ", or add --oversubscribe to run them anyway");
  // A case the ranks would all refuse is refused here, once, without the launcher's banners.
  (void)parse_case_file(options.case_file, options.overrides);
  // -q: no launcher banner when the ranks exit with an error status (they report it themselves).
  std::vector<std::string> words = {"mpiexec", "-q", "-n", std::to_string(ranks)};
  // This executable, then the arguments it was given (its -n is checked in the children).
  char self[4096];
  const ssize_t length = ::readlink("/proc/self/exe", self, sizeof self - 1);
  if (length <= 0)
    throw Error("cannot find this executable (/proc/self/exe) to start it under mpiexec");
  self[length] = '\0';
  words.emplace_back(self);
  for (int i = 1; i < command_line().argc; ++i) words.emplace_back(command_line().argv[i]);
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  // Open MPI refuses to start as root unless told, and more ranks than cores unless told; plisse
  // leaves that choice to the user who asked for N ranks.
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 0);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 0);
  ::setenv("OMPI_MCA_rmaps_base_oversubscribe", "1", 0);
  ::execvp("mpiexec", argv.data());
  throw InputError({"command line", 0, 0, "-n"},
                   std::string("cannot start mpiexec for -n ") + std::to_string(ranks) + ": " +
                       std::strerror(errno) + " (install Debian's openmpi-bin)");
}

}  // namespace

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
