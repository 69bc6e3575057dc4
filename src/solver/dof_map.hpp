#pragma once
/// Numbering of the unknowns: four per node (ux, uy, uz, p), then the global unknowns of the model
/// terms (physics/model_term.hpp). Constrained displacement components are eliminated from the
/// algebraic system: only free dofs get an equation number.
///
/// Equations are numbered node by node in a given node order (the identity by default), the free
/// components of a node consecutively, then the free global unknowns. A distributed run orders the
/// nodes by rank, so that each rank owns one contiguous range of equations (solver/partition.hpp).
#include <vector>

#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"

namespace plisse {

class DofMap {
 public:
  static constexpr int kPerNode = kValuesPerNode;  ///< ux, uy, uz, p
  /// `node_order`, when given, is a permutation of the nodes: the order in which their equations
  /// are numbered.
  DofMap(int n_nodes, int n_global, const std::vector<ConstrainedComponent>& constrained,
         const std::vector<int>& node_order = {});

  /// Index of component `comp` (0..2 displacement, 3 pressure) of `node` in the full state: the
  /// layout's one formula, node_dof (physics/model_term.hpp), which the terms use.
  static int dof(int node, int comp) { return node_dof(node, comp); }
  int n_dofs() const { return static_cast<int>(equation_.size()); }
  int n_free() const { return n_free_; }
  int n_free_pressure() const { return n_free_pressure_; }
  int n_nodes() const { return n_nodes_; }
  /// Full-state index of global unknown k (after all nodal values).
  int global_dof(int k) const { return kPerNode * n_nodes_ + k; }
  /// True when full-state index d is a nodal pressure (not a displacement, not a global unknown).
  bool is_pressure(int d) const { return d < kPerNode * n_nodes_ && d % kPerNode == 3; }
  /// Equation number of a full-state dof, or -1 when it is constrained.
  int equation(int dof) const { return equation_[dof]; }
  const std::vector<int>& equations() const { return equation_; }

 private:
  std::vector<int> equation_;
  int n_nodes_ = 0;
  int n_free_ = 0;
  int n_free_pressure_ = 0;
};

/// The largest distance between two full states' displacements over the nodes 0 .. n_nodes - 1:
/// max over nodes of |u(x) - u(y)| [mm] (the pressures and global unknowns left out).
double max_nodal_distance(const std::vector<double>& x, const std::vector<double>& y, int n_nodes);

}  // namespace plisse
