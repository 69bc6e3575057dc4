#include "physics/cavity_volume.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "physics/model_term.hpp"

namespace plisse {

Vec3d deformed_position(const Mesh& mesh, std::span<const double> state, int node) {
  return mesh.nodes[node] +
         Vec3d(state[node_dof(node, 0)], state[node_dof(node, 1)], state[node_dof(node, 2)]);
}

double cavity_volume(const Mesh& mesh, const std::vector<std::array<int, 3>>& triangles,
                     std::span<const double> state) {
  double six_volume = 0.0;
  for (const auto& t : triangles) {
    const Vec3d x0 = deformed_position(mesh, state, t[0]);
    const Vec3d x1 = deformed_position(mesh, state, t[1]);
    const Vec3d x2 = deformed_position(mesh, state, t[2]);
    six_volume -= x0.dot(x1.cross(x2));  // (cavities.md, C1)
  }
  return six_volume / 6.0;
}

std::optional<std::array<int, 2>> first_open_edge(const Mesh& mesh,
                                                  const std::vector<std::array<int, 3>>& triangles,
                                                  double relative_tolerance) {
  std::map<std::array<int, 2>, int> edge_count;
  Vec3d low = Vec3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++edge_count[{std::min(a, b), std::max(a, b)}];
      low = low.cwiseMin(mesh.nodes[a]);
      high = high.cwiseMax(mesh.nodes[a]);
    }
  if (triangles.empty()) return std::nullopt;
  const double tol = relative_tolerance * (high - low).maxCoeff();
  for (const auto& [edge, count] : edge_count) {
    if (count == 2) continue;
    bool on_plane = false;
    for (int k = 0; k < 3 && count == 1 && !on_plane; ++k)
      on_plane = std::abs(mesh.nodes[edge[0]][k]) <= tol && std::abs(mesh.nodes[edge[1]][k]) <= tol;
    if (!on_plane) return edge;
  }
  return std::nullopt;
}

}  // namespace plisse
