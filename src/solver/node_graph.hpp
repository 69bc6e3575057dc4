#pragma once
/// The node graph of the discrete problem: which nodes are coupled in the tangent. The nodes of
/// an element couple with each other, every node with itself, and the nodes of the couplings the
/// model terms declare (ModelTerm::add_couplings) with each other. The graph is cut into parts
/// for distributed runs (solver/distribution.hpp) and gives the sparsity of the tangent
/// (solver/tangent_layout.hpp).
#include <utility>
#include <vector>

#include "solver/element_nodes.hpp"

namespace plisse {

/// Compressed rows: the neighbours of node v are neighbours[start[v]] .. neighbours[start[v + 1]
/// - 1], sorted ascending and unique; every node lists itself.
struct NodeGraph {
  std::vector<int> start;       ///< n_nodes + 1 row starts
  std::vector<int> neighbours;  ///< node indices
};

/// The node graph of `n_nodes` nodes coupled by `elements` and by `couplings` ((row, column)
/// pairs of full-state dofs, solver/dof_map.hpp layout; pairs involving a global unknown of a
/// term couple no nodes and are skipped).
NodeGraph build_node_graph(int n_nodes, ElementNodes elements,
                           const std::vector<std::pair<int, int>>& couplings);

}  // namespace plisse
