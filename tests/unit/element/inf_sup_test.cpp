// Inf-sup stability of the MINI element: on a clamped, distorted cube mesh at the reference state,
// the pressure Schur complement of the condensed tangent has exactly one zero eigenvalue (the
// constant pressure, undetermined when every boundary displacement is fixed). Without the bubble
// (the P1/P1 pair) it has at least n_p - n_u zero eigenvalues: spurious pressure modes.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "element/mini.hpp"
#include "element_test_support.hpp"
#include "material/neo_hookean.hpp"

namespace plisse::mini {
namespace {

/// Number of eigenvalues of the pressure Schur complement S = K_pu K_uu⁻¹ K_up - K_pp (free u:
/// interior nodes) below 1e-10 of the largest. `with_bubble`: MINI (condensed); else P1/P1.
int count_zero_pressure_modes(const test::PatchMesh& m, bool with_bubble, int& n_u, int& n_p) {
  const NeoHookean mat{0.5};
  const int n_nodes = static_cast<int>(m.nodes.size());
  std::vector<int> u_index(n_nodes, -1);
  n_u = 0;
  for (int v = 0; v < n_nodes; ++v)
    if (!m.on_boundary[v]) u_index[v] = 3 * n_u++;
  n_u *= 3;
  n_p = n_nodes;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n_u + n_p, n_u + n_p);
  for (const auto& tet : m.tets) {
    std::array<Vec3d, 4> X;
    for (int a = 0; a < 4; ++a) X[a] = m.nodes[tet[a]];
    const TetGeometry g = compute_tet_geometry(X);
    const ElemVec x = ElemVec::Zero();
    ElemMat K_e;
    if (with_bubble) {
      BubbleVec b = BubbleVec::Zero();
      ElemVec r;
      EXPECT_TRUE(assemble_mini(g, x, mat, 0.0, b, r, &K_e).ok);
    } else {
      MiniLocalSystem sys;
      EXPECT_TRUE(assemble_mini_uncondensed(g, x, mat, 0.0, BubbleVec::Zero(), sys, true));
      K_e = sys.K_xx;
    }
    std::array<int, kDof> global;  // -1: clamped
    for (int a = 0; a < 4; ++a) {
      for (int i = 0; i < 3; ++i)
        global[dof_u(a, i)] = u_index[tet[a]] < 0 ? -1 : u_index[tet[a]] + i;
      global[dof_p(a)] = n_u + tet[a];
    }
    for (int i = 0; i < kDof; ++i)
      for (int j = 0; j < kDof; ++j)
        if (global[i] >= 0 && global[j] >= 0) K(global[i], global[j]) += K_e(i, j);
  }
  const Eigen::MatrixXd K_uu = K.topLeftCorner(n_u, n_u), K_up = K.topRightCorner(n_u, n_p);
  const Eigen::MatrixXd S =
      K_up.transpose() * K_uu.llt().solve(K_up) - K.bottomRightCorner(n_p, n_p);
  const Eigen::VectorXd eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(S).eigenvalues();
  EXPECT_GT(eigenvalues.minCoeff(), -1e-10 * eigenvalues.maxCoeff());  // S is semi-definite
  int zeros = 0;
  for (double lambda : eigenvalues) zeros += std::abs(lambda) < 1e-10 * eigenvalues.maxCoeff();
  return zeros;
}

TEST(MiniInfSup, OnlyTheConstantPressureModeOnAClampedMesh) {
  const test::PatchMesh m = test::distorted_cube(3, 5);
  int n_u = 0, n_p = 0;
  EXPECT_EQ(count_zero_pressure_modes(m, true, n_u, n_p), 1);
  EXPECT_GE(count_zero_pressure_modes(m, false, n_u, n_p), n_p - n_u);  // P1/P1: unstable
  EXPECT_GT(n_p - n_u, 10);  // the comparison is meaningful
}

}  // namespace
}  // namespace plisse::mini
