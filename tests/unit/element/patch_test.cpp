// Patch test of the MINI element: a distorted mesh of a cube in a homogeneous deformation with a
// uniform pressure. Interior nodes carry no residual, the bubbles stay zero, and the boundary
// nodal forces equal the traction σ n integrated over the deformed faces (σ = σ_iso - p I).
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <vector>

#include "element/mini.hpp"
#include "element_test_support.hpp"
#include "material/mooney_rivlin.hpp"
#include "material/neo_hookean.hpp"

namespace plisse::mini {
namespace {

/// Assembles the condensed residual over the mesh at x = F0 X + c with uniform nodal pressure p.
/// Returns the global residual (4 values per node: u_x, u_y, u_z, p) and, in largest_bubble, the
/// largest |b| / h_e.
template <class Material>
std::vector<double> assemble_patch(const test::PatchMesh& m, const Mat3d& F0, double p,
                                   const Material& mat, double inverse_bulk_modulus,
                                   double& largest_bubble) {
  std::vector<double> residual(4 * m.nodes.size(), 0.0);
  largest_bubble = 0.0;
  for (const auto& tet : m.tets) {
    std::array<Vec3d, 4> X;
    for (int a = 0; a < 4; ++a) X[a] = m.nodes[tet[a]];
    const TetGeometry g = compute_tet_geometry(X);
    ElemVec x = test::homogeneous_state(X, F0, Vec3d(0.1, -0.2, 0.3));
    x.tail<kDofP>().setConstant(p);
    BubbleVec b = BubbleVec::Zero();
    ElemVec r;
    ElemMat K;
    EXPECT_TRUE(assemble_mini(g, x, mat, inverse_bulk_modulus, b, r, &K).ok);
    largest_bubble = std::max(largest_bubble, b.norm() / g.size);
    for (int a = 0; a < 4; ++a) {
      for (int i = 0; i < 3; ++i) residual[4 * tet[a] + i] += r(dof_u(a, i));
      residual[4 * tet[a] + 3] += r(dof_p(a));
    }
  }
  return residual;
}

/// Σ over the boundary faces at each node of ∫ N_a σ n da on the deformed configuration
/// (deformed area / 3 per corner: N_a integrates to a third of a triangle).
std::vector<Vec3d> traction_forces(const test::PatchMesh& m, const Mat3d& F0, const Mat3d& sigma) {
  std::vector<Vec3d> force(m.nodes.size(), Vec3d::Zero());
  const std::array<std::array<int, 4>, 4> faces = {
      {{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}}};  // 3 corners + opposite
  for (const auto& tet : m.tets)
    for (const auto& f : faces) {
      const int n0 = tet[f[0]], n1 = tet[f[1]], n2 = tet[f[2]];
      bool on_cube_face = false;  // all three corners on one face of the cube
      for (int axis = 0; axis < 3; ++axis)
        for (double side : {0.0, 1.0})
          on_cube_face = on_cube_face || (m.nodes[n0](axis) == side && m.nodes[n1](axis) == side &&
                                          m.nodes[n2](axis) == side);
      if (!on_cube_face) continue;
      const Vec3d x0 = F0 * m.nodes[n0], x1 = F0 * m.nodes[n1], x2 = F0 * m.nodes[n2];
      Vec3d area_normal = 0.5 * (x1 - x0).cross(x2 - x0);  // |.| = deformed area
      if (area_normal.dot(x0 - F0 * m.nodes[tet[f[3]]]) < 0) area_normal = -area_normal;
      for (int corner : {n0, n1, n2}) force[corner] += sigma * area_normal / 3.0;
    }
  return force;
}

template <class Material>
void expect_patch_test_passes(const Material& mat, const Mat3d& F0, double p,
                              double inverse_bulk_modulus) {
  const test::PatchMesh m = test::distorted_cube(3, 17);
  double largest_bubble = 0.0;
  const std::vector<double> r = assemble_patch(m, F0, p, mat, inverse_bulk_modulus, largest_bubble);
  EXPECT_LT(largest_bubble, 1e-13);
  const double J = F0.determinant();
  const Mat3d sigma = mat.evaluate(F0).P * F0.transpose() / J - p * Mat3d::Identity();
  const std::vector<Vec3d> expected = traction_forces(m, F0, sigma);
  double force_scale = 0.0;
  for (const Vec3d& f : expected) force_scale = std::max(force_scale, f.norm());
  ASSERT_GT(force_scale, 0.0);
  const double volume_per_node = 1.0 / m.nodes.size();
  for (std::size_t v = 0; v < m.nodes.size(); ++v) {
    const Vec3d r_u(r[4 * v], r[4 * v + 1], r[4 * v + 2]);
    // Interior nodes: expected force zero. Boundary nodes: the integrated traction.
    EXPECT_LT((r_u - expected[v]).norm(), 1e-12 * force_scale)
        << "node " << v << (m.on_boundary[v] ? " (boundary)" : " (interior)");
    if (!m.on_boundary[v]) {
      EXPECT_TRUE(expected[v].isZero(0.0));
    }
    // The constraint rows: ∫ N_a ((J - 1) + p/κ) = 0 for the consistent pressure.
    EXPECT_LT(std::abs(r[4 * v + 3]), 1e-13 * volume_per_node) << "node " << v;
  }
}

TEST(MiniPatchTest, IncompressibleHomogeneousDeformation) {
  // det F0 = 1 (exact incompressibility); any uniform pressure is an equilibrium state.
  Mat3d U;
  U << 1.3, 0.2, 0.0, 0.0, 1.0 / 1.3, 0.1, 0.0, 0.0, 1.0;
  const Mat3d F0 = test::rotation(Vec3d(0.3, 1.0, -0.4), 0.6) * U;
  ASSERT_NEAR(F0.determinant(), 1.0, 1e-15);
  expect_patch_test_passes(NeoHookean{0.5}, F0, 0.37, 0.0);
  expect_patch_test_passes(MooneyRivlin{0.3, 0.2}, F0, -0.21, 0.0);
}

TEST(MiniPatchTest, NearlyIncompressibleHomogeneousDeformation) {
  // det F0 ≠ 1 with the consistent pressure p = -κ (J - 1).
  Mat3d F0;
  F0 << 1.1, 0.15, 0.0, -0.05, 0.95, 0.1, 0.02, 0.0, 0.98;
  const double kappa = 200.0;
  const double p = -kappa * (F0.determinant() - 1.0);
  expect_patch_test_passes(NeoHookean{0.5}, F0, p, 1.0 / kappa);
}

}  // namespace
}  // namespace plisse::mini
