#pragma once
/// The mid-surface of a shell (docs/theory/shell.md): a mesh of triangles and no tetrahedra,
/// with the thickness of every node and, for every triangle, the nodes and triangles across its
/// three sides, from which the assembly reads the 12-node patch of the rotation-free shell
/// triangle (KL1b) in O(1). The neighbours are found once, here.
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"

namespace plisse {

/// Makes `mesh` (triangles, no tetrahedra) the mid-surface of a shell of uniform reference
/// thickness `thickness` [mm]: fills mesh.triangle_thickness, mesh.shell_thickness,
/// mesh.triangle_neighbours and mesh.triangle_adjacent. Throws
/// plisse::Error when the mesh has tetrahedra or no triangles, the thickness is not positive, a
/// triangle repeats a node or names one out of range, an edge is shared by more than two
/// triangles, or two triangles sharing an edge are oriented inconsistently (both run through it
/// in the same direction: their normals, and a follower pressure on them, would disagree).
void make_shell_surface(Mesh& mesh, double thickness);

/// Gives the triangles `triangles` (indices into mesh.triangles) the reference thickness
/// `thickness` [mm] (a region of its own thickness) and makes every node's the mean of its
/// triangles'. Precondition: mesh.is_shell(); throws plisse::Error for a thickness that is not
/// positive or a triangle out of range.
void set_shell_thickness(Mesh& mesh, const std::vector<int>& triangles, double thickness);

/// A side of a shell triangle on the surface's edge: its triangle and its directed pair of nodes
/// (corner i + 1, corner i + 2 of the triangle, the key of Mesh::side_mirrors).
struct EdgeSide {
  int triangle = 0;
  std::pair<int, int> nodes;
};

/// The sides of the shell's triangles that lie on the tagged edges `edges` (indices into
/// mesh.edges) and have no neighbour. Precondition: mesh.is_shell().
std::vector<EdgeSide> sides_on_edges(const Mesh& mesh, const std::vector<int>& edges);

/// A clamped edge (docs/theory/shell.md, KL8a): every side of `edges` without a neighbour sees
/// its missing node as the half turn of the opposite corner about the triangle's reference
/// normal through the side's midpoint, so that the slope across the edge stays in the reference
/// tangent plane while the edge's nodes are held. Precondition: mesh.is_shell().
void clamp_sides(Mesh& mesh, const std::vector<int>& edges);

/// A shell glued to rigid parts that only translate (a case's rigid regions): the patches of the
/// triangles with `rigid[t]` == 0 no longer reach across their sides into the triangles with
/// `rigid[t]` != 0 (neither side sees the other as a neighbour), and each side between the two
/// is clamped as clamp_sides clamps an edge (KL8a): the rigid part's slope is its reference one,
/// and the side's bending is counted in full on the deformable side. Returns the number of sides
/// clamped. Precondition: mesh.is_shell(), rigid.size() == mesh.triangles.size().
int clamp_to_rigid(Mesh& mesh, const std::vector<char>& rigid);

/// A symmetry edge (KL8a): every side of `edges` without a neighbour sees its missing node as the
/// mirror image of the opposite corner through the plane x_axis = value, so that the surface
/// meets the plane at a right angle. Precondition: mesh.is_shell(), axis 0, 1 or 2.
void mirror_sides(Mesh& mesh, const std::vector<int>& edges, int axis, double value);

}  // namespace plisse
