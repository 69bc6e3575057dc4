#pragma once
/// Boundary triangles of a tagged surface, oriented with the body's outward normal.
#include <array>
#include <set>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace plisse {

/// The triangles of tag `name`, each ordered so that (x1 - x0) x (x2 - x0) points out of the body
/// (away from the fourth node of the tetrahedron the triangle is a face of). Throws plisse::Error
/// when a triangle is not a face of any tetrahedron.
std::vector<std::array<int, 3>> outward_triangles(const Mesh& mesh, const std::string& name);

/// The distinct nodes of `triangles`.
std::set<int> surface_nodes(const std::vector<std::array<int, 3>>& triangles);

}  // namespace plisse
