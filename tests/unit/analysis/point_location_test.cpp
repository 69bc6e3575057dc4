// Probes' point location (analysis/point_location.hpp): a point inside the body is found in its
// element with coordinates that map back to it, fields of the element's degree are interpolated
// exactly, a point off the body goes to the nearest point of its surface, on a curved
// second-order shell the element's own map is inverted, and on a shell's mid-surface a point goes
// to the nearest point of its triangles.
#include "analysis/point_location.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fixtures/shells.hpp"
#include "mesh/box_mesh.hpp"
#include "support/shell_mesh.hpp"

namespace plisse {
namespace {

/// A field linear in X, and one quadratic in X.
double linear(const Vec3d& X) { return 0.7 - 1.3 * X.x() + 2.1 * X.y() + 0.4 * X.z(); }
double quadratic(const Vec3d& X) {
  return linear(X) + 0.3 * X.x() * X.x() - 0.8 * X.y() * X.z() + 1.1 * X.z() * X.z();
}

std::vector<double> nodal(const Mesh& mesh, double (*f)(const Vec3d&)) {
  std::vector<double> values;
  for (const Vec3d& X : mesh.nodes) values.push_back(f(X));
  return values;
}

TEST(PointLocation, InsideABoxEveryPointMapsBackAndFieldsOfTheElementsDegreeAreExact) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> in_box(0.0, 1.0);
  for (int order : {1, 2}) {
    const Mesh mesh = make_box_mesh({2.0, 3.0, 1.5}, {3, 4, 2}, order);
    const std::vector<double> f1 = nodal(mesh, linear), f2 = nodal(mesh, quadratic);
    for (int trial = 0; trial < 50; ++trial) {
      const Vec3d X(2.0 * in_box(random), 3.0 * in_box(random), 1.5 * in_box(random));
      const MeshPoint p = locate_point(mesh, X);
      ASSERT_TRUE(p.inside) << "order " << order << ", X = " << X.transpose();
      EXPECT_LT(p.distance, 1e-12);
      EXPECT_LT((p.position - X).norm(), 1e-12);
      double sum = 0.0;
      for (double L : p.L) {
        EXPECT_GE(L, -1e-10);
        sum += L;
      }
      EXPECT_NEAR(sum, 1.0, 1e-14);
      const auto weights = interpolation_weights(mesh, p);
      EXPECT_EQ(weights.size(), order == 1 ? 4u : 10u);
      EXPECT_NEAR(interpolate(weights, f1), linear(X), 1e-12);
      if (order == 2) {
        EXPECT_NEAR(interpolate(weights, f2), quadratic(X), 1e-12);
      }
    }
  }
}

TEST(PointLocation, ANodeOrAPointOnASharedFaceIsInsideWithTheNodesValue) {
  const Mesh mesh = make_box_mesh({1.0, 1.0, 1.0}, {2, 2, 2});
  const std::vector<double> f = nodal(mesh, quadratic);  // any nodal values
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const MeshPoint p = locate_point(mesh, mesh.nodes[v]);
    EXPECT_TRUE(p.inside) << "node " << v;
    EXPECT_NEAR(interpolate(interpolation_weights(mesh, p), f), f[v], 1e-12) << "node " << v;
  }
}

TEST(PointLocation, APointOffTheBodyGoesToTheNearestPointOfItsSurface) {
  const Mesh mesh = make_box_mesh({2.0, 2.0, 1.0}, {2, 2, 1});
  const std::vector<double> f = nodal(mesh, linear);
  struct Case {
    Vec3d point, nearest;
  };
  for (const Case& c : {Case{{0.7, 1.2, 1.3}, {0.7, 1.2, 1.0}},     // above a face
                        Case{{-0.5, 0.4, 0.5}, {0.0, 0.4, 0.5}},    // beside a face
                        Case{{2.4, -0.3, 0.5}, {2.0, 0.0, 0.5}},    // off an edge
                        Case{{2.5, 2.5, 1.5}, {2.0, 2.0, 1.0}}}) {  // off a corner
    const MeshPoint p = locate_point(mesh, c.point);
    EXPECT_FALSE(p.inside) << c.point.transpose();
    EXPECT_LT((p.position - c.nearest).norm(), 1e-12) << c.point.transpose();
    EXPECT_NEAR(p.distance, (c.point - c.nearest).norm(), 1e-12);
    EXPECT_NEAR(interpolate(interpolation_weights(mesh, p), f), linear(c.nearest), 1e-12);
  }
}

TEST(PointLocation, OnACurvedShellTheQuadraticElementsHoldPointsTheirChordsMiss) {
  // A point on the outer sphere between nodes: the flat facets of the linear mesh lie inside the
  // sphere by up to their sagitta h²/(8R), so it is off that mesh; the 10-node elements follow the
  // sphere to O(h³) and hold it (or miss it by far less).
  const double inner = 10.0, wall = 1.0, outer = inner + wall;
  const Vec3d X = outer * Vec3d(1.0, 2.0, 1.5).normalized();
  double linear_miss = 0.0;
  for (int order : {1, 2}) {
    const Mesh mesh = test::sphere_shell(Symmetry::octant, inner, wall, 2, 2.0, order);
    const MeshPoint p = locate_point(mesh, X);
    const std::vector<double> f = nodal(mesh, linear);
    // Isoparametric elements reproduce a linear field exactly wherever the point is.
    EXPECT_NEAR(interpolate(interpolation_weights(mesh, p), f), linear(p.position), 1e-11);
    if (order == 1) {
      EXPECT_FALSE(p.inside);
      EXPECT_GT(p.distance, 1e-4);
      EXPECT_LT(p.distance, 2.0 * 2.0 / (8 * outer) * 2);  // the sagitta of an edge up to 2h
      linear_miss = p.distance;
    } else {
      EXPECT_LT(p.distance, 0.1 * linear_miss);
      EXPECT_NEAR(p.position.norm(), outer, 0.1 * linear_miss);
    }
  }
}

TEST(PointLocation, OnAShellsMidSurfaceAPointGoesToTheNearestPointOfItsTriangles) {
  // The octant of a sphere of radius 10 mm as a shell's mid-surface (8² triangles). A
  // point inside a triangle's plane lies in it with its own barycentric coordinates, and a linear
  // field interpolates exactly there; the same point moved 0.3 mm along the triangle's normal (a
  // point on a face of a 0.6 mm wall) comes back to it, 0.3 mm away.
  const Mesh mesh = test::octahedral_sphere(10.0, 0.6, 8, true);
  ASSERT_TRUE(mesh.is_shell());
  const std::vector<double> f = nodal(mesh, linear);
  for (int e : {0, 7, 21, 40}) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(e)];
    const Vec3d x0 = mesh.nodes[tri[0]], x1 = mesh.nodes[tri[1]], x2 = mesh.nodes[tri[2]];
    const Vec3d L(0.2, 0.5, 0.3);
    const Vec3d X = L[0] * x0 + L[1] * x1 + L[2] * x2;
    const Vec3d n = (x1 - x0).cross(x2 - x0).normalized();
    for (double off : {0.0, 0.3}) {
      const MeshPoint at = locate_point(mesh, X + off * n);
      EXPECT_EQ(at.element, e) << "off " << off;
      EXPECT_NEAR(at.distance, off, 1e-12);
      EXPECT_EQ(at.inside, off == 0.0);
      EXPECT_LT((at.position - X).norm(), 1e-12);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(at.L[static_cast<std::size_t>(k)], L[k], 1e-12);
      const auto weights = interpolation_weights(mesh, at);
      ASSERT_EQ(weights.size(), 3u);
      EXPECT_NEAR(interpolate(weights, f), linear(X), 1e-12);
    }
  }
}

}  // namespace
}  // namespace plisse
