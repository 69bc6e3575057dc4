#include "mesh/boundary_tags.hpp"

#include <cmath>

#include "core/error.hpp"

namespace plisse {

void tag_boundary(Mesh& mesh, const std::vector<std::vector<std::string>>& side_tags,
                  const std::function<int(const BoundaryFace&)>& side_of) {
  const auto faces = compute_boundary_faces(mesh);
  std::vector<std::vector<int>> by_side(side_tags.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const int side = side_of(faces[i]);
    PLISSE_CHECK(side >= 0 && static_cast<std::size_t>(side) < side_tags.size(),
                 "internal error: boundary face (" << faces[i].nodes[0] << ", " << faces[i].nodes[1]
                                                   << ", " << faces[i].nodes[2]
                                                   << ") of a generated mesh is on no known side");
    by_side[static_cast<std::size_t>(side)].push_back(static_cast<int>(i));
  }
  mesh.triangles.clear();
  mesh.surface_tags.clear();
  for (std::size_t side = 0; side < side_tags.size(); ++side) {
    const int first = static_cast<int>(mesh.triangles.size());
    for (int f : by_side[side]) mesh.triangles.push_back(faces[static_cast<std::size_t>(f)].nodes);
    const int last = static_cast<int>(mesh.triangles.size());
    for (const auto& name : side_tags[side]) {
      auto& indices = mesh.surface_tags[name];
      for (int i = first; i < last; ++i) indices.push_back(i);
    }
  }
}

void orient_generated_tets(Mesh& mesh, const std::string& generator) {
  for (int t = 0; t < mesh.n_tets(); ++t) {
    const auto& n = mesh.tets[static_cast<std::size_t>(t)];
    double longest = 0.0;
    for (const auto& e : kTetEdges)
      longest = std::max(longest,
                         (mesh.nodes[static_cast<std::size_t>(n[static_cast<std::size_t>(e[0])])] -
                          mesh.nodes[static_cast<std::size_t>(n[static_cast<std::size_t>(e[1])])])
                             .norm());
    const double volume = tet_signed_volume(mesh, t);
    PLISSE_CHECK(std::abs(volume) > 1e-12 * longest * longest * longest,
                 generator << ": generated tetrahedron " << t << " is degenerate (volume " << volume
                           << " mm^3); try a smaller element_size");
    if (volume < 0.0) flip_tet(mesh, t);
  }
}

}  // namespace plisse
