#include "solver/pressure_twins.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>

#include "core/error.hpp"

namespace plisse {

PressureTwins make_pressure_twins(int n_mesh_nodes, const std::vector<std::array<int, 4>>& corners,
                                  const std::vector<int>& region) {
  PressureTwins twins;
  twins.n_nodes = n_mesh_nodes;
  if (region.empty()) return twins;
  PLISSE_CHECK(region.size() == corners.size(),
               "pressure regions: " << region.size() << " for " << corners.size() << " elements");
  // (node, region) of every deformable element's corner, sorted and unique: the regions at each
  // node, smallest first.
  std::vector<std::pair<int, int>> node_region;
  node_region.reserve(4 * corners.size());
  for (std::size_t e = 0; e < corners.size(); ++e)
    if (region[e] >= 0)
      for (int v : corners[e]) node_region.emplace_back(v, region[e]);
  std::sort(node_region.begin(), node_region.end());
  node_region.erase(std::unique(node_region.begin(), node_region.end()), node_region.end());
  // The node of each (node, region): the node itself for its first region, else a new twin.
  std::vector<int> holder(node_region.size());
  for (std::size_t k = 0; k < node_region.size(); ++k) {
    if (k > 0 && node_region[k - 1].first == node_region[k].first) {
      holder[k] = n_mesh_nodes + twins.n_twins();
      twins.corner.push_back(node_region[k].first);
    } else {
      holder[k] = node_region[k].first;
    }
  }
  twins.n_nodes = n_mesh_nodes + twins.n_twins();
  if (twins.corner.empty()) return twins;  // one region touches every node: nothing to split
  twins.carrier.resize(4 * corners.size());
  for (std::size_t e = 0; e < corners.size(); ++e)
    for (int a = 0; a < 4; ++a) {
      const int v = corners[e][static_cast<std::size_t>(a)];
      if (region[e] < 0) {
        twins.carrier[4 * e + a] = v;
        continue;
      }
      const auto it =
          std::lower_bound(node_region.begin(), node_region.end(), std::make_pair(v, region[e]));
      twins.carrier[4 * e + a] = holder[static_cast<std::size_t>(it - node_region.begin())];
    }
  return twins;
}

}  // namespace plisse
