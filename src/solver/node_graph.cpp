#include "solver/node_graph.hpp"

#include <algorithm>

#include "solver/dof_map.hpp"

namespace plisse {

NodeGraph build_node_graph(int n_nodes, ElementNodes elements,
                           const std::vector<std::pair<int, int>>& couplings) {
  const int n_nodal = DofMap::kPerNode * n_nodes;
  // Filled by counting, then sorted and made unique per node.
  std::vector<int> count(n_nodes + 1, 0);
  for (int e = 0; e < elements.n_elements(); ++e)
    for (int a : elements.of(e)) count[a + 1] += elements.width;
  for (int v = 0; v < n_nodes; ++v) ++count[v + 1];
  for (const auto& [row, col] : couplings)
    if (row < n_nodal && col < n_nodal) ++count[row / DofMap::kPerNode + 1];
  for (int v = 0; v < n_nodes; ++v) count[v + 1] += count[v];
  std::vector<int> fill(count.begin(), count.end() - 1);
  std::vector<int> all(count[n_nodes]);
  for (int e = 0; e < elements.n_elements(); ++e)
    for (int a : elements.of(e))
      for (int b : elements.of(e)) all[fill[a]++] = b;
  for (int v = 0; v < n_nodes; ++v) all[fill[v]++] = v;
  for (const auto& [row, col] : couplings)
    if (row < n_nodal && col < n_nodal)
      all[fill[row / DofMap::kPerNode]++] = col / DofMap::kPerNode;
  NodeGraph graph;
  graph.start.assign(n_nodes + 1, 0);
  graph.neighbours.reserve(all.size() / 3);
  for (int v = 0; v < n_nodes; ++v) {
    auto begin = all.begin() + count[v], end = all.begin() + count[v + 1];
    std::sort(begin, end);
    graph.neighbours.insert(graph.neighbours.end(), begin, std::unique(begin, end));
    graph.start[v + 1] = static_cast<int>(graph.neighbours.size());
  }
  return graph;
}

}  // namespace plisse
