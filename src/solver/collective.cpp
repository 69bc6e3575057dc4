#include "solver/collective.hpp"

#include <mpi.h>
#include <petscsys.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>

#include "solver/petsc_call.hpp"
#include "solver/petsc_session.hpp"

namespace plisse {

bool any_rank(bool value) {
  if (PetscSession::size() == 1) return value;
  int flag = value ? 1 : 0;
  PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, &flag, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD));
  return flag != 0;
}

namespace {
/// What an exception says: its what(), or the text of a thrown string (Gmsh's API throws them).
std::string message_of(std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    return e.what();
  } catch (const std::string& e) {
    return e;
  } catch (...) {
    return "an exception of unknown type";
  }
}

/// `text` as rank `root` has it, on every rank.
std::string broadcast(std::string text, int root) {
  unsigned long length = text.size();
  PLISSE_PETSC(MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG, root, PETSC_COMM_WORLD));
  text.resize(length);
  PLISSE_PETSC(MPI_Bcast(text.data(), static_cast<int>(length), MPI_CHAR, root, PETSC_COMM_WORLD));
  return text;
}
}  // namespace

std::string from_root(std::string text) {
  if (PetscSession::size() == 1) return text;
  return broadcast(std::move(text), 0);
}

void on_every_rank_alike(const std::function<void()>& work) {
  const int size = PetscSession::size();
  if (size == 1) {
    work();
    return;
  }
  std::string message;
  bool failed = false;
  int input = 0;  // an InputError stays one: exit status 2
  try {
    work();
  } catch (const InputError& e) {
    failed = true;
    input = 1;
    message = e.what();
  } catch (...) {
    failed = true;
    message = message_of(std::current_exception());
  }
  // The lowest failing rank speaks for all.
  int first = failed ? PetscSession::rank() : size;
  PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD));
  if (first == size) return;
  message = broadcast(std::move(message), first);
  PLISSE_PETSC(MPI_Bcast(&input, 1, MPI_INT, first, PETSC_COMM_WORLD));
  if (input) throw InputError({}, message);
  throw SharedError("rank " + std::to_string(first) + ": " + message);
}

void abort_all_ranks(std::exception_ptr error) {
  std::fprintf(stderr, "plisse: error on rank %d: %s\n", PetscSession::rank(),
               message_of(error).c_str());
  std::fflush(stderr);
  MPI_Abort(PETSC_COMM_WORLD, 1);
  std::abort();
}

void end_with_launcher() {
  if (PetscSession::size() == 1) return;
  const pid_t launcher = getppid();
  if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0) return;  // not Linux: nothing to tie
  // The launcher may have died before the tie was made.
  if (getppid() != launcher) _exit(1);
}

void abort_job_when_memory_runs_out() {
  if (PetscSession::size() == 1) return;
  std::set_new_handler([] {
    // No allocation here: a fixed message and the rank's number.
    char text[160];
    const int n = std::snprintf(text, sizeof text,
                                "plisse: out of memory on rank %d: an allocation failed; ending "
                                "every rank of the job\n",
                                PetscSession::rank());
    if (n > 0) (void)!write(STDERR_FILENO, text, static_cast<std::size_t>(n));
    MPI_Abort(PETSC_COMM_WORLD, 1);
    std::abort();
  });
}

}  // namespace plisse
