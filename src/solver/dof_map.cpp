#include "solver/dof_map.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace plisse {

DofMap::DofMap(int n_nodes, int n_global, const std::vector<ConstrainedComponent>& constrained,
               const std::vector<int>& node_order)
    : equation_(static_cast<size_t>(kPerNode) * n_nodes + n_global, 0), n_nodes_(n_nodes) {
  PLISSE_CHECK(
      node_order.empty() || node_order.size() == static_cast<size_t>(n_nodes),
      "DofMap: a node order of " << node_order.size() << " entries for " << n_nodes << " nodes");
  for (const auto& c : constrained) equation_[dof(c.node, c.component)] = -1;
  const auto number = [&](int d) {
    if (equation_[d] < 0) return;
    equation_[d] = n_free_++;
    if (is_pressure(d)) ++n_free_pressure_;
  };
  std::vector<char> seen(node_order.empty() ? 0 : n_nodes, 0);
  for (int k = 0; k < n_nodes; ++k) {
    const int v = node_order.empty() ? k : node_order[k];
    if (!node_order.empty()) {
      PLISSE_CHECK(v >= 0 && v < n_nodes && !seen[v],
                   "DofMap: the node order is not a permutation");
      seen[v] = 1;
    }
    for (int c = 0; c < kPerNode; ++c) number(dof(v, c));
  }
  for (int d = kPerNode * n_nodes; d < n_dofs(); ++d) number(d);
}

double max_nodal_distance(const std::vector<double>& x, const std::vector<double>& y, int n_nodes) {
  double d = 0.0;
  for (int v = 0; v < n_nodes; ++v) {
    double s = 0.0;
    for (int k = 0; k < 3; ++k) s += std::pow(x[DofMap::dof(v, k)] - y[DofMap::dof(v, k)], 2);
    d = std::max(d, std::sqrt(s));
  }
  return d;
}

}  // namespace plisse
