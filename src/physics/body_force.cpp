#include "physics/body_force.hpp"

namespace plisse {

BodyForce::BodyForce(const Mesh& mesh, std::string name, const Vec3d& force_density, Ramp ramp)
    : nodal_volume_(mesh.n_nodes(), 0.0),
      name_(std::move(name)),
      force_density_(force_density),
      ramp_(ramp) {
  for (const auto& tet : mesh.tets) {
    Mat3d d;
    for (int a = 1; a < 4; ++a) d.col(a - 1) = mesh.nodes[tet[a]] - mesh.nodes[tet[0]];
    const double quarter = d.determinant() / 24.0;
    for (int v : tet) nodal_volume_[v] += quarter;
  }
}

void BodyForce::assemble(double t, std::span<const double>, std::span<double> residual,
                         TangentSink*) {
  const Vec3d f = ramp_.factor(t) * force_density_;
  for (size_t v = 0; v < nodal_volume_.size(); ++v)
    for (int i = 0; i < 3; ++i)
      residual[node_dof(static_cast<int>(v), i)] -= f[i] * nodal_volume_[v];
}

}  // namespace plisse
