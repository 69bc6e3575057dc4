#include "physics/cavity_volume.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "physics/model_term.hpp"
#include "physics/quadratic_triangle.hpp"

namespace plisse {

Vec3d deformed_position(const Mesh& mesh, std::span<const double> state, int node) {
  return mesh.nodes[node] +
         Vec3d(state[node_dof(node, 0)], state[node_dof(node, 1)], state[node_dof(node, 2)]);
}

double quadratic_cone_volume(const std::array<Vec3d, 6>& xs) {
  double three_volume = 0.0;
  for (const auto& q : quadratic_triangle::rule_points()) {
    const auto f = quadratic_triangle::face_frame(xs, q);
    three_volume += q.weight * f.x.dot(f.x_xi.cross(f.x_eta));  // (cavities.md, C12)
  }
  return three_volume / 3.0;
}

std::array<Vec3d, 6> quadratic_cone_volume_gradient(const std::array<Vec3d, 6>& xs) {
  std::array<Vec3d, 6> g;
  g.fill(Vec3d::Zero());
  for (const auto& q : quadratic_triangle::rule_points()) {
    const auto f = quadratic_triangle::face_frame(xs, q);
    const Vec3d c = f.x_xi.cross(f.x_eta), c_xi = f.x_eta.cross(f.x), c_eta = f.x.cross(f.x_xi);
    for (int a = 0; a < 6; ++a)  // (cavities.md, C13)
      g[a] += (q.weight / 3.0) * (q.N[a] * c + q.dN_dxi[a] * c_xi + q.dN_deta[a] * c_eta);
  }
  return g;
}

double cavity_volume(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                     std::span<const double> state) {
  double six_volume = 0.0;
  for (const SurfaceFace& f : faces) {
    if (f.n_nodes == 3) {
      const Vec3d x0 = deformed_position(mesh, state, f.nodes[0]);
      const Vec3d x1 = deformed_position(mesh, state, f.nodes[1]);
      const Vec3d x2 = deformed_position(mesh, state, f.nodes[2]);
      six_volume -= x0.dot(x1.cross(x2));  // (cavities.md, C1)
      continue;
    }
    std::array<Vec3d, 6> xs;
    for (int a = 0; a < 6; ++a) xs[a] = deformed_position(mesh, state, f.nodes[a]);
    six_volume -= 6.0 * quadratic_cone_volume(xs);  // (C12)
  }
  return six_volume / 6.0;
}

std::vector<OpenEdge> open_edges(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                                 double relative_tolerance) {
  std::vector<OpenEdge> open;
  if (faces.empty()) return open;
  // Per corner edge (sorted pair): the edge as the first face runs it, counting its faces.
  std::map<std::array<int, 2>, OpenEdge> edges;
  Vec3d low = Vec3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const auto& f : faces) {
    for (int k = 0; k < 3; ++k) {
      const int a = f.nodes[k], b = f.nodes[(k + 1) % 3];
      const auto [it, first] =
          edges.try_emplace({std::min(a, b), std::max(a, b)}, OpenEdge{a, b, f.edge_node(k), 1});
      if (!first) ++it->second.faces;
    }
    for (int v : f.node_list()) {
      low = low.cwiseMin(mesh.nodes[v]);
      high = high.cwiseMax(mesh.nodes[v]);
    }
  }
  const double tol = relative_tolerance * (high - low).maxCoeff();
  for (auto& [key, edge] : edges) {
    if (edge.faces == 2) continue;
    const auto on = [&](int v, int k) { return v < 0 || std::abs(mesh.nodes[v][k]) <= tol; };
    for (int k = 0; k < 3 && edge.faces == 1 && edge.plane < 0; ++k)
      if (on(edge.a, k) && on(edge.b, k) && on(edge.middle, k)) edge.plane = k;
    open.push_back(edge);
  }
  return open;
}

namespace {

struct EdgeScan {
  std::optional<std::array<int, 2>> open_edge;  ///< the first edge that breaks the rule
  int planes = 0;                               ///< bit k: a boundary edge lies in x_k = 0
};

/// The closure rule of first_open_edge, edge by edge, with the planes the boundary lies in.
EdgeScan scan_edges(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                    double relative_tolerance) {
  EdgeScan scan;
  for (const OpenEdge& edge : open_edges(mesh, faces, relative_tolerance)) {
    if (edge.plane < 0) {
      scan.open_edge = std::array<int, 2>{std::min(edge.a, edge.b), std::max(edge.a, edge.b)};
      return scan;
    }
    scan.planes |= 1 << edge.plane;
  }
  return scan;
}

}  // namespace

std::optional<std::array<int, 2>> first_open_edge(const Mesh& mesh,
                                                  const std::vector<SurfaceFace>& faces,
                                                  double relative_tolerance) {
  return scan_edges(mesh, faces, relative_tolerance).open_edge;
}

std::optional<int> closing_planes(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                                  double relative_tolerance) {
  const EdgeScan scan = scan_edges(mesh, faces, relative_tolerance);
  if (scan.open_edge) return std::nullopt;
  return scan.planes;
}

int full_body_factor(int planes) {
  return (planes & 1 ? 2 : 1) * (planes & 2 ? 2 : 1) * (planes & 4 ? 2 : 1);
}

}  // namespace plisse
