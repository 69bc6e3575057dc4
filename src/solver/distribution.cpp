#include "solver/distribution.hpp"

#include <algorithm>

#include "solver/partition.hpp"

namespace plisse {

Distribution::Distribution(const NodeGraph& graph, ElementNodes elements, int n_global,
                           const std::vector<ConstrainedComponent>& constraints)
    : dofs_(static_cast<int>(graph.start.size()) - 1, n_global, constraints) {
  const int n_nodes = dofs_.n_nodes();
  PetscBool initialized = PETSC_FALSE;
  PLISSE_PETSC(PetscInitialized(&initialized));
  if (initialized) {
    PLISSE_PETSC(MPI_Comm_size(PETSC_COMM_WORLD, &size_));
    PLISSE_PETSC(MPI_Comm_rank(PETSC_COMM_WORLD, &rank_));
  }
  node_rank_.assign(n_nodes, 0);
  if (size_ > 1) {
    // Balance the free unknowns (every node has at least its pressure unless constrained).
    std::vector<int> weights(n_nodes, 1);
    for (int v = 0; v < n_nodes; ++v) {
      int free = 0;
      for (int k = 0; k < DofMap::kPerNode; ++k) free += dofs_.equation(DofMap::dof(v, k)) >= 0;
      weights[v] = std::max(1, free);
    }
    node_rank_ = partition_graph(graph.start, graph.neighbours, weights, size_, PETSC_COMM_WORLD);
    std::vector<int> order(n_nodes);
    for (int v = 0; v < n_nodes; ++v) order[v] = v;
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return node_rank_[a] < node_rank_[b]; });
    dofs_ = DofMap(n_nodes, n_global, constraints, order);
  }
  // Owned range: the free equations of the nodes of lower ranks come first; the last rank also
  // owns the terms' global unknowns, numbered after every node.
  std::vector<int> before(size_ + 1, 0);
  for (int v = 0; v < n_nodes; ++v)
    for (int k = 0; k < DofMap::kPerNode; ++k)
      before[node_rank_[v] + 1] += dofs_.equation(DofMap::dof(v, k)) >= 0;
  for (int r = 0; r < size_; ++r) before[r + 1] += before[r];
  first_equation_ = before[rank_];
  end_equation_ = rank_ == size_ - 1 ? dofs_.n_free() : before[rank_ + 1];
  for (int e = 0; e < elements.n_elements(); ++e) {
    const auto nodes = elements.of(e);
    if (node_rank_[nodes[0]] == rank_) owned_elements_.push_back(e);
    for (int a : nodes)
      if (node_rank_[a] == rank_) {
        local_elements_.push_back(e);
        break;
      }
  }
  if (size_ > 1) {
    Vec x = create_vector();
    PLISSE_PETSC(VecScatterCreateToAll(x, &gather_all_, &gathered_));
    PLISSE_PETSC(VecDestroy(&x));
  }
}

Distribution::~Distribution() {
  VecScatterDestroy(&gather_all_);
  VecDestroy(&gathered_);
}

Vec Distribution::create_vector() const {
  Vec x = nullptr;
  if (size_ > 1)
    PLISSE_PETSC(VecCreateMPI(PETSC_COMM_WORLD, n_owned(), dofs_.n_free(), &x));
  else
    PLISSE_PETSC(VecCreateSeq(PETSC_COMM_SELF, dofs_.n_free(), &x));
  return x;
}

std::vector<double> Distribution::full_from_free(Vec x) const {
  std::vector<double> full(dofs_.n_dofs(), 0.0);
  for_each_free_value(x, [&](int d, double value) { full[d] = value; });
  return full;
}

void Distribution::owned_from_full(std::span<const double> full, Vec x) const {
  PetscScalar* a = nullptr;
  PLISSE_PETSC(VecGetArray(x, &a));
  for (int d = 0; d < dofs_.n_dofs(); ++d)
    if (const int eq = dofs_.equation(d); owns_equation(eq)) a[eq - first_equation_] = full[d];
  PLISSE_PETSC(VecRestoreArray(x, &a));
}

AssemblyStatus Distribution::reduce(const AssemblyStatus& local) const {
  if (size_ == 1) return local;
  // (failed, min J, worst element) of every rank; every rank picks the same one.
  const double mine[3] = {local.ok ? 0.0 : 1.0, local.min_J,
                          static_cast<double>(local.worst_element)};
  std::vector<double> all(3 * size_);
  PLISSE_PETSC(MPI_Allgather(mine, 3, MPI_DOUBLE, all.data(), 3, MPI_DOUBLE, PETSC_COMM_WORLD));
  int pick = -1;
  for (int r = 0; r < size_ && pick < 0; ++r)
    if (all[3 * r] != 0.0) pick = r;
  if (pick < 0) {
    pick = 0;
    for (int r = 1; r < size_; ++r)
      if (all[3 * r + 1] < all[3 * pick + 1]) pick = r;
  }
  AssemblyStatus status;
  status.ok = all[3 * pick] == 0.0;
  status.min_J = all[3 * pick + 1];
  status.worst_element = static_cast<int>(all[3 * pick + 2]);
  return status;
}

void Distribution::sum_over_ranks(double* values, std::size_t count) const {
  if (size_ == 1 || count == 0) return;
  // In slices: MPI counts are ints.
  constexpr std::size_t kSlice = std::size_t{1} << 28;
  for (std::size_t first = 0; first < count; first += kSlice)
    PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, values + first,
                               static_cast<int>(std::min(kSlice, count - first)), MPI_DOUBLE,
                               MPI_SUM, PETSC_COMM_WORLD));
}

}  // namespace plisse
