#include "app/run_session.hpp"

#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "solver/collective.hpp"
#include "solver/newton_solver.hpp"
#include "solver/petsc_call.hpp"
#include "solver/thread_counts.hpp"

namespace plisse::app {
namespace {

volatile std::sig_atomic_t g_interrupt = 0;
/// The first SIGINT/SIGTERM asks the run to stop; a second one ends the process at once. What
/// was written stays whole: files are replaced by rename or grow by whole lines, and the next run
/// or resume in the directory removes the temporaries and takes over the lock.
extern "C" void on_interrupt(int) {
  if (g_interrupt != 0) {
    static const char kMessage[] =
        "\nplisse: second interrupt: stopping at once; the files written so far are whole, the "
        "last checkpoint is the place to resume from\n";
    const ssize_t written = ::write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
    (void)written;
    ::_exit(1);
  }
  g_interrupt = 1;
}

/// The rank count -n asks for, checked against the job this process is in and the CPUs it may
/// use. False: there is nothing to start (inside a job, or one rank).
bool ranks_to_start(int ranks, bool oversubscribe) {
  const int size = launcher_size();
  if (size > 0) {
    if (ranks != 0 && size != ranks)
      throw InputError({"command line", 0, 0, "-n"},
                       "-n " + std::to_string(ranks) + " inside an MPI job of " +
                           std::to_string(size) + " ranks; give the same number or leave -n out");
    return false;
  }
  if (ranks <= 1) return false;
  // More ranks than CPUs: the ranks would take turns on the cores and wait for each other at
  // every collective call.
  if (const int cpus = affinity_cpus(); ranks > cpus && !oversubscribe)
    throw InputError({"command line", 0, 0, "-n"},
                     "-n " + std::to_string(ranks) + " is more ranks than the " +
                         std::to_string(cpus) +
                         " CPUs this process may use: the ranks would wait for each other's "
                         "cores at every step; give at most " +
                         std::to_string(cpus) + ", or add --oversubscribe to run them anyway");
  return true;
}

}  // namespace

int launcher_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(name)) return std::atoi(value);
  return 0;
}

void launch_ranks(int ranks, bool oversubscribe, const RunOptions& options) {
  if (!ranks_to_start(ranks, oversubscribe)) return;
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

void check_solver_options(const Case& c, const std::vector<std::string>& command_line_options) {
  try {
    check_petsc_options(c.solver.newton);
  } catch (const Error& e) {
    std::string given = c.solver.petsc_options;
    for (const auto& o : command_line_options) given += (given.empty() ? "" : " ") + o;
    const InputPlace place = command_line_options.empty()
                                 ? c.solver.petsc_options_place
                                 : InputPlace{"command line", 0, 0, "--petsc"};
    throw InputError(place, "PETSc refuses the options '" + given + "': " + e.what());
  }
}

RunSession::RunSession(const Case& c, const std::vector<std::string>& command_line_petsc_options)
    : petsc_({"-no_signal_handler", c.solver.petsc_options}) {
  for (const auto& o : command_line_petsc_options) PetscSession::insert_options(o);
  check_solver_options(c, command_line_petsc_options);
  threads_ = describe(apply_thread_counts(PETSC_COMM_WORLD));
  // SIGINT/SIGTERM set a flag for the duration of the run; the stepper asks it before every step
  // and after every Newton iteration, stops with the last converged step and the run
  // checkpoints it. A second signal ends the process at once (on_interrupt).
  g_interrupt = 0;
  previous_int_ = std::signal(SIGINT, on_interrupt);
  previous_term_ = std::signal(SIGTERM, on_interrupt);
  end_with_launcher();
  abort_job_when_memory_runs_out();
}

RunSession::~RunSession() {
  std::signal(SIGINT, previous_int_);
  std::signal(SIGTERM, previous_term_);
}

bool RunSession::interrupt_requested() const { return any_rank(g_interrupt != 0); }

void RunSession::run_collectively(const std::function<void()>& work) const {
  try {
    work();
  } catch (const InputError&) {
    throw;
  } catch (const SolverError&) {
    throw;
  } catch (const SharedError&) {
    throw;
  } catch (...) {
    if (PetscSession::size() > 1) abort_all_ranks(std::current_exception());
    throw;
  }
}

}  // namespace plisse::app
