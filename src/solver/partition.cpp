#include "solver/partition.hpp"

#include <petscmat.h>

#include <algorithm>
#include <string>

#include "core/error.hpp"
#include "solver/petsc_call.hpp"

namespace plisse {
namespace {

/// The partition computed on this process alone (PETSC_COMM_SELF).
std::vector<int> partition_here(const std::vector<int>& start, const std::vector<int>& adjacency,
                                const std::vector<int>& weights, int parts) {
  const int n = static_cast<int>(start.size()) - 1;
  // MatCreateMPIAdj takes ownership of arrays allocated with PetscMalloc; it wants sorted rows
  // without the diagonal.
  PetscInt* ia = nullptr;
  PetscInt* ja = nullptr;
  PetscInt* vertex_weights = nullptr;
  PetscInt edges = 0;
  for (int v = 0; v < n; ++v)
    for (int k = start[v]; k < start[v + 1]; ++k) edges += adjacency[k] != v;
  PLISSE_PETSC(PetscMalloc1(n + 1, &ia));
  PLISSE_PETSC(PetscMalloc1(edges > 0 ? edges : 1, &ja));
  PLISSE_PETSC(PetscMalloc1(n, &vertex_weights));
  ia[0] = 0;
  for (int v = 0; v < n; ++v) {
    PetscInt next = ia[v];
    for (int k = start[v]; k < start[v + 1]; ++k)
      if (adjacency[k] != v) ja[next++] = adjacency[k];
    std::sort(ja + ia[v], ja + next);
    ia[v + 1] = next;
    vertex_weights[v] = weights[v];
  }
  Mat graph = nullptr;
  MatPartitioning partitioning = nullptr;
  IS is = nullptr;
  std::vector<int> part(n, 0);
  try {
    PLISSE_PETSC(MatCreateMPIAdj(PETSC_COMM_SELF, n, n, ia, ja, nullptr, &graph));
    PLISSE_PETSC(MatPartitioningCreate(PETSC_COMM_SELF, &partitioning));
    PLISSE_PETSC(MatPartitioningSetAdjacency(partitioning, graph));
    PLISSE_PETSC(MatPartitioningSetNParts(partitioning, parts));
    PLISSE_PETSC(MatPartitioningSetType(partitioning, MATPARTITIONINGPTSCOTCH));
    PLISSE_PETSC(MatPartitioningSetVertexWeights(partitioning, vertex_weights));
    vertex_weights = nullptr;  // owned by the partitioning now
    PLISSE_PETSC(MatPartitioningSetFromOptions(partitioning));
    PLISSE_PETSC(MatPartitioningApply(partitioning, &is));
    const PetscInt* indices = nullptr;
    PLISSE_PETSC(ISGetIndices(is, &indices));
    for (int v = 0; v < n; ++v) part[v] = static_cast<int>(indices[v]);
    PLISSE_PETSC(ISRestoreIndices(is, &indices));
  } catch (...) {
    ISDestroy(&is);
    MatPartitioningDestroy(&partitioning);
    MatDestroy(&graph);
    PetscFree(vertex_weights);
    throw;
  }
  ISDestroy(&is);
  MatPartitioningDestroy(&partitioning);
  MatDestroy(&graph);
  for (int v = 0; v < n; ++v)
    FE_CHECK(part[v] >= 0 && part[v] < parts,
             "the partitioner put node " << v << " into part " << part[v] << " of " << parts);
  return part;
}

}  // namespace

std::vector<int> partition_graph(const std::vector<int>& start, const std::vector<int>& adjacency,
                                 const std::vector<int>& weights, int parts, MPI_Comm comm) {
  FE_CHECK(!start.empty() && weights.size() + 1 == start.size(),
           "partition_graph: " << weights.size() << " weights for " << start.size() - 1
                               << " vertices");
  FE_CHECK(parts >= 1, "partition_graph: " << parts << " parts");
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
