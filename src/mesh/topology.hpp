#pragma once
/// Face topology of a tetrahedral mesh: local faces of a tetrahedron, signed volumes, and the
/// boundary faces (faces that belong to exactly one tetrahedron), oriented outward.
///
/// Convention: a tetrahedron (n0, n1, n2, n3) is positively oriented when
///   6 V = (x1 - x0) . ((x2 - x0) x (x3 - x0)) > 0.
/// Its faces, numbered by the opposite corner, are listed so that the right-hand rule gives the
/// outward normal: face k is opposite corner k (Gmsh/FEniCS style "face k misses node k").
#include <array>
#include <cstdint>
#include <set>
#include <vector>

#include "core/fnv1a.hpp"
#include "core/types.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// Local corner indices of face k (opposite corner k), outward for a positive tetrahedron.
inline constexpr std::array<std::array<int, 3>, 4> kTetFaces = {
    {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};

/// Local corner pairs of the six edges in Gmsh's order (01, 12, 20, 30, 32, 31); the 10-node
/// tetrahedron stores its edge nodes in this order.
inline constexpr std::array<std::array<int, 2>, 6> kTetEdges = {
    {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}}};

/// 6 V = (x1 - x0) . ((x2 - x0) x (x3 - x0)) [mm^3]; positive for a positively oriented tet.
inline double six_signed_volume(const Vec3d& x0, const Vec3d& x1, const Vec3d& x2,
                                const Vec3d& x3) {
  return (x1 - x0).dot((x2 - x0).cross(x3 - x0));
}

/// Signed volume of tetrahedron `t` of `mesh` [mm^3].
double tet_signed_volume(const Mesh& mesh, int t);

/// Swaps corners 1 and 2 of tetrahedron `t` (and, for a second-order mesh, its edge nodes
/// accordingly), which flips the sign of its volume.
void flip_tet(Mesh& mesh, int t);

/// The nodes of the boundary triangles `triangles` (indices into mesh.triangles): their corners
/// and, on a second-order mesh, their edge nodes. Throws plisse::Error when a triangle of a
/// second-order mesh has no edge nodes.
std::set<int> triangle_nodes(const Mesh& mesh, const std::vector<int>& triangles);

/// The nodes of the shell edges `edges` (indices into mesh.edges).
std::set<int> edge_nodes(const Mesh& mesh, const std::vector<int>& edges);

/// The nodes of the tetrahedra `tets` (indices into mesh.tets): their corners and, on a
/// second-order mesh, their edge nodes.
std::set<int> tet_nodes(const Mesh& mesh, const std::vector<int>& tets);

/// The node nearest to `point` (on equal distance the lower index): corners and, on a
/// second-order mesh, edge nodes alike. O(n_nodes). Precondition: the mesh has nodes.
int nearest_node(const Mesh& mesh, const Vec3d& point);

/// FNV-1a (64 bit) of the mesh's node coordinates and tetrahedra, bit for bit: two meshes with
/// the same value are the same mesh (the ranks' agreement, the checkpoint's fingerprint).
inline std::uint64_t geometry_hash(const Mesh& mesh) {
  Fnv1a hash;
  for (const auto& x : mesh.nodes) hash.add(x.data(), 3 * sizeof(double));
  for (const auto& t : mesh.tets) hash.add(t.data(), sizeof t);
  return hash.value();
}

/// The longest edge [mm] of the tetrahedra that have node `v` as a corner or an edge node (the
/// corner edges: a curved 10-node edge counts by its chord), on a shell mesh of the triangles
/// that have it as a corner. 0 for a node of no element.
double longest_edge_at(const Mesh& mesh, int v);

/// A face of the tetrahedral mesh that belongs to exactly one tetrahedron.
struct BoundaryFace {
  std::array<int, 3> nodes;  ///< corner nodes, outward normal by the right-hand rule
  int tet = -1;              ///< the tetrahedron it belongs to
  int local_face = -1;       ///< 0..3, opposite corner of `tet`
};

/// All boundary faces, sorted by their sorted node triple. Outward orientation assumes the
/// tetrahedra are positively oriented. Cost O(n log n), n = number of tetrahedra.
std::vector<BoundaryFace> compute_boundary_faces(const Mesh& mesh);

/// Face key: the three node indices in increasing order.
inline std::array<int, 3> sorted_face(std::array<int, 3> f) {
  if (f[0] > f[1]) std::swap(f[0], f[1]);
  if (f[1] > f[2]) std::swap(f[1], f[2]);
  if (f[0] > f[1]) std::swap(f[0], f[1]);
  return f;
}

}  // namespace plisse
