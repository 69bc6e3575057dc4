#include "physics/die_surface.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "physics/quadratic_triangle.hpp"

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

namespace {

/// A third of the area of the linear face `f`: the share of each of its corners (D5).
double third_of_linear_face(const Mesh& mesh, const SurfaceFace& f) {
  const Vec3d& x0 = mesh.nodes[f.nodes[0]];
  return (mesh.nodes[f.nodes[1]] - x0).cross(mesh.nodes[f.nodes[2]] - x0).norm() / 6.0;
}

/// ∫ N_a^power dA over the curved 6-node face `f` by the degree-4 rule, a = 0..5.
std::array<double, 6> shape_integrals(const Mesh& mesh, const SurfaceFace& f, int power) {
  std::array<Vec3d, 6> xs;
  for (int a = 0; a < 6; ++a) xs[a] = mesh.nodes[f.nodes[a]];
  std::array<double, 6> w{};
  for (const auto& q : quadratic_triangle::rule_points()) {
    const auto frame = quadratic_triangle::face_frame(xs, q);
    const double da = q.weight * frame.x_xi.cross(frame.x_eta).norm();
    for (int a = 0; a < 6; ++a) w[a] += (power == 1 ? q.N[a] : q.N[a] * q.N[a]) * da;
  }
  return w;
}

}  // namespace

std::map<int, double> tributary_areas(const Mesh& mesh, const std::vector<SurfaceFace>& faces) {
  std::map<int, double> area;
  for (const SurfaceFace& f : faces) {
    if (f.n_nodes == 3) {
      // A_v = sum over the triangles at v of |T| / 3   (contact.md, D5)
      const double third = third_of_linear_face(mesh, f);
      for (int v : f.corners()) area[v] += third;
      continue;
    }
    const std::array<double, 6> w = shape_integrals(mesh, f, 1);  // ∫ N_a dA   (D16)
    const double corner_share = (w[0] + w[1] + w[2]) / 3.0;
    for (int a = 3; a < 6; ++a) area[f.nodes[a]] += w[a] + corner_share;
  }
  return area;
}

std::map<int, double> tie_areas(const Mesh& mesh, const std::vector<SurfaceFace>& faces) {
  std::map<int, double> weight;
  for (const SurfaceFace& f : faces) {
    if (f.n_nodes == 3) {
      const double third = third_of_linear_face(mesh, f);
      for (int v : f.corners()) weight[v] += third;
      continue;
    }
    // W_a = |T| m_a / sum_b m_b with m_a = ∫ N_a^2 dA and |T| = sum_a ∫ N_a dA   (D17)
    const std::array<double, 6> m = shape_integrals(mesh, f, 2), w = shape_integrals(mesh, f, 1);
    double area = 0.0, mass = 0.0;
    for (int a = 0; a < 6; ++a) {
      area += w[a];
      mass += m[a];
    }
    for (int a = 0; a < 6; ++a) weight[f.nodes[a]] += area * m[a] / mass;
  }
  return weight;
}

double mean_edge_length(const Mesh& mesh, const std::vector<std::array<int, 3>>& triangles) {
  PLISSE_CHECK(!triangles.empty(), "a contact surface without triangles has no element size");
  double sum = 0.0;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) sum += (mesh.nodes[t[(k + 1) % 3]] - mesh.nodes[t[k]]).norm();
  return sum / (3.0 * static_cast<double>(triangles.size()));
}

}  // namespace plisse
