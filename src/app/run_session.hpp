#pragma once
/// The process around a run of `plisse run`: the MPI ranks (-n N starts the job under mpiexec),
/// PETSc and SLEPc with the run's options, the thread counts, the SIGINT/SIGTERM handlers and
/// the rules that make the ranks of a distributed job fail together.
#include <functional>
#include <string>
#include <vector>

#include "app/run_plan.hpp"
#include "case/case.hpp"
#include "solver/petsc_session.hpp"

namespace plisse::app {

/// The number of ranks of the MPI job this process belongs to, from the launcher's environment
/// (Open MPI, PMIx, MPICH/Hydra), or 0 when it was not started by an MPI launcher.
int launcher_size();

/// `-n N` outside an MPI job: starts the same command line under `mpiexec -n N` in place of this
/// process (returns only when there is nothing to start). Inside a job (mpirun, mpiexec or srun
/// started this process) -n may be left out; when given, it must be the job's size. More ranks
/// than CPUs only with `oversubscribe`. Throws InputError (key -n) for a refused count, a case
/// the ranks would all refuse, or an mpiexec that cannot be started.
void launch_ranks(int ranks, bool oversubscribe, const RunOptions& options);

/// Checks the PETSc options of the case (solver.petsc_options) and of the command line (--petsc)
/// against plisse's solver set-up; PETSc's refusal becomes an InputError at that key. Needs a
/// live PetscSession that holds the options.
void check_solver_options(const Case& c, const std::vector<std::string>& command_line_options);

/// PETSc, threads and signals for the lifetime of one run, set up in this order: PETSc and SLEPc
/// with the case's solver.petsc_options then the command line's --petsc options (PETSc's own
/// signal handler off: plisse checkpoints instead), the options checked (check_solver_options),
/// the thread counts applied (solver/thread_counts.hpp), the SIGINT/SIGTERM handlers installed,
/// each rank tied to its launcher and an allocation failure on one rank made to end the job
/// (solver/collective.hpp). The destructor puts the previous signal handlers back, then
/// finalises PETSc.
class RunSession {
 public:
  /// Throws InputError when PETSc refuses the options.
  RunSession(const Case& c, const std::vector<std::string>& command_line_petsc_options);
  ~RunSession();
  RunSession(const RunSession&) = delete;
  RunSession& operator=(const RunSession&) = delete;

  /// The thread counts, in words for the log.
  const std::string& threads() const { return threads_; }
  /// True when SIGINT or SIGTERM reached any rank since the session started: the run stops with
  /// its last converged step. A second signal ends the process at once. Collective.
  bool interrupt_requested() const;
  /// Runs `work`, in which input and solver errors arise on every rank alike, and so do failed
  /// writes (on_every_rank_alike): those pass to the caller. Anything else on one rank of a
  /// distributed run would leave the others waiting in a collective call, so it ends the whole
  /// job (abort_all_ranks).
  void run_collectively(const std::function<void()>& work) const;

 private:
  PetscSession petsc_;
  std::string threads_;
  void (*previous_int_)(int) = nullptr;
  void (*previous_term_)(int) = nullptr;
};

}  // namespace plisse::app
