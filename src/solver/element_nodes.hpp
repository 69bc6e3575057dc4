#pragma once
/// The node lists of the elements of a mesh, as the assembly sees them: `width` nodes per element,
/// element after element. The MINI tetrahedron lists its 4 corners; a quadratic tetrahedron would
/// list its 10 nodes. The node graph, the distribution and the tangent layout take this view and
/// so do not depend on the element type.
#include <cstddef>
#include <span>

namespace plisse {

/// A borrowed view of the element node lists; the storage must outlive it.
struct ElementNodes {
  std::span<const int> nodes;  ///< n_elements() * width node indices
  int width = 0;               ///< nodes per element (> 0 when there are elements)

  int n_elements() const { return width > 0 ? static_cast<int>(nodes.size()) / width : 0; }
  /// The nodes of element e (0 <= e < n_elements()).
  std::span<const int> of(int e) const {
    return nodes.subspan(static_cast<std::size_t>(e) * width, width);
  }
};

}  // namespace plisse
