#include "solver/thread_counts.hpp"

#include <dlfcn.h>
#include <omp.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>

namespace plisse {
namespace {

/// OMP_NUM_THREADS as the process started (0: not set). Read during static initialisation:
/// Gmsh's initialisation later sets OpenMP's count to its own General.NumThreads (1 by default).
const int kOpenMPThreadsAtStart = std::getenv("OMP_NUM_THREADS") ? omp_get_max_threads() : 0;

int chosen_assembly_threads = 0;  ///< by apply_thread_counts (0: not yet)

/// OPENBLAS_NUM_THREADS or GOTO_NUM_THREADS set. (OpenBLAS would also take OMP_NUM_THREADS,
/// which plisse reads as the element loops' count only.)
bool blas_threads_in_environment() {
  return std::getenv("OPENBLAS_NUM_THREADS") != nullptr ||
         std::getenv("GOTO_NUM_THREADS") != nullptr;
}

int ranks_on_this_node(MPI_Comm comm) {
  MPI_Comm node = MPI_COMM_NULL;
  if (MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node) != MPI_SUCCESS)
    return 1;
  int size = 1;
  MPI_Comm_size(node, &size);
  MPI_Comm_free(&node);
  return size;
}

}  // namespace

int affinity_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 1;
  return std::max(1, CPU_COUNT(&set));
}

ThreadCounts apply_thread_counts(MPI_Comm comm) {
  ThreadCounts counts;
  counts.cpus = affinity_cpus();
  counts.ranks_on_node = ranks_on_this_node(comm);
  // A launcher that binds each rank to its own cores gives a mask of those cores alone; one
  // that does not gives every rank all of them, to be shared.
  const int bound = counts.cpus < static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)))
                        ? counts.cpus
                        : counts.cpus / counts.ranks_on_node;
  const int per_rank = std::max(1, bound);
  counts.assembly_from_environment = kOpenMPThreadsAtStart > 0;
  counts.assembly = counts.assembly_from_environment ? kOpenMPThreadsAtStart : per_rank;
  chosen_assembly_threads = counts.assembly;
  counts.blas_from_environment = blas_threads_in_environment();
  // OpenBLAS reads its environment when it loads, before main: the count is set by its own call.
  using SetThreads = void (*)(int);
  using GetThreads = int (*)();
  auto* set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  auto* get = reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  if (set == nullptr || get == nullptr) {
    counts.blas = 0;
  } else {
    if (!counts.blas_from_environment) set(1);
    counts.blas = get();
  }
  return counts;
}

int default_assembly_threads() {
  if (kOpenMPThreadsAtStart > 0) return kOpenMPThreadsAtStart;
  return chosen_assembly_threads > 0 ? chosen_assembly_threads : 1;
}

std::string describe(const ThreadCounts& c) {
  const auto plural = [](int n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  };
  std::string text = plural(c.assembly, "assembly thread") +
                     (c.assembly_from_environment ? " (OMP_NUM_THREADS)" : "") + ", ";
  text += c.blas > 0 ? plural(c.blas, "BLAS thread") +
                           (c.blas_from_environment ? " (OPENBLAS_NUM_THREADS)" : "")
                     : std::string("BLAS threads: the library's own");
  text += " (" + plural(c.cpus, "CPU") + ", " + plural(c.ranks_on_node, "rank") + " on this node)";
  return text;
}

}  // namespace plisse
