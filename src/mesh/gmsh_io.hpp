#pragma once
/// Reading and writing Gmsh `.msh` files through the Gmsh SDK (v2 and v4, ASCII and binary).
#include <string>

#include "mesh/mesh.hpp"

namespace plisse {

/// Reads a tetrahedral mesh. Physical groups of dimension 2 become surface tags, of dimension 3
/// volume tags (unnamed groups are called "<dim>:<tag>"). Linear and second-order (10-node)
/// tetrahedra are read; other volume element types, a missing or unreadable file and a mesh
/// without tetrahedra are reported as InputError naming the file.
Mesh read_gmsh(const std::string& path);

/// Writes `mesh` with its tags as physical groups. `version` is 2.2 or 4.1.
void write_gmsh(const Mesh& mesh, const std::string& path, double version = 4.1, bool binary = false);

}  // namespace plisse
