#include "physics/body_force.hpp"

#include "core/error.hpp"
#include "element/taylor_hood_geometry.hpp"

namespace plisse {

std::vector<double> consistent_nodal_volumes(const Mesh& mesh,
                                             const std::vector<double>& element_weight) {
  const std::size_t n_elements = mesh.is_shell() ? mesh.triangles.size() : mesh.tets.size();
  PLISSE_CHECK(element_weight.empty() || element_weight.size() == n_elements,
               element_weight.size() << " element weights for " << n_elements << " elements");
  const auto weight = [&](std::size_t t) {
    return element_weight.empty() ? 1.0 : element_weight[t];
  };
  std::vector<double> volume(mesh.n_nodes(), 0.0);
  if (mesh.is_shell()) {
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
      const auto& triangle = mesh.triangles[e];
      const Vec3d X0 = mesh.nodes[triangle[0]];
      const double area =
          0.5 * (mesh.nodes[triangle[1]] - X0).cross(mesh.nodes[triangle[2]] - X0).norm();
      // The element's thickness (shell.md, section 7): uniform, or its region's.
      const double third = weight(e) * area * mesh.triangle_thickness[e] / 3.0;
      for (int node : triangle) volume[node] += third;  // (loads.md, L6s)
    }
    return volume;
  }
  if (mesh.order() == 1) {
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      const auto& tet = mesh.tets[t];
      Mat3d d;
      for (int a = 1; a < 4; ++a) d.col(a - 1) = mesh.nodes[tet[a]] - mesh.nodes[tet[0]];
      const double quarter = weight(t) * d.determinant() / 24.0;
      for (int v : tet) volume[v] += quarter;  // (loads.md, L6)
    }
    return volume;
  }
  namespace th = taylor_hood;
  for (size_t t = 0; t < mesh.tets.size(); ++t) {
    std::array<int, th::kNodes> nodes;
    std::array<Vec3d, th::kNodes> X;
    for (int a = 0; a < th::kNodes; ++a) {
      nodes[a] = a < th::kCorners ? mesh.tets[t][a] : mesh.tet_edge_nodes[t][a - th::kCorners];
      X[a] = mesh.nodes[nodes[a]];
    }
    // ∫ N_a dV = Σ_q w_q det J_q N_a(L_q) / 6, exact (degree 2 + 3 <= 5)   (L10)
    const th::Geometry g = th::compute_geometry(X);
    for (int q = 0; q < th::kQuadPoints; ++q) {
      const auto N = th::shape_values(th::kQuadrature.points[q]);
      for (int a = 0; a < th::kNodes; ++a) volume[nodes[a]] += weight(t) * g.weight[q] * N[a];
    }
  }
  return volume;
}

BodyForce::BodyForce(const Mesh& mesh, std::string name, const Vec3d& force_density, Ramp ramp,
                     const std::vector<double>& element_scale)
    : nodal_volume_(consistent_nodal_volumes(mesh, element_scale)),
      name_(std::move(name)),
      force_density_(force_density),
      ramp_(ramp) {}

void BodyForce::assemble(double t, std::span<const double>, std::span<double> residual,
                         TangentSink*) {
  const Vec3d f = ramp_.factor(t) * force_density_;
  for (size_t v = 0; v < nodal_volume_.size(); ++v)
    for (int i = 0; i < 3; ++i)
      residual[node_dof(static_cast<int>(v), i)] -= f[i] * nodal_volume_[v];
}

}  // namespace plisse
