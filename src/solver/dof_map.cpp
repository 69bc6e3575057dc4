#include "solver/dof_map.hpp"

namespace plisse {

DofMap::DofMap(int n_nodes, const std::vector<ConstrainedComponent>& constrained)
    : equation_(static_cast<size_t>(kPerNode) * n_nodes, 0) {
  for (const auto& c : constrained) equation_[dof(c.node, c.component)] = -1;
  for (int d = 0; d < n_dofs(); ++d) {
    if (equation_[d] < 0) continue;
    equation_[d] = n_free_++;
    if (d % kPerNode == 3) ++n_free_pressure_;
  }
}

}  // namespace plisse
