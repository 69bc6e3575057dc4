#include "solver/partition.hpp"

#include <metis.h>

#include <string>

#include "core/error.hpp"
#include "solver/petsc_call.hpp"

namespace plisse {
namespace {

/// The partition computed on this process alone, by METIS's multilevel k-way partitioning
/// (deterministic: a fixed seed gives the same parts on every machine and run).
std::vector<int> partition_here(const std::vector<int>& start, const std::vector<int>& adjacency,
                                const std::vector<int>& weights, int parts) {
  idx_t n = static_cast<idx_t>(weights.size());
  // METIS wants the graph without self loops.
  std::vector<idx_t> xadj(n + 1, 0), adjncy;
  adjncy.reserve(adjacency.size());
  for (idx_t v = 0; v < n; ++v) {
    for (int k = start[v]; k < start[v + 1]; ++k)
      if (adjacency[k] != v) adjncy.push_back(adjacency[k]);
    xadj[v + 1] = static_cast<idx_t>(adjncy.size());
  }
  std::vector<idx_t> vertex_weights(weights.begin(), weights.end());
  idx_t constraints = 1, n_parts = parts, cut = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_SEED] = 1;
  std::vector<idx_t> part(n, 0);
  const int status =
      METIS_PartGraphKway(&n, &constraints, xadj.data(), adjncy.data(), vertex_weights.data(),
                          nullptr, nullptr, &n_parts, nullptr, nullptr, options, &cut, part.data());
  PLISSE_CHECK(status == METIS_OK, "METIS_PartGraphKway failed (status " << status << ")");
  std::vector<int> out(part.begin(), part.end());
  for (idx_t v = 0; v < n; ++v)
    PLISSE_CHECK(out[v] >= 0 && out[v] < parts,
                 "the partitioner put node " << v << " into part " << out[v] << " of " << parts);
  return out;
}

}  // namespace

std::vector<int> partition_graph(const std::vector<int>& start, const std::vector<int>& adjacency,
                                 const std::vector<int>& weights, int parts, MPI_Comm comm) {
  PLISSE_CHECK(
      !start.empty() && weights.size() + 1 == start.size(),
      "partition_graph: " << weights.size() << " weights for " << start.size() - 1 << " vertices");
  PLISSE_CHECK(parts >= 1, "partition_graph: " << parts << " parts");
  const int n = static_cast<int>(weights.size());
  if (parts == 1) return std::vector<int>(n, 0);
  int rank = 0;
  PLISSE_PETSC(MPI_Comm_rank(comm, &rank));
  // Rank 0 partitions; a failure there must reach every rank, which would otherwise wait in the
  // broadcast.
  std::vector<int> part(n, 0);
  int failed = 0;
  std::string message;
  if (rank == 0) {
    try {
      part = partition_here(start, adjacency, weights, parts);
    } catch (const std::exception& e) {
      failed = 1;
      message = e.what();
    }
  }
  PLISSE_PETSC(MPI_Bcast(&failed, 1, MPI_INT, 0, comm));
  if (failed) throw Error("partitioning the mesh failed" + (message.empty() ? "" : ": " + message));
  PLISSE_PETSC(MPI_Bcast(part.data(), n, MPI_INT, 0, comm));
  return part;
}

}  // namespace plisse
