#pragma once
/// Boundary triangles and their tags for generated meshes; the tagged edges of generated shells.
#include <functional>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/topology.hpp"

namespace plisse {

/// Fills `mesh.triangles` with all boundary faces of the tetrahedra (outward normal by the
/// right-hand rule) and `mesh.surface_tags` from a side classification: `side_of(face)` returns
/// an index into `side_tags`, whose entry lists the tag names of that side (e.g. {"left",
/// "sym_x"}). Triangles are grouped by side (in the order of `side_tags`). Every boundary face must
/// belong to a side (internal invariant: throws Error otherwise). Precondition: positive
/// tetrahedra.
void tag_boundary(Mesh& mesh, const std::vector<std::vector<std::string>>& side_tags,
                  const std::function<int(const BoundaryFace&)>& side_of);

/// Makes every tetrahedron positively oriented (swapping corners 1 and 2 where the signed volume
/// is negative) and throws Error if one has (near) zero volume: generators call it once.
void orient_generated_tets(Mesh& mesh, const std::string& generator);

/// A plane x_axis = value and the names of the edge tags of a shell's boundary edges in it.
struct EdgePlane {
  std::vector<std::string> names;  ///< e.g. {"left", "sym_x"}
  int axis = 0;                    ///< 0, 1, 2: x, y, z
  double value = 0.0;              ///< [mm]
};

/// Fills `mesh.edges` and `mesh.edge_tags` of a triangulated surface (a shell's mid-surface,
/// triangles and no tetrahedra) from its boundary: every side of exactly one triangle whose two
/// nodes have the coordinate `axis` exactly equal to `value` of a plane of `planes` is an edge
/// of that plane's tags (the first plane that holds it), stored once, as its triangle runs
/// through it: plane by plane in the order of `planes`, each plane's edges in the order of the
/// triangles and their sides. Every plane's names get a tag, empty if no edge lies in it.
/// Precondition: generators put the nodes of such planes exactly on them. With `others` given,
/// the boundary sides in none of the planes follow, as the edges of that tag (a disc's rim).
void tag_boundary_edges(Mesh& mesh, const std::vector<EdgePlane>& planes,
                        const std::string& others = "");

}  // namespace plisse
