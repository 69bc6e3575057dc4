#pragma once
/// Boundary faces of a tagged surface, linear (3 nodes) or quadratic (6 nodes), oriented with the
/// body's outward normal.
#include <array>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace plisse {

/// A boundary face: the corners 0, 1, 2 and, on a second-order mesh, the edge nodes of the edges
/// 01, 12, 20 (nodes 3, 4, 5), so that the face map of the 6-node triangle
/// (physics/quadratic_triangle.hpp) has the orientation of the corners.
struct SurfaceFace {
  std::array<int, 6> nodes{-1, -1, -1, -1, -1, -1};  ///< mesh node indices; -1 when unused
  int n_nodes = 3;                                   ///< 3 (linear) or 6 (quadratic)

  std::array<int, 3> corners() const { return {nodes[0], nodes[1], nodes[2]}; }
  /// The n_nodes nodes, corners first. Borrows this face.
  std::span<const int> node_list() const { return {nodes.data(), static_cast<size_t>(n_nodes)}; }
  /// The edge node of corner edge k (0: 01, 1: 12, 2: 20); -1 on a linear face.
  int edge_node(int k) const { return n_nodes == 6 ? nodes[3 + k] : -1; }
};

/// The faces of tag `name`, each ordered so that (x1 - x0) x (x2 - x0) of its corners points out
/// of the body (away from the fourth corner of the tetrahedron the face belongs to), with the edge
/// nodes of a second-order mesh (mesh.triangle_edge_nodes) permuted with the corners. On a shell
/// mesh the tag names a face of the shell (Mesh::shell_face_side) and its outward normal is the
/// triangles' own on the +1 face, the opposite on the -1 face. Throws
/// plisse::Error when a triangle is not a face of any tetrahedron, or a second-order mesh lacks
/// the edge nodes of its triangles.
std::vector<SurfaceFace> outward_faces(const Mesh& mesh, const std::string& name);

/// The corners of outward_faces(mesh, name): how callers that only name faces (die contact
/// surfaces, which take corner triples) identify them.
std::vector<std::array<int, 3>> outward_triangles(const Mesh& mesh, const std::string& name);

/// The faces whose corners are `triangles` (each kept in its order), with their edge nodes on a
/// second-order mesh taken from the tetrahedra (mesh.tet_edge_nodes). Throws plisse::Error when
/// a corner pair is not an edge of any tetrahedron of a second-order mesh.
std::vector<SurfaceFace> faces_with_corners(const Mesh& mesh,
                                            const std::vector<std::array<int, 3>>& triangles);

/// Shell meshes only: the reference thickness [mm] of each of `triangles` (corner triples of the
/// mesh's triangles in any order, such as those of outward_triangles): Mesh::triangle_thickness
/// of the triangle with those corners. Throws plisse::Error when a triple is not a triangle of
/// the mesh.
std::vector<double> shell_thickness(const Mesh& mesh,
                                    const std::vector<std::array<int, 3>>& triangles);

/// The distinct nodes of `faces`, corners and edge nodes.
std::set<int> surface_nodes(const std::vector<SurfaceFace>& faces);

}  // namespace plisse
