#include "physics/body_force.hpp"

#include "element/taylor_hood_geometry.hpp"

namespace plisse {

std::vector<double> consistent_nodal_volumes(const Mesh& mesh) {
  std::vector<double> volume(mesh.n_nodes(), 0.0);
  if (mesh.order() == 1) {
    for (const auto& tet : mesh.tets) {
      Mat3d d;
      for (int a = 1; a < 4; ++a) d.col(a - 1) = mesh.nodes[tet[a]] - mesh.nodes[tet[0]];
      const double quarter = d.determinant() / 24.0;
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
      for (int a = 0; a < th::kNodes; ++a) volume[nodes[a]] += g.weight[q] * N[a];
    }
  }
  return volume;
}

BodyForce::BodyForce(const Mesh& mesh, std::string name, const Vec3d& force_density, Ramp ramp)
    : nodal_volume_(consistent_nodal_volumes(mesh)),
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
