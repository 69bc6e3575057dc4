#include "physics/dirichlet.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "mesh/bounding_box.hpp"
#include "mesh/shell_surface.hpp"
#include "mesh/topology.hpp"

namespace plisse {

int mirror_planes(const std::vector<std::string>& symmetry_surfaces, const Mesh& mesh, double tol) {
  // The body's extent along each axis, and the levels of the symmetry planes of a solid.
  const BoundingBox box = bounding_box(mesh.nodes);
  const Vec3d &low = box.low, &high = box.high;
  const double size = std::max({low.cwiseAbs().maxCoeff(), high.cwiseAbs().maxCoeff(), 1.0});
  std::array<std::vector<double>, 3> levels;
  for (const std::string& surface : symmetry_surfaces) {
    const auto tag = mesh.surface_tags.find(surface);
    if (shell_edge_tag(mesh, surface) || tag == mesh.surface_tags.end() || tag->second.empty())
      continue;
    const int axis = coordinate_plane_axis(mesh, tag->second, tol);
    if (axis >= 0) levels[axis].push_back(mesh.nodes[mesh.triangles[tag->second.front()][0]][axis]);
  }
  const auto near = [&](double a, double b) { return std::abs(a - b) <= tol * size; };
  int planes = 0;
  for (const std::string& surface : symmetry_surfaces) {
    if (const std::vector<int>* edges = shell_edge_tag(mesh, surface)) {
      // The edge lies in its plane: the plane is a mirror plane when the edge reaches x_k = 0.
      const int axis = edges->empty() ? -1 : shell_edge_plane_axis(mesh, *edges, tol);
      if (axis >= 0) planes |= planes_reached(mesh, edge_nodes(mesh, *edges), 1 << axis, tol);
      continue;
    }
    const auto tag = mesh.surface_tags.find(surface);
    if (tag == mesh.surface_tags.end() || tag->second.empty()) continue;
    const int axis = coordinate_plane_axis(mesh, tag->second, tol);
    if (axis < 0) continue;
    double extent = 0.0;
    for (int t : tag->second)
      for (int v : mesh.triangles[t])
        extent = std::max(extent, mesh.nodes[v].cwiseAbs().maxCoeff());
    const double level = mesh.nodes[mesh.triangles[tag->second.front()][0]][axis];
    if (std::abs(level) > tol * std::max(extent, 1.0)) continue;
    // A mirror plane is a cut through the whole body, of which the model is the part on one
    // side: not a plane with the body on both sides of it.
    if (low[axis] < -tol * size && high[axis] > tol * size) continue;
    // Symmetry on the body's far face along the same axis too: the model is a slice between two
    // symmetry planes (plane strain, or a periodic structure), of a body with no end along that
    // axis; there is no whole body to sum over, and the plane at 0 mirrors nothing.
    const double far = high[axis] > tol * size ? high[axis] : low[axis];
    if (std::any_of(levels[axis].begin(), levels[axis].end(),
                    [&](double l) { return near(l, far) && !near(far, 0.0); }))
      continue;
    planes |= 1 << axis;
  }
  return planes;
}

int planes_reached(const Mesh& mesh, const std::vector<int>& triangles, int mirrors, double tol) {
  std::set<int> corners;
  for (int t : triangles) corners.insert(mesh.triangles[t].begin(), mesh.triangles[t].end());
  return planes_reached(mesh, corners, mirrors, tol);
}

int planes_reached(const Mesh& mesh, const std::set<int>& nodes, int mirrors, double tol) {
  double extent = 0.0;
  for (int v : nodes) extent = std::max(extent, mesh.nodes[v].cwiseAbs().maxCoeff());
  int reached = 0;
  for (int k = 0; k < 3; ++k) {
    if (!(mirrors & (1 << k))) continue;
    for (int v : nodes)
      if (std::abs(mesh.nodes[v][k]) <= tol * std::max(extent, 1.0)) reached |= 1 << k;
  }
  return reached;
}

int shell_edge_plane_axis(const Mesh& mesh, const std::vector<int>& edges, double tol) {
  const std::set<int> nodes = edge_nodes(mesh, edges);
  if (nodes.empty()) return -1;
  double extent = 0.0;
  for (int v : nodes) extent = std::max(extent, mesh.nodes[v].cwiseAbs().maxCoeff());
  // The unit normals of the triangles with a side on the edges.
  std::vector<Vec3d> normals;
  for (const EdgeSide& side : sides_on_edges(mesh, edges)) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(side.triangle)];
    const Vec3d& x0 = mesh.nodes[tri[0]];
    normals.push_back((mesh.nodes[tri[1]] - x0).cross(mesh.nodes[tri[2]] - x0).normalized());
  }
  for (int k = 0; k < 3; ++k) {
    const double level = mesh.nodes[*nodes.begin()][k];
    const bool in_plane = std::all_of(nodes.begin(), nodes.end(), [&](int v) {
      return std::abs(mesh.nodes[v][k] - level) <= tol * std::max(extent, 1.0);
    });
    // Across the plane, not along it: the facets beside a cut tilt from a right angle by about
    // h/R, while a shell lying in the plane (a sheet's edge is also in z = t/2) has |n_k| = 1.
    const bool across = std::all_of(normals.begin(), normals.end(),
                                    [&](const Vec3d& n) { return std::abs(n[k]) <= 0.5; });
    if (in_plane && across) return k;
  }
  return -1;
}

Vec3d whole_body_force(Vec3d f, int cut) {
  for (int k = 0; k < 3; ++k) {
    if (!(cut & (1 << k))) continue;
    f *= 2.0;
    f[k] = 0.0;
  }
  return f;
}

Vec3d whole_body_moment(Vec3d m, int cut) {
  for (int k = 0; k < 3; ++k) {
    if (!(cut & (1 << k))) continue;
    const double normal = 2.0 * m[k];
    m.setZero();
    m[k] = normal;
  }
  return m;
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

void ConstraintSet::begin(const InputPlace& place, const std::string& surface) {
  place_ = place;
  surface_ = surface;
}

void ConstraintSet::add(int node, int component, double value, const Ramp& ramp) {
  const ConstrainedComponent cc{node, component, value, ramp};
  auto [it, inserted] = by_dof_.try_emplace({node, component}, Held{cc, surface_});
  if (inserted) return;
  const ConstrainedComponent& old = it->second.component;
  const bool same = (old.value == 0.0 && value == 0.0) || (old.value == value && old.ramp == ramp);
  if (same) return;
  const char* axis = "xyz";
  throw InputError(place_, "node " + std::to_string(node) + " already has its " +
                               std::string(1, axis[component]) +
                               " displacement prescribed differently by the condition on '" +
                               it->second.surface + "'");
}

std::vector<ConstrainedComponent> ConstraintSet::components() const {
  std::vector<ConstrainedComponent> out;
  out.reserve(by_dof_.size());
  for (const auto& [key, held] : by_dof_) out.push_back(held.component);
  return out;
}

const std::vector<int>* shell_edge_tag(const Mesh& mesh, const std::string& name) {
  if (!mesh.is_shell()) return nullptr;
  const auto tag = mesh.edge_tags.find(name);
  return tag == mesh.edge_tags.end() ? nullptr : &tag->second;
}

std::set<int> condition_nodes(const Mesh& mesh, const SurfaceRef& surface) {
  if (const std::vector<int>* edges = shell_edge_tag(mesh, surface.name))
    return edge_nodes(mesh, *edges);
  const auto tag = mesh.surface_tags.find(surface.name);
  if (tag == mesh.surface_tags.end())
    throw InputError(surface.place,
                     std::string(mesh.is_shell() ? "no edge or surface" : "no surface") + " tag '" +
                         surface.name + "' in the mesh");
  return triangle_nodes(mesh, tag->second);
}

void fix_surface(const Mesh& mesh, const SurfaceRef& surface, ConstraintSet& set) {
  for (int v : condition_nodes(mesh, surface))
    for (int k = 0; k < 3; ++k) set.add(v, k, 0.0, Ramp{});
}

void hold_in_plane(const Mesh& mesh, const SurfaceRef& surface, ConstraintSet& set) {
  const std::set<int> nodes = condition_nodes(mesh, surface);
  if (const std::vector<int>* edges = shell_edge_tag(mesh, surface.name)) {
    const int axis = shell_edge_plane_axis(mesh, *edges);
    if (axis < 0)
      throw InputError(surface.place, "symmetry edge '" + surface.name +
                                          "' must lie in a plane x, y or z = const that meets "
                                          "the shell at a right angle");
    for (int v : nodes) set.add(v, axis, 0.0, Ramp{});
    return;
  }
  const int axis = coordinate_plane_axis(mesh, mesh.surface_tags.at(surface.name));
  if (axis < 0)
    throw InputError(surface.place,
                     "symmetry surface '" + surface.name + "' must be a plane x, y or z = const");
  for (int v : nodes) set.add(v, axis, 0.0, Ramp{});
}

void prescribe_surface(const Mesh& mesh, const SurfaceRef& surface,
                       const std::array<std::optional<double>, 3>& value, const Ramp& ramp,
                       ConstraintSet& set) {
  for (int v : condition_nodes(mesh, surface))
    for (int k = 0; k < 3; ++k)
      if (value[k]) set.add(v, k, *value[k], ramp);
}

Planarity planarity(const Mesh& mesh, const std::vector<int>& triangles) {
  std::set<int> nodes;
  double edge_sum = 0.0;
  for (int t : triangles) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      nodes.insert(tri[k]);
      edge_sum += (mesh.nodes[tri[(k + 1) % 3]] - mesh.nodes[tri[k]]).norm();
    }
  }
  const double mean_edge = edge_sum / (3.0 * static_cast<double>(triangles.size()));
  Vec3d centroid = Vec3d::Zero();
  for (int v : nodes) centroid += mesh.nodes[v];
  centroid /= static_cast<double>(nodes.size());
  Mat3d covariance = Mat3d::Zero();
  for (int v : nodes) {
    const Vec3d d = mesh.nodes[v] - centroid;
    covariance += d * d.transpose();
  }
  // The best-fit plane's normal is the eigenvector of the smallest eigenvalue (ascending order).
  const Eigen::SelfAdjointEigenSolver<Mat3d> eigen(covariance);
  const Vec3d normal = eigen.eigenvectors().col(0);
  double deviation = 0.0;
  for (int v : nodes)
    deviation = std::max(deviation, std::abs(normal.dot(mesh.nodes[v] - centroid)));
  return {deviation, kPlanarityTolerance * mean_edge};
}

}  // namespace plisse
