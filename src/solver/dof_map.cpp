#include "solver/dof_map.hpp"

namespace plisse {

DofMap::DofMap(int n_nodes, int n_global, const std::vector<ConstrainedComponent>& constrained)
    : equation_(static_cast<size_t>(kPerNode) * n_nodes + n_global, 0), n_nodes_(n_nodes) {
  for (const auto& c : constrained) equation_[dof(c.node, c.component)] = -1;
  for (int d = 0; d < n_dofs(); ++d) {
    if (equation_[d] < 0) continue;
    equation_[d] = n_free_++;
    if (d < kPerNode * n_nodes_ && d % kPerNode == 3) ++n_free_pressure_;
  }
}

}  // namespace plisse
