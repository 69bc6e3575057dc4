#pragma once
/// The nodes of a contact surface with their tributary areas (docs/theory/contact.md, D5).
#include <array>
#include <map>
#include <vector>

#include "mesh/mesh.hpp"
#include "physics/surface.hpp"

namespace plisse {

/// Faces of the tetrahedra that belong to exactly one tetrahedron (the whole boundary), each as
/// its three corner nodes (orientation not normalised).
std::vector<std::array<int, 3>> boundary_faces(const Mesh& mesh);

/// Reference tributary area of the nodes of `faces` [mm^2], ordered by node index. A linear face
/// gives a third of its area to each corner (D5). A 6-node face gives its edge nodes the
/// consistent weights of a uniform pressure, ∫ N_a dA over the curved reference face, plus a third
/// of the corners' weights ∫ N_c dA each (0 on a face with a constant Jacobian), and its corners
/// nothing: they are not contact nodes (D16). The areas of a face sum to its area.
std::map<int, double> tributary_areas(const Mesh& mesh, const std::vector<SurfaceFace>& faces);

/// Reference tie weights of the nodes of `faces` [mm^2], the areas that scale the glue of a
/// sticking die (contact.md, D17), ordered by node index: on a linear face the tributary areas of
/// D5; on a 6-node face the diagonally lumped surface mass |T| m_a / Σ_b m_b with m_a = ∫ N_a² dA
/// (|T|/19 at the corners, 16|T|/57 at the edge nodes of a flat face). Positive at every node,
/// corners included; the weights of a face sum to its area.
std::map<int, double> tie_areas(const Mesh& mesh, const std::vector<SurfaceFace>& faces);

/// Mean reference edge length of `triangles` [mm] (each edge counted once per triangle).
/// Precondition: `triangles` is not empty.
double mean_edge_length(const Mesh& mesh, const std::vector<std::array<int, 3>>& triangles);

}  // namespace plisse
