#pragma once
/// How the discrete problem is spread over the ranks of PETSC_COMM_WORLD: everything of the model
/// that knows about ranks.
///
/// Every rank holds the whole mesh and the whole state; the equations are distributed. The nodes
/// are partitioned (solver/partition.hpp), the equations numbered rank by rank (DofMap with a node
/// order), so that rank r owns one contiguous range: the free equations of its nodes; the last
/// rank also owns the terms' global unknowns. Rank r evaluates the elements that touch one of its
/// nodes (its local elements) and reports those whose first node it owns (its owned elements:
/// each element is owned by exactly one rank). Free values are gathered to every rank after each
/// update (for_each_free_value), and whole-body results are summed over the ranks. On one rank
/// (or without PETSc) this is rank 0 of 1: everything local and owned, no communication.
#include <mpi.h>
#include <petscvec.h>

#include <cstddef>
#include <span>
#include <vector>

#include "physics/dirichlet.hpp"
#include "solver/assembly_status.hpp"
#include "solver/dof_map.hpp"
#include "solver/element_nodes.hpp"
#include "solver/node_graph.hpp"
#include "solver/petsc_call.hpp"

namespace plisse {

class Distribution {
 public:
  /// Partitions the nodes of `graph` among the ranks (balancing their free unknowns) and numbers
  /// the equations of the `n_global` global unknowns and of the nodes, minus `constraints`, rank
  /// by rank. `elements` are the model's element node lists. Collective on PETSC_COMM_WORLD
  /// when PETSc is initialised.
  Distribution(const NodeGraph& graph, ElementNodes elements, int n_global,
               const std::vector<ConstrainedComponent>& constraints);
  ~Distribution();
  Distribution(const Distribution&) = delete;
  Distribution& operator=(const Distribution&) = delete;

  /// The equation numbering (rank by rank).
  const DofMap& dofs() const { return dofs_; }
  /// The communicator of the algebraic objects: PETSC_COMM_SELF on one rank, else PETSC_COMM_WORLD.
  MPI_Comm comm() const { return size_ > 1 ? PETSC_COMM_WORLD : PETSC_COMM_SELF; }
  int rank() const { return rank_; }
  int n_ranks() const { return size_; }
  /// The equations this rank owns: [first_equation, end_equation).
  int first_equation() const { return first_equation_; }
  int end_equation() const { return end_equation_; }
  int n_owned() const { return end_equation_ - first_equation_; }
  /// True when equation `eq` (negative: constrained) is one of this rank's.
  bool owns_equation(int eq) const { return eq >= first_equation_ && eq < end_equation_; }
  /// True when node v's equations are this rank's (its residual entries are complete here).
  bool owns_node(int v) const { return node_rank_[v] == rank_; }
  /// Elements with at least one owned node, ascending (all of them on one rank).
  const std::vector<int>& local_elements() const { return local_elements_; }
  /// Elements whose first node is owned, ascending.
  const std::vector<int>& owned_elements() const { return owned_elements_; }

  /// A vector over the free dofs with this rank's owned range. The caller owns it.
  Vec create_vector() const;
  /// Calls use(d, value) for every free dof d with its value in `x` (a vector of create_vector's
  /// layout). Collective: gathers `x` to every rank in a distributed run.
  template <class Use>
  void for_each_free_value(Vec x, Use&& use) const;
  /// The full state layout (zeros on constrained dofs) of `x`. Collective.
  std::vector<double> full_from_free(Vec x) const;
  /// The reverse: writes the entries of `full` (full-state layout) on this rank's owned free
  /// equations into `x` (a vector of create_vector's layout). Not collective.
  void owned_from_full(std::span<const double> full, Vec x) const;

  /// The same status on every rank: the first rank's failure, else the smallest J of all.
  /// Collective.
  AssemblyStatus reduce(const AssemblyStatus& local) const;
  /// Sums `values` over the ranks in place (each rank contributes what it owns, zeros elsewhere).
  /// Collective.
  void sum_over_ranks(double* values, std::size_t count) const;

 private:
  DofMap dofs_;
  int rank_ = 0, size_ = 1;
  std::vector<int> node_rank_;
  int first_equation_ = 0, end_equation_ = 0;
  std::vector<int> local_elements_;
  std::vector<int> owned_elements_;
  VecScatter gather_all_ = nullptr;  ///< free vector -> every rank's full copy
  Vec gathered_ = nullptr;
};

template <class Use>
void Distribution::for_each_free_value(Vec x, Use&& use) const {
  Vec source = x;
  if (size_ > 1) {  // every rank needs every free value
    PLISSE_PETSC(VecScatterBegin(gather_all_, x, gathered_, INSERT_VALUES, SCATTER_FORWARD));
    PLISSE_PETSC(VecScatterEnd(gather_all_, x, gathered_, INSERT_VALUES, SCATTER_FORWARD));
    source = gathered_;
  }
  const PetscScalar* a = nullptr;
  PLISSE_PETSC(VecGetArrayRead(source, &a));
  for (int d = 0; d < dofs_.n_dofs(); ++d)
    if (const int eq = dofs_.equation(d); eq >= 0) use(d, a[eq]);
  PLISSE_PETSC(VecRestoreArrayRead(source, &a));
}

}  // namespace plisse
