#include "physics/pressure_load.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "physics/follower_pressure.hpp"
#include "physics/surface.hpp"

namespace plisse {
bool pressure_stiffness_is_symmetric(const Mesh& mesh,
                                     const std::vector<std::array<int, 3>>& triangles,
                                     const std::vector<ConstrainedComponent>& constraints) {
  std::map<std::pair<int, int>, int> edge_count;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++edge_count[{std::min(a, b), std::max(a, b)}];
    }
  std::set<std::pair<int, int>> constrained;
  for (const auto& c : constraints) constrained.insert({c.node, c.component});
  const auto fixed = [&](int v) {
    return constrained.count({v, 0}) && constrained.count({v, 1}) && constrained.count({v, 2});
  };
  for (const auto& [edge, count] : edge_count) {
    if (count != 1) continue;  // interior edge
    const auto [a, b] = edge;
    bool ok = fixed(a) && fixed(b);
    for (int k = 0; k < 3 && !ok; ++k)
      ok = constrained.count({a, k}) && constrained.count({b, k}) &&
           mesh.nodes[a][k] == mesh.nodes[b][k];
    if (!ok) return false;
  }
  return true;
}

PressureLoad::PressureLoad(const Mesh& mesh, std::string name, const std::string& surface,
                           double value, Ramp ramp,
                           const std::vector<ConstrainedComponent>& constraints)
    : mesh_(mesh),
      name_(std::move(name)),
      triangles_(outward_triangles(mesh, surface)),
      value_(value),
      ramp_(ramp),
      symmetric_(pressure_stiffness_is_symmetric(mesh, triangles_, constraints)) {}

void PressureLoad::assemble(double t, std::span<const double> x, std::span<double> residual,
                            TangentSink* tangent) {
  const double p = pressure(t);
  if (p == 0.0) return;
  // Residual (loads.md, L2) and load stiffness (L3) of each triangle: the shared kernel.
  std::array<int, 9> dofs;
  Eigen::Matrix<double, 9, 9, Eigen::RowMajor> k;
  for (const auto& tri : triangles_) {
    std::array<Vec3d, 3> xs;
    for (int a = 0; a < 3; ++a) {
      xs[a] = mesh_.nodes[tri[a]];
      for (int i = 0; i < 3; ++i) {
        dofs[3 * a + i] = node_dof(tri[a], i);
        xs[a][i] += x[dofs[3 * a + i]];
      }
    }
    add_follower_pressure_residual(p, xs, dofs, residual);
    if (!tangent) continue;
    follower_pressure_stiffness(p, xs, k);
    tangent->add(dofs, dofs, std::span<const double>(k.data(), 81));
  }
}

}  // namespace plisse
