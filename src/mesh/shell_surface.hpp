#pragma once
/// The mid-surface of a shell (docs/theory/shell.md): a mesh of triangles and no tetrahedra,
/// with the thickness of every node and, for every triangle, the nodes across its three sides,
/// the 6-node patch of the rotation-free shell triangle (KL1). The neighbours are found once,
/// here, so that the assembly reads an element's patch in O(1).
#include "mesh/mesh.hpp"

namespace plisse {

/// Makes `mesh` (triangles, no tetrahedra) the mid-surface of a shell of uniform reference
/// thickness `thickness` [mm]: fills mesh.shell_thickness and mesh.triangle_neighbours. Throws
/// plisse::Error when the mesh has tetrahedra or no triangles, the thickness is not positive, a
/// triangle repeats a node or names one out of range, an edge is shared by more than two
/// triangles, or two triangles sharing an edge are oriented inconsistently (both run through it
/// in the same direction: their normals, and a follower pressure on them, would disagree).
void make_shell_surface(Mesh& mesh, double thickness);

}  // namespace plisse
