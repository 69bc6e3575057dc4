// The consistent nodal volumes of a shell's mid-surface (loads.md, L6s): a third of each
// triangle's reference area times its thickness at each corner, weighed by a density per triangle,
// and the body force they give.
#include "physics/body_force.hpp"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "core/error.hpp"
#include "mesh/shell_surface.hpp"

namespace plisse {
namespace {

/// Three triangles of areas 6, 12.5 and 5 mm², the third turned out of the plane of the first two
/// (normals consistent across their common sides), 5 nodes.
///   T0 = (0, 1, 2): X1 - X0 = (4, 0, 0), X2 - X0 = (0, 3, 0): A = 6
///   T1 = (1, 3, 2): X3 - X1 = (3, 4, 0), X2 - X1 = (-4, 3, 0): A = |3·3 + 4·4| / 2 = 12.5
///   T2 = (1, 4, 3): X4 - X1 = (0, 0, 2), X3 - X1 = (3, 4, 0): A = 2·5 / 2 = 5
Mesh three_triangles() {
  Mesh mesh;
  mesh.nodes = {Vec3d(0, 0, 0), Vec3d(4, 0, 0), Vec3d(0, 3, 0), Vec3d(7, 4, 0), Vec3d(4, 0, 2)};
  mesh.triangles = {{0, 1, 2}, {1, 3, 2}, {1, 4, 3}};
  make_shell_surface(mesh, 0.5);
  return mesh;
}

double sum_of(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

TEST(ShellNodalVolumes, UniformThicknessSumsToAreaTimesThickness) {
  const Mesh mesh = three_triangles();
  ASSERT_TRUE(mesh.is_shell());
  const std::vector<double> volume = consistent_nodal_volumes(mesh);
  ASSERT_EQ(volume.size(), 5u);
  // (6 + 12.5 + 5) mm² × 0.5 mm; round-off of three products and sums.
  EXPECT_NEAR(sum_of(volume), 23.5 * 0.5, 1e-14 * 23.5);
  // Node 1 is in all three triangles: (6 + 12.5 + 5) 0.5 / 3.
  EXPECT_NEAR(volume[1], 23.5 * 0.5 / 3.0, 1e-15 * 23.5);
  EXPECT_NEAR(volume[0], 6.0 * 0.5 / 3.0, 1e-15 * 6.0);
}

/// The three triangles with thicknesses of their own (regions): T0 0.6, T1 0.9, T2 1.1 mm.
Mesh three_thicknesses() {
  Mesh mesh = three_triangles();
  set_shell_thickness(mesh, {0}, 0.6);
  set_shell_thickness(mesh, {1}, 0.9);
  set_shell_thickness(mesh, {2}, 1.1);
  return mesh;
}

TEST(ShellThickness, EachTriangleKeepsItsOwnAndANodeTakesTheMeanOfItsTriangles) {
  const Mesh mesh = three_thicknesses();
  EXPECT_EQ(mesh.triangle_thickness, (std::vector<double>{0.6, 0.9, 1.1}));
  // Node 0 is in T0 only, node 1 in all three, node 2 in T0 and T1, node 3 in T1 and T2, node 4
  // in T2 only.
  const std::vector<double> expected = {0.6, (0.6 + 0.9 + 1.1) / 3.0, 0.75, 1.0, 1.1};
  for (std::size_t v = 0; v < expected.size(); ++v)
    EXPECT_NEAR(mesh.shell_thickness[v], expected[v], 1e-15) << "node " << v;
  Mesh copy = mesh;
  EXPECT_THROW(set_shell_thickness(copy, {3}, 1.0), Error);  // no triangle 3
  EXPECT_THROW(set_shell_thickness(copy, {0}, 0.0), Error);  // not positive
  EXPECT_THROW(set_shell_thickness(copy, {0}, -1.0), Error);
}

TEST(ShellNodalVolumes, EachCornerGetsAThirdOfItsTrianglesAreaTimesItsThickness) {
  const Mesh mesh = three_thicknesses();
  // T0 0.6, T1 0.9, T2 1.1 mm; A_e t_e / 3 = 1.2, 3.75, 11/6 mm³.
  const double t0 = 1.2, t1 = 3.75, t2 = 11.0 / 6.0;
  const std::vector<double> expected = {t0, t0 + t1 + t2, t0 + t1, t1 + t2, t2};
  const std::vector<double> volume = consistent_nodal_volumes(mesh);
  for (std::size_t v = 0; v < expected.size(); ++v)
    EXPECT_NEAR(volume[v], expected[v], 1e-14) << "node " << v;
  EXPECT_NEAR(sum_of(volume), 3.6 + 11.25 + 5.5, 1e-14 * 20.35);  // Σ A_e t_e
  // One weight per triangle (a density): Σ_e w_e A_e t_e / 3.
  const std::vector<double> weighted = consistent_nodal_volumes(mesh, {2.0, 1.0, 0.5});
  EXPECT_NEAR(weighted[1], 2.0 * t0 + t1 + 0.5 * t2, 1e-14);
  EXPECT_NEAR(weighted[4], 0.5 * t2, 1e-15);
  // A weight per tetrahedron (there are none) is not a weight per triangle.
  EXPECT_THROW(consistent_nodal_volumes(mesh, {1.0}), Error);
}

TEST(ShellNodalVolumes, BodyForceOnAShellIsItsWeight) {
  const Mesh mesh = three_thicknesses();
  // Densities per triangle [tonne/mm³] and g [mm/s²]: the resultant is -g Σ_e ρ_e A_e t_e in the
  // residual's sign (a load enters the residual negatively).
  const std::vector<double> density = {1e-9, 2e-9, 3e-9};
  const Vec3d g(0.0, 0.0, -9810.0);
  BodyForce force(mesh, "g", g, Ramp{}, density);
  std::vector<double> x(kValuesPerNode * 5, 0.0), residual(kValuesPerNode * 5, 0.0);
  force.assemble(1.0, x, residual, nullptr);
  Vec3d total = Vec3d::Zero();
  for (int v = 0; v < 5; ++v)
    for (int i = 0; i < 3; ++i) total[i] += residual[static_cast<std::size_t>(node_dof(v, i))];
  const double weight = 9810.0 * (1e-9 * 3.6 + 2e-9 * 11.25 + 3e-9 * 5.5);
  EXPECT_NEAR(total.z(), weight, 1e-14 * weight);
  EXPECT_EQ(total.x(), 0.0);
  EXPECT_EQ(total.y(), 0.0);
}

}  // namespace
}  // namespace plisse
