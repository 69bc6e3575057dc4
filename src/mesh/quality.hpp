#pragma once
/// Mesh admissibility and quality report.
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace plisse {

struct MeshReport {
  std::vector<std::string> errors;    ///< the mesh cannot be used (each names the element/tag)
  std::vector<std::string> warnings;  ///< usable but suspicious
  double min_volume = 0.0;            ///< smallest tetrahedron volume [mm^3]
  double max_aspect_ratio = 0.0;      ///< largest (longest edge / inradius) / (2 sqrt 6)
  bool ok() const { return errors.empty(); }
};

/// Checks: inverted or degenerate tetrahedra, unused nodes, missing or empty tags among
/// `required_tags`, boundary triangles not on the boundary of the tetrahedra, and non-manifold
/// boundary edges (shared by other than two boundary faces).
MeshReport check_mesh(const Mesh& mesh, const std::vector<std::string>& required_tags = {});

}  // namespace plisse
