#pragma once
/// Second-order (10-node) tetrahedral meshes from linear ones: one node per edge.
#include <functional>

#include "core/types.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// Makes the linear mesh `mesh` second order: adds one node per distinct edge of its tetrahedra
/// (shared by every tetrahedron and boundary triangle on that edge) and fills
/// `mesh.tet_edge_nodes` (Gmsh edge order 01, 12, 20, 30, 32, 31 of each tetrahedron's corners)
/// and `mesh.triangle_edge_nodes` (01, 12, 20 of each triangle's corners).
/// The edge between corner nodes a < b gets the position `midpoint(a, b)` [mm] (called once per
/// edge, always with a < b): the straight midpoint for flat walls, a point on the true surface for
/// curved ones. Edge nodes are numbered n, n + 1, ... (n = `mesh.n_nodes()` before the call) in
/// increasing (a, b); corner nodes, tetrahedra, triangles and tags are unchanged.
/// Preconditions: `mesh` is linear (`order() == 1`) and every triangle edge is a tetrahedron edge
/// (throws Error otherwise). Cost O(E log E), E = 6 x number of tetrahedra.
void add_edge_nodes(Mesh& mesh, const std::function<Vec3d(int a, int b)>& midpoint);

/// `add_edge_nodes` with the straight midpoint (x_a + x_b) / 2: exact for straight-sided
/// tetrahedra (cube, sheet). An edge in a coordinate plane keeps that coordinate exactly.
void add_straight_edge_nodes(Mesh& mesh);

}  // namespace plisse
