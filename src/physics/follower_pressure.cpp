#include "physics/follower_pressure.hpp"

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

}  // namespace plisse
