#pragma once
/// Test helpers for second-order meshes: a linear mesh made second order with the edge nodes
/// placed by a caller's rule (e.g. on a sphere), and the nodes of a boundary face.
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/second_order.hpp"

namespace plisse::test {

/// Where the edge node of the edge (Xa, Xb) goes [mm].
using EdgeNodePlacement = std::function<Vec3d(const Vec3d& Xa, const Vec3d& Xb)>;

/// The midpoint of the edge: a straight-sided second-order mesh.
inline Vec3d edge_midpoint(const Vec3d& a, const Vec3d& b) { return 0.5 * (a + b); }

/// `linear` with an edge node on every tetrahedron edge, at place(Xa, Xb) (mesh/second_order.hpp).
inline Mesh with_edge_nodes(const Mesh& linear, const EdgeNodePlacement& place = edge_midpoint) {
  Mesh mesh = linear;
  add_edge_nodes(mesh, [&](int a, int b) { return place(linear.nodes[a], linear.nodes[b]); });
  return mesh;
}

/// The nodes of boundary triangle t: its corners, then on a second-order mesh its edge nodes.
inline std::vector<int> face_nodes(const Mesh& mesh, int t) {
  std::vector<int> nodes(mesh.triangles[t].begin(), mesh.triangles[t].end());
  if (mesh.order() == 2)
    nodes.insert(nodes.end(), mesh.triangle_edge_nodes[t].begin(),
                 mesh.triangle_edge_nodes[t].end());
  return nodes;
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
