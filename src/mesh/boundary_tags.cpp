#include "mesh/boundary_tags.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

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

void tag_boundary_edges(Mesh& mesh, const std::vector<EdgePlane>& planes,
                        const std::string& others) {
  // Undirected side -> number of triangles using it.
  std::map<std::pair<int, int>, int> uses;
  auto key = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  for (const auto& tri : mesh.triangles)
    for (std::size_t i = 0; i < 3; ++i) ++uses[key(tri[i], tri[(i + 1) % 3])];
  // The plane of each boundary side, so that each plane's edges are consecutive (one Gmsh curve
  // per tag when written).
  // in_plane[planes.size()]: the sides in none of them.
  std::vector<std::vector<std::array<int, 2>>> in_plane(planes.size() + 1);
  for (const auto& tri : mesh.triangles)
    for (std::size_t i = 0; i < 3; ++i) {
      const int a = tri[i], b = tri[(i + 1) % 3];
      if (uses.at(key(a, b)) != 1) continue;
      const Vec3d& xa = mesh.nodes[static_cast<std::size_t>(a)];
      const Vec3d& xb = mesh.nodes[static_cast<std::size_t>(b)];
      std::size_t p = 0;
      while (p < planes.size() &&
             !(xa[planes[p].axis] == planes[p].value && xb[planes[p].axis] == planes[p].value))
        ++p;
      in_plane[p].push_back({a, b});
    }
  mesh.edges.clear();
  mesh.edge_tags.clear();
  for (std::size_t p = 0; p <= planes.size(); ++p) {
    const std::vector<std::string> names =
        p < planes.size()
            ? planes[p].names
            : (others.empty() ? std::vector<std::string>{} : std::vector<std::string>{others});
    if (names.empty()) continue;
    for (const auto& name : names) mesh.edge_tags[name];
    for (const auto& edge : in_plane[p]) {
      const int index = static_cast<int>(mesh.edges.size());
      mesh.edges.push_back(edge);
      for (const auto& name : names) mesh.edge_tags[name].push_back(index);
    }
  }
}

}  // namespace plisse
