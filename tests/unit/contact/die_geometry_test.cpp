// Die geometry: the gap of each shape against its closed form, the motion of the die, and the
// normal and its derivative as derivatives of the gap (central differences).
#include "physics/die_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/error.hpp"

namespace plisse {
namespace {

DieGeometry plane() {
  return DieGeometry(DieShape::plane, Vec3d(0, 1, 0), Vec3d(0, -1, 0), Vec3d::UnitZ(), 0.0,
                     Vec3d(0, -4, 0), Ramp{1.0, 3.0});
}
DieGeometry sphere() {
  return DieGeometry(DieShape::sphere, Vec3d(1, 2, 3), Vec3d::UnitY(), Vec3d::UnitZ(), 2.0,
                     Vec3d(0.5, 0, -1), Ramp{0.0, 1.0});
}
DieGeometry cylinder() {
  return DieGeometry(DieShape::cylinder, Vec3d(0, 0, 1), Vec3d::UnitY(),
                     Vec3d(1, 1, 0).normalized(), 1.5, Vec3d(0, 0, 2), Ramp{0.0, 2.0});
}

TEST(DieGeometry, PlaneGapIsSignedDistanceAlongTheNormalOfTheMovedPlane) {
  const DieGeometry die = plane();
  // Before the ramp starts the plane is y = 1, body below it (normal -y).
  EXPECT_DOUBLE_EQ(die.gap(Vec3d(5, -2, 7), 0.5).g, 3.0);
  // Half-way up the ramp it has moved 2 mm down: y = -1.
  const DieGap g = die.gap(Vec3d(5, -2, 7), 2.0);
  EXPECT_DOUBLE_EQ(g.g, 1.0);
  EXPECT_TRUE(g.n.isApprox(Vec3d(0, -1, 0)));
  EXPECT_EQ(g.H.norm(), 0.0);
  EXPECT_NEAR(die.gap(Vec3d(0, 0, 0), 10.0).g, -3.0, 1e-15);  // penetrates after y = -3
}

TEST(DieGeometry, SphereGapIsDistanceToCentreMinusRadius) {
  const DieGeometry die = sphere();
  // At t = 0.5 the centre is (1.25, 2, 2.5).
  const Vec3d c(1.25, 2, 2.5);
  const Vec3d x = c + Vec3d(3, 0, 4);  // distance 5
  const DieGap g = die.gap(x, 0.5);
  EXPECT_NEAR(g.g, 3.0, 1e-14);
  EXPECT_TRUE(g.n.isApprox(Vec3d(0.6, 0, 0.8), 1e-14));
  EXPECT_NEAR(die.gap(c + Vec3d(0, -1, 0), 0.5).g, -1.0, 1e-14);  // inside: penetration 1
  EXPECT_THROW(die.gap(c, 0.5), Error);
}

TEST(DieGeometry, CylinderGapIgnoresTheAxialPosition) {
  const DieGeometry die = cylinder();
  // At t = 1 the axis passes through (0, 0, 2) along (1, 1, 0)/sqrt 2.
  const Vec3d on_axis(3, 3, 2);
  const Vec3d radial = Vec3d(1, -1, 0).normalized() * 4.0;
  const DieGap g = die.gap(on_axis + radial, 1.0);
  EXPECT_NEAR(g.g, 2.5, 1e-14);
  EXPECT_TRUE(g.n.isApprox(radial.normalized(), 1e-14));
  EXPECT_NEAR(die.gap(on_axis + radial + Vec3d(7, 7, 0), 1.0).g, 2.5, 1e-13);
  EXPECT_NEAR(die.gap(Vec3d(0, 0, 2.5), 1.0).g, -1.0, 1e-14);
}

TEST(DieGeometry, NormalAndCurvatureAreDerivativesOfTheGap) {
  const double h = 1e-5;
  for (const DieGeometry& die : {plane(), sphere(), cylinder()}) {
    const Vec3d x(2.1, -0.7, 4.3);
    const double t = 0.8;
    const DieGap g = die.gap(x, t);
    EXPECT_NEAR(g.n.norm(), 1.0, 1e-14);
    EXPECT_LT((g.H - g.H.transpose()).norm(), 1e-15);
    for (int j = 0; j < 3; ++j) {
      Vec3d xp = x, xm = x;
      xp[j] += h;
      xm[j] -= h;
      const DieGap gp = die.gap(xp, t), gm = die.gap(xm, t);
      // Central differences: error ~ h^2 |third derivative| (curvature radii >= 1.5 mm here).
      EXPECT_NEAR((gp.g - gm.g) / (2 * h), g.n[j], 1e-9);
      EXPECT_LT(((gp.n - gm.n) / (2 * h) - g.H.col(j)).norm(), 1e-8);
    }
  }
}

TEST(DieGeometry, SymmetricPlanesAreThoseWhoseReflectionLeavesEveryGapUnchanged) {
  // The die is its own mirror image in x_k = 0 exactly when the gap of every point equals the gap
  // of its reflection at every time: checked on random points for planes, spheres and cylinders
  // placed on, off and across the coordinate planes, still and moving.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-5.0, 5.0);
  const Vec3d tilted = Vec3d(1, 2, 0).normalized();
  struct Die {
    DieShape shape;
    Vec3d point, direction, displacement;
  };
  const std::vector<Die> dies = {
      {DieShape::plane, {0, 11, 0}, {0, -1, 0}, {0, -3, 0}},  // a punch along -y
      {DieShape::plane, {2, 1, 0}, tilted, {1, 0, 0}},        // a tilted plane
      {DieShape::plane, {0, 0, 3}, {0, 0, 1}, {0, 0, 0}},
      {DieShape::sphere, {0, 12, 0}, {0, 1, 0}, {0, -2, 0}},  // centred on x = 0 and z = 0
      {DieShape::sphere, {0, 12, 0}, {0, 1, 0}, {1, -2, 0}},  // moving off x = 0
      {DieShape::sphere, {3, 0, -1}, {0, 1, 0}, {0, 0, 0}},
      {DieShape::cylinder, {0, 4, 0}, {0, 0, 1}, {0, -1, 0}},  // axis along z, in x = 0
      {DieShape::cylinder, {2, 4, 0}, {0, 0, 1}, {0, 0, 0}},   // axis along z, off x = 0
      {DieShape::cylinder, {0, 4, 1}, {1, 0, 0}, {0, 0, 0}},   // axis along x, off z = 0
      {DieShape::cylinder, {0, 4, 0}, tilted, {0, 0, 0}},
  };
  for (std::size_t d = 0; d < dies.size(); ++d) {
    const Die& die = dies[d];
    const DieGeometry g(die.shape, die.point, die.direction, die.direction, 1.5, die.displacement,
                        Ramp{0.0, 1.0});
    const int symmetric = g.symmetric_planes(7);
    for (int k = 0; k < 3; ++k) {
      bool invariant = true;
      for (int trial = 0; trial < 50; ++trial) {
        const Vec3d x(coordinate(random), coordinate(random), coordinate(random));
        Vec3d mirrored = x;
        mirrored[k] = -x[k];
        for (double t : {0.0, 0.5, 1.0})
          invariant = invariant && std::abs(g.gap(x, t).g - g.gap(mirrored, t).g) < 1e-12;
      }
      EXPECT_EQ((symmetric >> k) & 1, invariant ? 1 : 0) << "die " << d << ", plane " << k;
      EXPECT_EQ((g.symmetric_planes(7 & ~(1 << k)) >> k) & 1, 0) << "not a mirror plane";
    }
  }
}

TEST(DieGeometry, RejectsNonUnitDirectionsAndNonPositiveRadius) {
  EXPECT_THROW(DieGeometry(DieShape::plane, Vec3d::Zero(), Vec3d(0, 2, 0), Vec3d::UnitZ(), 0.0,
                           Vec3d::Zero(), Ramp{}),
               Error);
  EXPECT_THROW(DieGeometry(DieShape::sphere, Vec3d::Zero(), Vec3d::UnitY(), Vec3d::UnitZ(), 0.0,
                           Vec3d::Zero(), Ramp{}),
               Error);
  EXPECT_THROW(DieGeometry(DieShape::cylinder, Vec3d::Zero(), Vec3d::UnitY(), Vec3d(1, 1, 0), 1.0,
                           Vec3d::Zero(), Ramp{}),
               Error);
}

}  // namespace
}  // namespace plisse
