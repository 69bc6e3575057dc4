#pragma once
/// Where a point of the undeformed body lies in the mesh, and the values of nodal fields there
/// (probes, docs/output.md "Probes").
#include <array>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// A material point of the mesh: an element and the point's barycentric coordinates in it.
struct MeshPoint {
  int element = -1;                ///< index into mesh.tets (of a shell, into mesh.triangles)
  std::array<double, 4> L{};       ///< barycentric coordinates in the element, sum 1 (of a
                                   ///< shell's triangle, the first three)
  Vec3d position = Vec3d::Zero();  ///< X(L), the point of the mesh [mm] (reference)
  double distance = 0.0;           ///< |X(L) - the point asked for| [mm]
  bool inside = false;             ///< the point lies in the element (distance ~ 0)
};

/// Locates `point` (reference configuration) in `mesh`. Inside the body: the element that
/// contains it, with the barycentric coordinates of the point under the element's own map
/// (linear, or the 10-node isoparametric map of a second-order mesh, inverted by Newton's method);
/// a point on a shared face or edge goes to the element that contains it with the largest
/// smallest coordinate. Outside (a point on a curved surface that the mesh's facets miss, or off
/// the body): the nearest point of the boundary faces, on the flat face through its corners, with
/// its distance. On a shell's mid-surface (Mesh::is_shell): the nearest point of its triangles,
/// `inside` when the point lies on it. O(n_elements), once per point. Throws Error for a mesh
/// without elements.
MeshPoint locate_point(const Mesh& mesh, const Vec3d& point);

/// The nodes of element `p.element` and the values of their shape functions at p.L: the 4 linear
/// ones on a first-order mesh, the 10 quadratic ones (corners, then edge nodes) on a second-order
/// mesh, the 3 linear ones of a shell's triangle. A nodal field f is Σ_a N_a f[node_a] at the
/// point.
std::vector<std::pair<int, double>> interpolation_weights(const Mesh& mesh, const MeshPoint& p);

/// Σ_a N_a f[node_a]: a nodal field (one value a node, of any type with + and scalar *) at `p`.
template <class T>
T interpolate(const std::vector<std::pair<int, double>>& weights, const std::vector<T>& f) {
  T sum = weights.front().second * f[static_cast<std::size_t>(weights.front().first)];
  for (std::size_t a = 1; a < weights.size(); ++a)
    sum = sum + weights[a].second * f[static_cast<std::size_t>(weights[a].first)];
  return sum;
}

}  // namespace plisse
