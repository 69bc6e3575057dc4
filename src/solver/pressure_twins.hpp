#pragma once
/// A discontinuous pressure between the regions of a body (docs/theory/regions.md, BL1-BL4): at a
/// corner node that tetrahedra of two or more regions share, every region but the first has a
/// pressure unknown of its own, held by a twin node after the mesh's nodes. The twin carries a
/// pressure value only (the model holds its displacement values at 0: the displacement is the
/// corner's, continuous). A region's elements take their pressure at such a corner from their
/// region's node, so the pressure may jump across the interface as the hydrostatic stress of two
/// bonded materials does, while it stays continuous inside each region.
#include <array>
#include <vector>

namespace plisse {

struct PressureTwins {
  /// Nodes of the state: the mesh's, then the twins.
  int n_nodes = 0;
  /// Per twin (node n_mesh_nodes + k): the mesh node it doubles.
  std::vector<int> corner;
  /// Per element and corner a (4 per element): the node whose pressure value the element's
  /// corner a takes; the corner itself, or its region's twin. Empty: no twins, every element
  /// takes its corners' values.
  std::vector<int> carrier;

  int n_twins() const { return static_cast<int>(corner.size()); }
  /// The node whose pressure element e takes at its corner a (0..3).
  int carrier_of(int e, int a, int corner_node) const {
    return carrier.empty() ? corner_node : carrier[4 * static_cast<std::size_t>(e) + a];
  }
};

/// The twins of a body whose element e (of `corners`, the four corner nodes of each element)
/// belongs to region `region[e]` (>= 0; negative: a rigid element, which takes no pressure).
/// At a corner node touched by the elements of several regions, the region with the smallest
/// number keeps the node's own pressure value and every other gets a twin, numbered node by node
/// in increasing order, then by region. `region` empty: no twins (n_nodes = n_mesh_nodes).
PressureTwins make_pressure_twins(int n_mesh_nodes, const std::vector<std::array<int, 4>>& corners,
                                  const std::vector<int>& region);

}  // namespace plisse
