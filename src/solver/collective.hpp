#pragma once
/// Agreement between the ranks of a distributed run (collective over PETSC_COMM_WORLD; on one
/// rank each is a plain call). A rank that fails alone while the others go on into the next
/// collective call leaves them waiting there for ever, and its own unwinding blocks too (MUMPS
/// frees its factor collectively): work that can fail on one rank only, such as writing a file,
/// goes through `on_every_rank_alike`, so that every rank fails with it and they unwind together.
#include <exception>
#include <functional>
#include <string>

#include "core/error.hpp"

namespace plisse {

/// An error raised alike on every rank of the job: the ranks unwind together, and the job ends
/// with the ordinary exit status 1 (not an abort of all ranks).
class SharedError : public Error {
 public:
  using Error::Error;
};

/// True when any rank passes true.
bool any_rank(bool value);

/// `text` as rank 0 has it, on every rank.
std::string from_root(std::string text);

/// Runs `work` on this rank and agrees on its outcome: when it throws on any rank, every rank
/// throws the error of the lowest failing rank, an InputError (its message as the rule) when it
/// was one, else a SharedError ("rank R: message"). On one rank, `work`'s own exception passes
/// unchanged. `work` itself must not call collective operations.
void on_every_rank_alike(const std::function<void()>& work);

/// Ends a distributed job after an error on this rank alone: prints "plisse: error on rank R:
/// message", then MPI_Abort (exit status 1), since the other ranks may be waiting in a collective
/// call.
[[noreturn]] void abort_all_ranks(std::exception_ptr error);

/// Ties this process to its launcher (mpirun, orted, srun's step daemon) in a distributed run:
/// when the launcher dies, the kernel kills this rank (Linux PR_SET_PDEATHSIG), so that no rank
/// outlives its job, also one that is stuck waiting for a dead peer. Call once per process after
/// MPI starts; a no-op on one rank.
void end_with_launcher();

/// In a distributed run, an allocation that fails on one rank ends the whole job at once (a
/// new-handler that prints "out of memory on rank R" and calls MPI_Abort): the exception would
/// leave the other ranks waiting in a collective call. On one rank the allocation throws
/// std::bad_alloc as usual, and the load stepper stops the run there. Call once per process.
void abort_job_when_memory_runs_out();

}  // namespace plisse
