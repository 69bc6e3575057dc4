#pragma once
/// The volume enclosed by a cavity's wall and the closure rule it relies on
/// (docs/theory/cavities.md, C1-C3).
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// Deformed position x = X + u of `node` from the full state (u at node_dof(node, 0..2)).
Vec3d deformed_position(const Mesh& mesh, std::span<const double> state, int node);

/// Volume [mm^3] enclosed by `triangles` in the state `state` (full-state layout of
/// model_term.hpp; only the nodal displacements are read), together with the symmetry planes
/// x = 0, y = 0, z = 0 that close its boundary:
///   V = -(1/6) sum x0 . (x1 x x2)   (cavities.md, C1).
/// `triangles` are oriented with the BODY's outward normal (outward_triangles), which points into
/// the cavity, so the volume of the cavity on the far side of the body's wall is positive.
/// Exact for the deformed tessellation when the surface is closed up to those planes
/// (first_open_edge) and its boundary nodes stay on them.
double cavity_volume(const Mesh& mesh, const std::vector<std::array<int, 3>>& triangles,
                     std::span<const double> state);

/// The first edge (node pair) of `triangles` that breaks the closure rule (cavities.md, C2): an
/// edge must belong to exactly two triangles, or to one triangle and lie in one of the planes
/// x = 0, y = 0, z = 0 (both end nodes with |coordinate| <= relative_tolerance times the largest
/// extent of the surface, in the reference configuration). nullopt when the rule holds.
std::optional<std::array<int, 2>> first_open_edge(const Mesh& mesh,
                                                  const std::vector<std::array<int, 3>>& triangles,
                                                  double relative_tolerance = 1e-8);

}  // namespace plisse
