#include "physics/die_surface.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace plisse {

std::vector<std::array<int, 3>> boundary_faces(const Mesh& mesh) {
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  std::map<std::array<int, 3>, int> count;
  for (const auto& tet : mesh.tets)
    for (const auto& f : kFaces) {
      std::array<int, 3> key = {tet[f[0]], tet[f[1]], tet[f[2]]};
      std::sort(key.begin(), key.end());
      ++count[key];
    }
  std::vector<std::array<int, 3>> out;
  for (const auto& [face, n] : count)
    if (n == 1) out.push_back(face);
  return out;
}

std::map<int, double> tributary_areas(const Mesh& mesh,
                                      const std::vector<std::array<int, 3>>& triangles) {
  std::map<int, double> area;
  for (const auto& t : triangles) {
    const Vec3d& x0 = mesh.nodes[t[0]];
    // A_v = sum over the triangles at v of |T| / 3   (contact.md, D5)
    const double third = (mesh.nodes[t[1]] - x0).cross(mesh.nodes[t[2]] - x0).norm() / 6.0;
    for (int v : t) area[v] += third;
  }
  return area;
}

double mean_edge_length(const Mesh& mesh, const std::vector<std::array<int, 3>>& triangles) {
  FE_CHECK(!triangles.empty(), "a contact surface without triangles has no element size");
  double sum = 0.0;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) sum += (mesh.nodes[t[(k + 1) % 3]] - mesh.nodes[t[k]]).norm();
  return sum / (3.0 * static_cast<double>(triangles.size()));
}

}  // namespace plisse
