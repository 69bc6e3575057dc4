// Follower traction (loads.md, L14-L16): the tangent is the derivative of the residual on linear
// and quadratic faces, a purely normal traction is the follower pressure of the opposite sign,
// the resultant on the undeformed flat face is (normal n + shear s) x area, a rigid rotation of
// the body and the direction rotates the forces with it, and the work and checkpoint hold.
#include "physics/follower_traction.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/error.hpp"
#include "mesh/box_mesh.hpp"
#include "physics/pressure_load.hpp"
#include "support/term_testing.hpp"

namespace plisse {
namespace {

using test::DenseSink;
using test::random_state;
using test::term_residual;

FollowerTractionValues normal_and_shear() {
  FollowerTractionValues v;
  v.normal = 0.7;
  v.shear = -0.4;
  v.direction = Vec3d(1.0, 0.3, 0.2).normalized();
  return v;
}

/// The largest difference between the assembled tangent and central differences of the residual,
/// relative to the largest tangent entry.
double tangent_error(ModelTerm& term, const std::vector<double>& x) {
  const int n = static_cast<int>(x.size());
  DenseSink sink(n);
  std::vector<double> r(n, 0.0);
  term.assemble(1.0, x, r, &sink);
  const double h = 1e-6;
  const double max_error = test::max_tangent_error(term, 1.0, x, sink.K, h);
  return max_error / sink.K.cwiseAbs().maxCoeff();
}

TEST(FollowerTraction, TangentIsTheDerivativeOfTheResidualOnLinearAndQuadraticFaces) {
  for (int order : {1, 2}) {
    const Mesh mesh = make_box_mesh({2.0, 2.0, 1.0}, {2, 2, 1}, order);
    FollowerTraction load(mesh, "t", "top", normal_and_shear(), Ramp{0.0, 1.0}, {});
    EXPECT_FALSE(load.symmetric());
    const auto x = random_state(kValuesPerNode * mesh.n_nodes(), 11, 0.2);
    // Central differences of a smooth residual: error O(h^2) ~ 1e-12 relative, plus round-off.
    EXPECT_LT(tangent_error(load, x), 1e-7) << "order " << order;
  }
}

TEST(FollowerTraction, NormalTractionIsTheFollowerPressureOfOppositeSign) {
  for (int order : {1, 2}) {
    const Mesh mesh = make_box_mesh({2.0, 1.0, 1.0}, {2, 1, 1}, order);
    FollowerTractionValues v;
    v.normal = -0.3;
    FollowerTraction traction(mesh, "t", "right", v, Ramp{0.0, 1.0}, {});
    PressureLoad pressure(mesh, "p", "right", 0.3, Ramp{0.0, 1.0}, {}, 0);
    const auto x = random_state(kValuesPerNode * mesh.n_nodes(), 3, 0.3);
    const Eigen::VectorXd a = term_residual(traction, 1.0, x), b = term_residual(pressure, 1.0, x);
    EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-14 * b.cwiseAbs().maxCoeff()) << order;
  }
}

TEST(FollowerTraction, ResultantOnTheUndeformedFlatFaceIsTractionTimesArea) {
  for (int order : {1, 2}) {
    const Mesh mesh = make_box_mesh({2.0, 3.0, 1.0}, {2, 3, 1}, order);
    FollowerTractionValues v = normal_and_shear();
    FollowerTraction load(mesh, "t", "top", v, Ramp{0.0, 2.0}, {});
    const std::vector<double> x(kValuesPerNode * mesh.n_nodes(), 0.0);
    // Half-way up the ramp; top normal +z, s = projection of d onto the xy plane.
    const Vec3d s = Vec3d(v.direction.x(), v.direction.y(), 0.0).normalized();
    const Vec3d expected = 0.5 * 6.0 * (v.normal * Vec3d::UnitZ() + v.shear * s);
    const auto values = load.history_values(1.0, x);
    EXPECT_LT((Vec3d(values[0], values[1], values[2]) - expected).norm(), 1e-14) << order;
  }
}

TEST(FollowerTraction, RigidRotationOfBodyAndDirectionRotatesTheForces) {
  // Objectivity: with x = Q X and the direction Q d, every nodal force is Q times the force at
  // the reference state with d.
  const Mesh mesh = make_box_mesh({2.0, 2.0, 1.0}, {2, 2, 1}, 2);
  const Mat3d Q = Eigen::AngleAxisd(1.1, Vec3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  FollowerTractionValues v = normal_and_shear();
  FollowerTraction reference(mesh, "t", "top", v, Ramp{0.0, 1.0}, {});
  v.direction = Q * v.direction;
  FollowerTraction rotated(mesh, "t", "top", v, Ramp{0.0, 1.0}, {});
  const int n = kValuesPerNode * mesh.n_nodes();
  std::vector<double> zero(n, 0.0), x(n, 0.0);
  for (int a = 0; a < mesh.n_nodes(); ++a) {
    const Vec3d u = Q * mesh.nodes[a] - mesh.nodes[a];
    for (int i = 0; i < 3; ++i) x[node_dof(a, i)] = u[i];
  }
  const Eigen::VectorXd r0 = term_residual(reference, 1.0, zero),
                        r = term_residual(rotated, 1.0, x);
  double max_error = 0.0;
  for (int a = 0; a < mesh.n_nodes(); ++a) {
    const Vec3d f0(r0[node_dof(a, 0)], r0[node_dof(a, 1)], r0[node_dof(a, 2)]);
    const Vec3d f(r[node_dof(a, 0)], r[node_dof(a, 1)], r[node_dof(a, 2)]);
    max_error = std::max(max_error, (f - Q * f0).norm());
  }
  EXPECT_LT(max_error, 1e-13 * r0.cwiseAbs().maxCoeff());
}

TEST(FollowerTraction, ShearVanishesWhereTheSurfaceIsNormalToTheDirection) {
  const Mesh mesh = make_box_mesh({2.0, 2.0, 1.0}, {2, 2, 1}, 1);
  FollowerTractionValues v;
  v.shear = 0.5;
  v.direction = Vec3d::UnitZ();  // the top's normal: no tangential direction
  FollowerTraction load(mesh, "t", "top", v, Ramp{0.0, 1.0}, {});
  const std::vector<double> x(kValuesPerNode * mesh.n_nodes(), 0.0);
  EXPECT_TRUE(term_residual(load, 1.0, x).isZero(0.0));
}

TEST(FollowerTraction, WorkIsTheTrapezoidalSumAndSurvivesACheckpoint) {
  // A rigid translation under the constant load (ramp done): the forces do not change, so the
  // work is exactly F · Δu, summed over two steps.
  const Mesh mesh = make_box_mesh({2.0, 2.0, 1.0}, {2, 2, 1}, 1);
  const FollowerTractionValues v = normal_and_shear();
  FollowerTraction load(mesh, "t", "top", v, Ramp{0.0, 1e-9}, {});
  const int n = kValuesPerNode * mesh.n_nodes();
  std::vector<double> x(n, 0.0), r(n, 0.0);
  load.assemble(1.0, x, r, nullptr);
  load.accept_step(x);
  const auto F = load.history_values(1.0, x);
  const Vec3d total(F[0], F[1], F[2]);
  EXPECT_EQ(F[3], 0.0);
  const Vec3d step(0.1, -0.2, 0.3);
  for (int k = 1; k <= 2; ++k) {
    for (int a = 0; a < mesh.n_nodes(); ++a)
      for (int i = 0; i < 3; ++i) x[node_dof(a, i)] = k * step[i];
    load.assemble(1.0 + k, x, r, nullptr);
    load.accept_step(x);
  }
  EXPECT_NEAR(load.history_values(3.0, x)[3], total.dot(2.0 * step), 1e-14);
  FollowerTraction restored(mesh, "t", "top", v, Ramp{0.0, 1e-9}, {});
  restored.load_state(load.save_state());
  EXPECT_EQ(restored.history_values(3.0, x), load.history_values(3.0, x));
  EXPECT_THROW(restored.load_state(std::vector<double>{0.0, 1.0}), Error);
}

}  // namespace
}  // namespace plisse
