// Dead loads: consistent nodal areas (loads.md, L11) on linear and quadratic faces, the total
// force spread over a surface (L12), and the load's columns and work (L13) through accepted and
// rejected steps and a checkpoint.
#include "physics/dead_load.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/error.hpp"
#include "mesh/box_mesh.hpp"
#include "physics/ramp.hpp"
#include "physics/surface.hpp"

namespace plisse {
namespace {

double sum_of_areas(const std::vector<std::pair<int, double>>& areas) {
  double total = 0.0;
  for (const auto& entry : areas) total += entry.second;
  return total;
}

TEST(Ramp, LinearRampAndLoadCurveGiveTheirFactors) {
  const Ramp linear{0.2, 0.6};
  EXPECT_EQ(linear.factor(0.1), 0.0);
  EXPECT_NEAR(linear.factor(0.5), 0.75, 1e-15);
  EXPECT_EQ(linear.factor(0.7), 1.0);
  // Load, hold, unload below zero: joined linearly, the end values held outside.
  Ramp curve;
  curve.table = {{0.1, 0.5}, {0.3, 1.0}, {0.5, 1.0}, {0.9, -0.6}};
  EXPECT_EQ(curve.factor(0.0), 0.5);
  EXPECT_NEAR(curve.factor(0.2), 0.75, 1e-15);
  EXPECT_EQ(curve.factor(0.3), 1.0);
  EXPECT_EQ(curve.factor(0.4), 1.0);
  EXPECT_NEAR(curve.factor(0.7), 0.2, 1e-15);
  EXPECT_EQ(curve.factor(0.9), -0.6);
  EXPECT_EQ(curve.factor(2.0), -0.6);
}

TEST(ConsistentNodalAreas, LinearFacesGiveAThirdOfEachTriangleToEachCorner) {
  // The top of a 3 x 2 mm box, 3 x 2 cells: every interior node of the structured triangulation
  // touches 6 triangles of 1/2 mm^2 (1 mm^2 in all), an edge node 3 or 2, a corner 1 or 2.
  const Mesh mesh = make_box_mesh({3.0, 2.0, 1.0}, {3, 2, 1});
  const auto areas = consistent_nodal_areas(mesh, outward_faces(mesh, "top"));
  EXPECT_EQ(areas.size(), 12u);
  EXPECT_NEAR(sum_of_areas(areas), 6.0, 1e-14);
  for (const auto& [node, area] : areas) {
    const Vec3d& X = mesh.nodes[node];
    const bool interior_x = X.x() > 0.0 && X.x()<3.0, interior_y = X.y()> 0.0 && X.y() < 2.0;
    if (interior_x && interior_y) {
      EXPECT_NEAR(area, 1.0, 1e-14) << "node " << node;
    }
  }
}

TEST(ConsistentNodalAreas, StraightQuadraticFacesGiveNothingToCornersAndAThirdToEdgeNodes) {
  // ∫ N_a dA of the 6-node triangle on a flat face: 0 for the corners, A/3 for the edge nodes.
  const Mesh mesh = make_box_mesh({2.0, 2.0, 0.5}, {2, 2, 1}, 2);
  const auto faces = outward_faces(mesh, "right");
  const auto areas = consistent_nodal_areas(mesh, faces);
  EXPECT_NEAR(sum_of_areas(areas), 1.0, 1e-14);  // 2 x 0.5 mm
  std::map<int, double> expected;
  for (const SurfaceFace& f : faces) {
    const Vec3d& X0 = mesh.nodes[f.nodes[0]];
    const double A = 0.5 * (mesh.nodes[f.nodes[1]] - X0).cross(mesh.nodes[f.nodes[2]] - X0).norm();
    for (int a = 0; a < 3; ++a) expected[f.nodes[a]] += 0.0;
    for (int a = 3; a < 6; ++a) expected[f.nodes[a]] += A / 3.0;
  }
  ASSERT_EQ(areas.size(), expected.size());
  for (const auto& [node, area] : areas) EXPECT_NEAR(area, expected.at(node), 1e-15);
}

TEST(ConsistentNodalAreas, CurvedQuadraticFaceIntegratesItsTrueArea) {
  // One 6-node face whose edge nodes lie on the paraboloid z = x^2 + y^2 over the triangle
  // (0,0), (1,0), (0,1): the face map is exactly that paraboloid patch. Its area
  // ∫∫ sqrt(1 + 4 x^2 + 4 y^2) dx dy is computed below by Gauss-Legendre quadrature on the
  // collapsed square (0.7511563...); the degree-4 rule on |X_ξ × X_η|, not a polynomial, gives
  // 0.7513334: 2.4e-4 relative, its quadrature error on this strongly curved patch.
  Mesh mesh;  // the face's nodes only: the areas need no tetrahedra
  mesh.nodes = {Vec3d(0, 0, 0),      Vec3d(1, 0, 1),       Vec3d(0, 1, 1),
                Vec3d(0.5, 0, 0.25), Vec3d(0.5, 0.5, 0.5), Vec3d(0, 0.5, 0.25)};
  SurfaceFace face;
  face.n_nodes = 6;
  face.nodes = {0, 1, 2, 3, 4, 5};
  const double rule = sum_of_areas(consistent_nodal_areas(mesh, {face}));
  // Reference: 40 x 40 Gauss-Legendre points mapped onto the triangle (Duffy), converged to 1e-12.
  double reference = 0.0;
  {
    constexpr int n = 40;
    std::vector<double> xg(n), wg(n);
    for (int i = 0; i < n; ++i) {  // Newton on the Legendre polynomial
      double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1.0);
        const double dz = p1 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-16) break;
      }
      xg[i] = 0.5 * (1.0 + z);
      wg[i] = 1.0 / ((1.0 - z * z) * dp * dp);
    }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double u = xg[i], v = xg[j] * (1.0 - u);  // (u, v) in the triangle
        reference += wg[i] * wg[j] * (1.0 - u) * std::sqrt(1.0 + 4.0 * (u * u + v * v));
      }
  }
  EXPECT_NEAR(rule, reference, 3e-4 * reference);
}

TEST(TotalForce, SpreadsTheForceInProportionToAreaAndSumsToIt) {
  for (int order : {1, 2}) {
    const Mesh mesh = make_box_mesh({2.0, 3.0, 1.0}, {2, 3, 2}, order);
    const auto faces = outward_faces(mesh, "top");
    const Vec3d F(1.5, -2.0, 0.25);
    const auto forces = total_force(mesh, faces, F);
    const auto tractions = traction_forces(mesh, faces, F / 6.0);  // top area 6 mm^2
    ASSERT_EQ(forces.size(), tractions.size());
    Vec3d sum = Vec3d::Zero();
    for (std::size_t k = 0; k < forces.size(); ++k) {
      sum += forces[k].force;
      EXPECT_EQ(forces[k].node, tractions[k].node);
      EXPECT_LT((forces[k].force - tractions[k].force).norm(), 1e-15) << "order " << order;
    }
    EXPECT_LT((sum - F).norm(), 1e-14) << "order " << order;
  }
}

TEST(DeadLoad, ResidualIsMinusTheRampedForcesAndTheTangentIsZero) {
  DeadLoad load("tip", {{1, Vec3d(1, 2, 3)}, {3, Vec3d(-1, 0, 0.5)}}, Ramp{0.0, 2.0});
  std::vector<double> x(4 * kValuesPerNode, 0.0), r(x.size(), 0.0);
  load.assemble(0.5, x, r, nullptr);
  EXPECT_DOUBLE_EQ(r[node_dof(1, 0)], -0.25);
  EXPECT_DOUBLE_EQ(r[node_dof(1, 2)], -0.75);
  EXPECT_DOUBLE_EQ(r[node_dof(3, 0)], 0.25);
  EXPECT_DOUBLE_EQ(r[node_dof(0, 0)], 0.0);
  EXPECT_DOUBLE_EQ(r[node_dof(1, 3)], 0.0);  // pressure rows untouched
  const auto values = load.history_values(1.0, x);
  ASSERT_EQ(values.size(), 4u);
  EXPECT_DOUBLE_EQ(values[0], 0.0);  // 0.5 x (1 - 1)
  EXPECT_DOUBLE_EQ(values[1], 1.0);
  EXPECT_DOUBLE_EQ(values[2], 1.75);
  EXPECT_EQ(load.history_columns(),
            (std::vector<std::string>{"load_x:tip", "load_y:tip", "load_z:tip", "work:tip"}));
}

TEST(DeadLoad, WorkIsTheTrapezoidalSumOverAcceptedStepsAndSurvivesACheckpoint) {
  // One node, force F = (2, 0, 0) ramped over [0, 1]; the node moves u(t) = t^2 along x. Exact
  // work ∫ λ F du = ∫_0^1 t 2 (2t) dt = 4/3; the trapezoidal sum over steps of 0.25 is
  // Σ ½ (λ_n + λ_n+1) F (u_n+1 − u_n) = Σ (t_n + t_n+1)² Δt = 1.3125.
  DeadLoad load("f", {{0, Vec3d(2, 0, 0)}}, Ramp{0.0, 1.0});
  std::vector<double> x(kValuesPerNode, 0.0), r(x.size(), 0.0);
  double expected = 0.0;
  for (int n = 1; n <= 4; ++n) {
    const double t0 = 0.25 * (n - 1), t1 = 0.25 * n;
    expected += 0.5 * (t0 + t1) * 2.0 * (t1 * t1 - t0 * t0);
    // A rejected attempt first, at a different time and state: it must leave no trace.
    x[0] = 9.0;
    load.assemble(t1 + 0.1, x, r, nullptr);
    load.reject_step();
    x[0] = t1 * t1;
    load.assemble(t1, x, r, nullptr);
    load.accept_step(x);
    EXPECT_NEAR(load.history_values(t1, x)[3], expected, 1e-15) << "step " << n;
  }
  EXPECT_NEAR(expected, 1.3125, 1e-15);
  // A checkpoint restores W, S and t: the next step continues the same sum.
  DeadLoad restored("f", {{0, Vec3d(2, 0, 0)}}, Ramp{0.0, 1.0});
  restored.load_state(load.save_state());
  x[0] = 1.5;
  load.assemble(1.25, x, r, nullptr);
  restored.assemble(1.25, x, r, nullptr);
  load.accept_step(x);
  restored.accept_step(x);
  EXPECT_EQ(restored.history_values(1.25, x)[3], load.history_values(1.25, x)[3]);
  EXPECT_NEAR(load.history_values(1.25, x)[3], expected + 2.0 * 0.5, 1e-15);
  EXPECT_THROW(restored.load_state(std::vector<double>{0.0, 1.0}), Error);
  EXPECT_THROW(restored.load_state(std::vector<double>{0.0, NAN, 1.0}), Error);
}

}  // namespace
}  // namespace plisse
