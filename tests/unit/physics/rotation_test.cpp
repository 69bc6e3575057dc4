// The rotated vector R(θ) d and its derivatives (docs/theory/caps.md, G1-G3): the value against
// Eigen's angle-axis rotation, the first and second derivatives against central differences,
// through θ = 0 and up to angles near 2π.
#include "physics/rotation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/error.hpp"

namespace plisse {
namespace {

Vec3d rotated(const Vec3d& theta, const Vec3d& d) {
  const double angle = theta.norm();
  if (angle == 0.0) return d;
  return Eigen::AngleAxisd(angle, theta / angle) * d;
}

const Vec3d kD(0.7, -1.3, 0.4);

class Rotation : public ::testing::TestWithParam<Vec3d> {};

TEST_P(Rotation, ValueIsTheAngleAxisRotation) {
  const Vec3d theta = GetParam();
  EXPECT_LT((rotate(theta, kD).value - rotated(theta, kD)).norm(), 1e-14);
}

TEST_P(Rotation, JacobianAndHessianAreTheDerivativesOfTheValue) {
  const Vec3d theta = GetParam();
  const RotatedVector w = rotate(theta, kD);
  const double h = 1e-5;
  for (int j = 0; j < 3; ++j) {
    const Vec3d e = h * Vec3d::Unit(j);
    const RotatedVector p = rotate(theta + e, kD), m = rotate(theta - e, kD);
    // Central differences: error O(h^2) ~ 1e-10 here.
    const Vec3d column = (p.value - m.value) / (2 * h);
    EXPECT_LT((column - w.jacobian.col(j)).norm(), 1e-9) << "θ = " << theta.transpose();
    for (int i = 0; i < 3; ++i) {
      const Vec3d row_derivative = (p.jacobian.row(i) - m.jacobian.row(i)).transpose() / (2 * h);
      EXPECT_LT((row_derivative - w.hessian[i].col(j)).norm(), 1e-8)
          << "component " << i << ", θ = " << theta.transpose();
    }
  }
  for (int i = 0; i < 3; ++i) {
    EXPECT_LT((w.hessian[i] - w.hessian[i].transpose()).norm(), 1e-15);
  }
}

INSTANTIATE_TEST_SUITE_P(Angles, Rotation,
                         ::testing::Values(Vec3d(0, 0, 0), Vec3d(1e-9, -2e-9, 0.5e-9),
                                           Vec3d(0.3, 0, 0), Vec3d(0.5, -1.0, 1.5),
                                           Vec3d(-2.0, 1.0, 2.2), Vec3d(0, 0, 6.0)));

TEST(Rotation, AngleBeyondTwoPiIsRefused) { EXPECT_THROW(rotate(Vec3d(0, 7.0, 0), kD), Error); }

}  // namespace
}  // namespace plisse
