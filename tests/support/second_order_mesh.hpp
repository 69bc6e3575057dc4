#pragma once
/// Test helper: turns a linear mesh into a second-order one by adding one node per tetrahedron
/// edge (tet_edge_nodes in Gmsh's order, triangle_edge_nodes in the order 01, 12, 20 of each
/// triangle), placed by a caller's rule, e.g. on a sphere. Independent of the mesh generators'
/// own `order 2`.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <utility>

#include "mesh/mesh.hpp"
#include "mesh/topology.hpp"

namespace plisse::test {

/// Where the edge node of the edge (Xa, Xb) goes [mm].
using EdgeNodePlacement = std::function<Vec3d(const Vec3d& Xa, const Vec3d& Xb)>;

/// The midpoint of the edge: a straight-sided second-order mesh.
inline Vec3d edge_midpoint(const Vec3d& a, const Vec3d& b) { return 0.5 * (a + b); }

/// `linear` with an edge node on every tetrahedron edge, at place(Xa, Xb).
inline Mesh with_edge_nodes(const Mesh& linear, const EdgeNodePlacement& place = edge_midpoint) {
  Mesh mesh = linear;
  std::map<std::pair<int, int>, int> edge_node;
  const auto node_of = [&](int a, int b) {
    const std::pair<int, int> key = {std::min(a, b), std::max(a, b)};
    auto it = edge_node.find(key);
    if (it != edge_node.end()) return it->second;
    mesh.nodes.push_back(place(linear.nodes[a], linear.nodes[b]));
    return edge_node[key] = mesh.n_nodes() - 1;
  };
  mesh.tet_edge_nodes.clear();
  for (const auto& tet : linear.tets) {
    std::array<int, 6> edges;
    for (size_t e = 0; e < kTetEdges.size(); ++e)
      edges[e] = node_of(tet[kTetEdges[e][0]], tet[kTetEdges[e][1]]);
    mesh.tet_edge_nodes.push_back(edges);
  }
  mesh.triangle_edge_nodes.clear();
  for (const auto& t : linear.triangles)
    mesh.triangle_edge_nodes.push_back(
        {node_of(t[0], t[1]), node_of(t[1], t[2]), node_of(t[2], t[0])});
  return mesh;
}

/// A placement for spherical shells centred at the origin: an edge whose two ends lie on one
/// sphere |X| = r (relative 1e-6) gets its node on that sphere, radially above the midpoint;
/// other edges stay straight.
inline Vec3d on_sphere_of_ends(const Vec3d& a, const Vec3d& b) {
  const Vec3d m = edge_midpoint(a, b);
  const double ra = a.norm(), rb = b.norm();
  if (std::abs(ra - rb) > 1e-6 * std::max(ra, rb)) return m;
  return m.normalized() * 0.5 * (ra + rb);
}

}  // namespace plisse::test
