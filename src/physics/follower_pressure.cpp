#include "physics/follower_pressure.hpp"

#include "physics/quadratic_triangle.hpp"

namespace plisse {

Vec3d add_follower_pressure_residual(double p, const std::array<Vec3d, 3>& xs,
                                     std::span<const int> dofs, std::span<double> residual) {
  const Vec3d c = (xs[1] - xs[0]).cross(xs[2] - xs[0]);
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < 3; ++i) residual[dofs[3 * a + i]] += p * c[i] / 6.0;  // (loads.md, L2)
  return c;
}

void follower_pressure_stiffness(double p, const std::array<Vec3d, 3>& xs,
                                 FollowerPressureBlock k) {
  const std::array<Mat3d, 3> dc = {cross_matrix(xs[2] - xs[1]), cross_matrix(xs[0] - xs[2]),
                                   cross_matrix(xs[1] - xs[0])};  // (loads.md, L3)
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) k.block<3, 3>(3 * a, 3 * b) = (p / 6.0) * dc[b];
}

std::array<Vec3d, 6> add_follower_pressure_residual(double p, const std::array<Vec3d, 6>& xs,
                                                    std::span<const int> dofs,
                                                    std::span<double> residual) {
  std::array<Vec3d, 6> g;
  g.fill(Vec3d::Zero());
  for (const auto& q : quadratic_triangle::rule_points()) {
    const auto f = quadratic_triangle::face_frame(xs, q);
    const Vec3d c = q.weight * f.x_xi.cross(f.x_eta);
    for (int a = 0; a < 6; ++a) g[a] += q.N[a] * c;  // (loads.md, L8)
  }
  for (int a = 0; a < 6; ++a)
    for (int i = 0; i < 3; ++i) residual[dofs[3 * a + i]] += p * g[a][i];
  return g;
}

void follower_pressure_stiffness(double p, const std::array<Vec3d, 6>& xs,
                                 FollowerPressureBlock6 k) {
  k.setZero();
  for (const auto& q : quadratic_triangle::rule_points()) {
    const auto f = quadratic_triangle::face_frame(xs, q);
    const Mat3d xi = cross_matrix(f.x_xi), eta = cross_matrix(f.x_eta);
    for (int b = 0; b < 6; ++b) {
      // d(x_ξ × x_η)/dx_b = N_b,η [x_ξ]x - N_b,ξ [x_η]x   (loads.md, L9)
      const Mat3d dc = (p * q.weight) * (q.dN_deta[b] * xi - q.dN_dxi[b] * eta);
      for (int a = 0; a < 6; ++a) k.block<3, 3>(3 * a, 3 * b) += q.N[a] * dc;
    }
  }
}

}  // namespace plisse
