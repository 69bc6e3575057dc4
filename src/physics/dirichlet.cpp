#include "physics/dirichlet.hpp"

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "mesh/topology.hpp"

namespace plisse {

int mirror_planes(const std::vector<BoundaryCondition>& conditions, const Mesh& mesh, double tol) {
  int planes = 0;
  for (const BoundaryCondition& bc : conditions) {
    if (bc.type != BoundaryType::symmetry) continue;
    const auto tag = mesh.surface_tags.find(bc.surface.name);
    if (tag == mesh.surface_tags.end() || tag->second.empty()) continue;
    const int axis = coordinate_plane_axis(mesh, tag->second, tol);
    if (axis < 0) continue;
    double extent = 0.0;
    for (int t : tag->second)
      for (int v : mesh.triangles[t])
        extent = std::max(extent, mesh.nodes[v].cwiseAbs().maxCoeff());
    const double level = mesh.nodes[mesh.triangles[tag->second.front()][0]][axis];
    if (std::abs(level) <= tol * std::max(extent, 1.0)) planes |= 1 << axis;
  }
  return planes;
}

int planes_reached(const Mesh& mesh, const std::vector<int>& triangles, int mirrors, double tol) {
  double extent = 0.0;
  for (int t : triangles)
    for (int v : mesh.triangles[t]) extent = std::max(extent, mesh.nodes[v].cwiseAbs().maxCoeff());
  int reached = 0;
  for (int k = 0; k < 3; ++k) {
    if (!(mirrors & (1 << k))) continue;
    for (int t : triangles)
      for (int v : mesh.triangles[t])
        if (std::abs(mesh.nodes[v][k]) <= tol * std::max(extent, 1.0)) reached |= 1 << k;
  }
  return reached;
}

Vec3d whole_body_force(Vec3d f, int cut) {
  for (int k = 0; k < 3; ++k) {
    if (!(cut & (1 << k))) continue;
    f *= 2.0;
    f[k] = 0.0;
  }
  return f;
}

int coordinate_plane_axis(const Mesh& mesh, const std::vector<int>& triangles, double tol) {
  int axis = -1;
  for (int t : triangles) {
    const auto& tri = mesh.triangles[t];
    const Vec3d n =
        (mesh.nodes[tri[1]] - mesh.nodes[tri[0]]).cross(mesh.nodes[tri[2]] - mesh.nodes[tri[0]]);
    const double norm = n.norm();
    if (norm == 0.0) continue;  // degenerate triangles are reported by the mesh check
    int a = 0;
    n.cwiseAbs().maxCoeff(&a);
    if (std::abs(n[a]) < (1.0 - tol) * norm) return -1;
    if (axis >= 0 && a != axis) return -1;
    axis = a;
  }
  if (axis < 0) return -1;
  // All triangles normal to `axis`: they must also lie in one plane.
  const double level = mesh.nodes[mesh.triangles[triangles.front()][0]][axis];
  double extent = 0.0;
  for (int t : triangles)
    for (int v : mesh.triangles[t]) extent = std::max(extent, mesh.nodes[v].cwiseAbs().maxCoeff());
  for (int t : triangles)
    for (int v : mesh.triangles[t])
      if (std::abs(mesh.nodes[v][axis] - level) > tol * std::max(extent, 1.0)) return -1;
  return axis;
}

std::vector<ConstrainedComponent> collect_constraints(
    const std::vector<BoundaryCondition>& conditions, const Mesh& mesh) {
  std::map<std::pair<int, int>, std::pair<ConstrainedComponent, const BoundaryCondition*>> by_dof;
  auto add = [&](const BoundaryCondition& bc, int node, int comp, double value, const Ramp& ramp) {
    const ConstrainedComponent cc{node, comp, value, ramp};
    auto [it, inserted] = by_dof.try_emplace({node, comp}, cc, &bc);
    if (inserted) return;
    const ConstrainedComponent& old = it->second.first;
    const bool same =
        (old.value == 0.0 && value == 0.0) || (old.value == value && old.ramp == ramp);
    if (!same) {
      const char* axis = "xyz";
      throw InputError(bc.place, "node " + std::to_string(node) + " already has its " +
                                     std::string(1, axis[comp]) +
                                     " displacement prescribed differently by the condition on '" +
                                     it->second.second->surface.name + "'");
    }
  };
  for (const BoundaryCondition& bc : conditions) {
    const auto tag = mesh.surface_tags.find(bc.surface.name);
    if (tag == mesh.surface_tags.end())
      throw InputError(bc.surface.place, "no surface tag '" + bc.surface.name + "' in the mesh");
    // The corners of the tagged triangles and, on a second-order mesh, their edge nodes.
    const std::set<int> nodes = triangle_nodes(mesh, tag->second);
    switch (bc.type) {
      case BoundaryType::fixed:
        for (int v : nodes)
          for (int k = 0; k < 3; ++k) add(bc, v, k, 0.0, bc.ramp);
        break;
      case BoundaryType::symmetry: {
        const int axis = coordinate_plane_axis(mesh, tag->second);
        if (axis < 0)
          throw InputError(bc.surface.place, "symmetry surface '" + bc.surface.name +
                                                 "' must be a plane x, y or z = const");
        for (int v : nodes) add(bc, v, axis, 0.0, bc.ramp);
        break;
      }
      case BoundaryType::displacement:
        for (int v : nodes)
          for (int k = 0; k < 3; ++k)
            if (bc.value[k]) add(bc, v, k, *bc.value[k], bc.ramp);
        break;
    }
  }
  std::vector<ConstrainedComponent> out;
  out.reserve(by_dof.size());
  for (const auto& [key, entry] : by_dof) out.push_back(entry.first);
  return out;
}

}  // namespace plisse
