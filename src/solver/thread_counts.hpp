#pragma once
/// How many threads one plisse process runs: the element loops (OpenMP) and the BLAS under
/// MUMPS (OpenBLAS's own threads). Chosen from the CPUs the process may run on and the MPI ranks
/// that share its node, so that the plain command is the fast one on any machine without
/// environment variables; OMP_NUM_THREADS and OPENBLAS_NUM_THREADS, when set, win
/// (docs/performance.md, "Threads").
#include <mpi.h>

#include <string>

namespace plisse {

struct ThreadCounts {
  int cpus = 1;           ///< CPUs in this process's affinity mask
  int ranks_on_node = 1;  ///< ranks of the communicator on this node (sharing its memory)
  int assembly = 1;       ///< element-loop threads
  int blas = 1;           ///< BLAS threads; 0: the BLAS library has no run-time setting
  bool assembly_from_environment = false;  ///< OMP_NUM_THREADS set
  bool blas_from_environment = false;      ///< OPENBLAS_NUM_THREADS (or GOTO_NUM_THREADS) set
};

/// Chooses the counts (collective on `comm`) and applies them: the element loops' default
/// (default_assembly_threads) and OpenBLAS's thread count. Element loops: the CPUs per rank on
/// the node, at least 1. BLAS: 1, because MUMPS's BLAS threads and the element loops take turns
/// on the same cores and OpenBLAS's threads spin after each call (measured in
/// docs/performance.md).
ThreadCounts apply_thread_counts(MPI_Comm comm);

/// The CPUs this process may run on (its affinity mask), at least 1.
int affinity_cpus();

/// The element loops' thread count when MixedModel is not told one: OMP_NUM_THREADS as the
/// process started when it was set, else what apply_thread_counts chose, else 1.
int default_assembly_threads();

/// One line for the log: "2 assembly threads, 1 BLAS thread (2 CPUs, 1 rank on this node)".
std::string describe(const ThreadCounts& counts);

}  // namespace plisse
