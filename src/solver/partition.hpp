#pragma once
/// Partition of a mesh's nodes among the ranks of a distributed run.
///
/// plisse keeps the mesh and the state on every rank and distributes the equations: rank r owns
/// the equations of the nodes of part r (solver/dof_map.hpp numbers them contiguously) and
/// evaluates every element that touches one of those nodes, so that it can fill its rows of the
/// tangent completely without sending element contributions to other ranks. The partition cuts
/// the node graph (nodes coupled through an element) into parts of about equal weight (free
/// unknowns) with few cut edges; the number of elements evaluated twice is the number of cut
/// elements.
#include <mpi.h>

#include <vector>

namespace plisse {

/// Splits the vertices of the graph (CSR: the neighbours of vertex v are
/// adjacency[start[v]] .. adjacency[start[v + 1] - 1]; self loops are ignored) into `parts` parts
/// and returns the part of every vertex. `weights` (one per vertex, >= 1) are balanced. The graph
/// is partitioned with METIS (multilevel k-way, fixed seed: the same parts in every run) on rank
/// 0 of `comm` and broadcast, so that every rank gets the same answer. With parts == 1 every
/// vertex is in part 0. Collective on `comm`.
std::vector<int> partition_graph(const std::vector<int>& start, const std::vector<int>& adjacency,
                                 const std::vector<int>& weights, int parts, MPI_Comm comm);

}  // namespace plisse
