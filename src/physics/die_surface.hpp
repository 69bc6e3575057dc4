#pragma once
/// The nodes of a contact surface with their tributary areas (docs/theory/contact.md, D5).
#include <array>
#include <map>
#include <vector>

#include "mesh/mesh.hpp"

namespace plisse {

/// Faces of the tetrahedra that belong to exactly one tetrahedron (the whole boundary), each as
/// its three corner nodes (orientation not normalised).
std::vector<std::array<int, 3>> boundary_faces(const Mesh& mesh);

/// Reference tributary area of every node of `triangles` [mm^2]: a third of the area of each
/// triangle it is a corner of (D5). Ordered by node index.
std::map<int, double> tributary_areas(const Mesh& mesh,
                                      const std::vector<std::array<int, 3>>& triangles);

/// Mean reference edge length of `triangles` [mm] (each edge counted once per triangle).
/// Precondition: `triangles` is not empty.
double mean_edge_length(const Mesh& mesh, const std::vector<std::array<int, 3>>& triangles);

}  // namespace plisse
