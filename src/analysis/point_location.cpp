#include "analysis/point_location.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/surface_columns.hpp"
#include "core/error.hpp"
#include "element/taylor_hood_geometry.hpp"
#include "mesh/topology.hpp"

namespace plisse {
namespace {

/// The element's nodes: 4 corners, then on a second-order mesh its 6 edge nodes; a shell's
/// triangle, its 3 corners.
std::vector<int> element_nodes(const Mesh& mesh, int e) {
  if (mesh.is_shell()) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(e)];
    return {tri.begin(), tri.end()};
  }
  const auto& t = mesh.tets[static_cast<std::size_t>(e)];
  std::vector<int> nodes(t.begin(), t.end());
  if (mesh.order() == 2) {
    const auto& edges = mesh.tet_edge_nodes[static_cast<std::size_t>(e)];
    nodes.insert(nodes.end(), edges.begin(), edges.end());
  }
  return nodes;
}

/// The shape functions of element nodes at L (4 linear or 10 quadratic; a shell's triangle, 3
/// linear).
std::vector<double> shape_values(const Mesh& mesh, const std::array<double, 4>& L) {
  if (mesh.is_shell()) return {L[0], L[1], L[2]};
  if (mesh.order() == 1) return {L.begin(), L.end()};
  const auto N = taylor_hood::shape_values(L);
  return {N.begin(), N.end()};
}

/// X(L) under the element's map.
Vec3d map_point(const Mesh& mesh, int e, const std::array<double, 4>& L) {
  const std::vector<int> nodes = element_nodes(mesh, e);
  const std::vector<double> N = shape_values(mesh, L);
  Vec3d x = Vec3d::Zero();
  for (std::size_t a = 0; a < nodes.size(); ++a)
    x += N[a] * mesh.nodes[static_cast<std::size_t>(nodes[a])];
  return x;
}

/// Barycentric coordinates of `point` in the straight tetrahedron of element e's corners.
std::array<double, 4> linear_coordinates(const Mesh& mesh, int e, const Vec3d& point) {
  const auto& t = mesh.tets[static_cast<std::size_t>(e)];
  const Vec3d& x0 = mesh.nodes[static_cast<std::size_t>(t[0])];
  Mat3d A;
  for (int a = 1; a < 4; ++a) A.col(a - 1) = mesh.nodes[static_cast<std::size_t>(t[a])] - x0;
  const Vec3d xi = A.partialPivLu().solve(point - x0);
  return {1.0 - xi.sum(), xi[0], xi[1], xi[2]};
}

/// Newton's method on X(ξ) = point under the 10-node map of element e, from `L` (the linear
/// coordinates). Keeps the start when Newton fails to settle (a point far outside the element).
std::array<double, 4> curved_coordinates(const Mesh& mesh, int e, const Vec3d& point,
                                         std::array<double, 4> L) {
  const std::vector<int> nodes = element_nodes(mesh, e);
  Eigen::Matrix<double, 3, taylor_hood::kNodes> X;
  for (int a = 0; a < taylor_hood::kNodes; ++a)
    X.col(a) = mesh.nodes[static_cast<std::size_t>(nodes[static_cast<std::size_t>(a)])];
  const double size = (X.col(1) - X.col(0)).norm() + (X.col(2) - X.col(0)).norm();
  const std::array<double, 4> start = L;
  for (int iteration = 0; iteration < 30; ++iteration) {
    const auto N = taylor_hood::shape_values(L);
    Vec3d r = -point;
    for (int a = 0; a < taylor_hood::kNodes; ++a) r += N[static_cast<std::size_t>(a)] * X.col(a);
    if (r.norm() <= 1e-14 * size) return L;
    const Mat3d J = X * taylor_hood::shape_derivatives(L).transpose();  // dX/dξ
    const Vec3d step = J.partialPivLu().solve(r);
    if (!step.allFinite()) return start;
    for (int k = 0; k < 3; ++k) L[static_cast<std::size_t>(k + 1)] -= step[k];
    L[0] = 1.0 - L[1] - L[2] - L[3];
    if (step.norm() <= 1e-15) return L;
  }
  return start;
}

double smallest(const std::array<double, 4>& L) { return *std::min_element(L.begin(), L.end()); }

/// The nearest point of a shell's mid-surface (its flat triangles) to `point`: the first triangle
/// at the smallest distance, with the point's barycentric coordinates in it.
MeshPoint locate_on_shell(const Mesh& mesh, const Vec3d& point) {
  MeshPoint best;
  best.distance = std::numeric_limits<double>::infinity();
  double size = 0.0;
  for (int e = 0; e < static_cast<int>(mesh.triangles.size()); ++e) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(e)];
    const auto x = [&](int k) { return mesh.nodes[static_cast<std::size_t>(tri[k])]; };
    const Vec3d w = closest_point_weights(point, x(0), x(1), x(2));
    const Vec3d at = w[0] * x(0) + w[1] * x(1) + w[2] * x(2);
    if (!((point - at).norm() < best.distance)) continue;
    best.element = e;
    best.L = {w[0], w[1], w[2], 0.0};
    best.position = at;
    best.distance = (point - at).norm();
    size = std::max({(x(1) - x(0)).norm(), (x(2) - x(1)).norm(), (x(0) - x(2)).norm()});
  }
  best.inside = best.distance <= 1e-10 * size;  // on the mid-surface, to rounding
  return best;
}

}  // namespace

MeshPoint locate_point(const Mesh& mesh, const Vec3d& point) {
  if (mesh.is_shell()) {
    PLISSE_CHECK(!mesh.triangles.empty(), "locate_point: the shell has no triangles");
    return locate_on_shell(mesh, point);
  }
  PLISSE_CHECK(mesh.n_tets() > 0, "locate_point: the mesh has no tetrahedra");
  // A point on a face shared by two elements is inside both, to rounding: accept a coordinate
  // this far below zero as inside.
  constexpr double kInside = -1e-10;
  MeshPoint best;
  double best_score = -std::numeric_limits<double>::infinity();
  for (int e = 0; e < mesh.n_tets(); ++e) {
    std::array<double, 4> L = linear_coordinates(mesh, e, point);
    // A curved element may hold points outside its straight chord tetrahedron (by the sagitta
    // of its faces, a small fraction of the element): try its own map when the point is near.
    if (mesh.order() == 2 && smallest(L) > -0.25) L = curved_coordinates(mesh, e, point, L);
    if (const double score = smallest(L); score > best_score) {
      best_score = score;
      best.element = e;
      best.L = L;
    }
  }
  if (best_score >= kInside) {
    best.inside = true;
    best.position = map_point(mesh, best.element, best.L);
    best.distance = (best.position - point).norm();
    return best;
  }
  // Outside every element: the nearest point of the boundary faces.
  double nearest = std::numeric_limits<double>::infinity();
  for (const BoundaryFace& f : compute_boundary_faces(mesh)) {
    const auto x = [&](int k) { return mesh.nodes[static_cast<std::size_t>(f.nodes[k])]; };
    const Vec3d w = closest_point_weights(point, x(0), x(1), x(2));
    const double d = (point - (w[0] * x(0) + w[1] * x(1) + w[2] * x(2))).norm();
    if (!(d < nearest)) continue;
    nearest = d;
    best.element = f.tet;
    best.L = {0.0, 0.0, 0.0, 0.0};
    const auto& t = mesh.tets[static_cast<std::size_t>(f.tet)];
    for (int k = 0; k < 3; ++k)
      best.L[static_cast<std::size_t>(std::find(t.begin(), t.end(), f.nodes[k]) - t.begin())] =
          w[k];
  }
  best.inside = false;
  best.position = map_point(mesh, best.element, best.L);
  best.distance = (best.position - point).norm();
  return best;
}

std::vector<std::pair<int, double>> interpolation_weights(const Mesh& mesh, const MeshPoint& p) {
  const int n_elements = mesh.is_shell() ? static_cast<int>(mesh.triangles.size()) : mesh.n_tets();
  PLISSE_CHECK(p.element >= 0 && p.element < n_elements,
               "interpolation_weights: element " << p.element << " is not in the mesh");
  const std::vector<int> nodes = element_nodes(mesh, p.element);
  const std::vector<double> N = shape_values(mesh, p.L);
  std::vector<std::pair<int, double>> weights;
  for (std::size_t a = 0; a < nodes.size(); ++a) weights.emplace_back(nodes[a], N[a]);
  return weights;
}

}  // namespace plisse
