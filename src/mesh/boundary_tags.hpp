#pragma once
/// Boundary triangles and their tags for generated meshes.
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

}  // namespace plisse
