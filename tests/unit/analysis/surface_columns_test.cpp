// Through-thickness columns: point-triangle distances against brute force, and the column of
// every tetrahedron of a layered shell is the outer triangle on top of its prism.
#include "analysis/surface_columns.hpp"

#include <gtest/gtest.h>

#include <random>

#include "analysis/wrinkle_rings.hpp"
#include "fixtures/shells.hpp"

namespace plisse {
namespace {

TEST(SurfaceColumns, PointTriangleDistanceMatchesBruteForce) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(-2.0, 2.0);
  const auto random_point = [&] { return Vec3d(coord(rng), coord(rng), coord(rng)); };
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3d a = random_point(), b = random_point(), c = random_point(), p = random_point();
    // Brute force over a barycentric lattice of 200 x 200: the lattice point nearest to the true
    // closest point is within |edge| / 200 of it, so d_brute - d <= 4 sqrt(3) / 200 < 0.035.
    double brute = 1e300;
    const int n = 200;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const Vec3d q =
            a + (b - a) * (static_cast<double>(i) / n) + (c - a) * (static_cast<double>(j) / n);
        brute = std::min(brute, (p - q).norm());
      }
    const double d = point_triangle_distance(p, a, b, c);
    EXPECT_LE(d, brute + 1e-12);
    EXPECT_GE(d, brute - 0.035);
  }
  // Exact cases: above the face, beyond a vertex, beside an edge.
  const Vec3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_DOUBLE_EQ(point_triangle_distance(Vec3d(0.2, 0.2, 3.0), a, b, c), 3.0);
  EXPECT_DOUBLE_EQ(point_triangle_distance(Vec3d(-3.0, -4.0, 0.0), a, b, c), 5.0);
  EXPECT_DOUBLE_EQ(point_triangle_distance(Vec3d(0.5, -2.0, 0.0), a, b, c), 2.0);
  EXPECT_NEAR(point_triangle_distance(Vec3d(1.0, 1.0, 0.0), a, b, c), std::sqrt(0.5), 1e-15);
}

TEST(SurfaceColumns, EachTetrahedronBelongsToTheTriangleOnTopOfItsPrism) {
  const int layers = 3;
  const Mesh mesh = test::sphere_shell(Symmetry::quarter, 10.0, 1.0, layers, 1.0);
  const auto outer = tagged_triangles(mesh, "outer");
  const std::vector<int> expected = test::prism_columns(mesh, layers, outer);
  const std::vector<int> column = assign_columns(mesh.nodes, mesh.tets, outer);
  ASSERT_EQ(column.size(), mesh.tets.size());
  int mismatches = 0;
  for (std::size_t e = 0; e < column.size(); ++e) {
    ASSERT_GE(expected[e], 0);
    if (column[e] != expected[e]) ++mismatches;
  }
  // The shell is made of radial prisms, and a centroid projects inside its own prism's outer
  // triangle (a tetrahedron's centroid lies inside the prism, whose sides are radial).
  EXPECT_EQ(mismatches, 0);
  std::vector<int> per_triangle(outer.size(), 0);
  for (int c : column) ++per_triangle[static_cast<std::size_t>(c)];
  for (int n : per_triangle) EXPECT_EQ(n, 3 * layers);  // 3 tetrahedra per prism and layer
}

}  // namespace
}  // namespace plisse
