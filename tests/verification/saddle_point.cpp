#include "verification/saddle_point.hpp"

#include <algorithm>
#include <set>
#include <utility>
#include <variant>

#include "element/mini.hpp"
#include "solver/petsc_call.hpp"

namespace plisse::test {
namespace {

constexpr int kPerNode = DofMap::kPerNode;

/// Equation numbers of the 16 element unknowns (-1 when constrained), MINI layout.
std::array<int, mini::kDof> element_equations(const MixedModel& model, int e) {
  std::array<int, mini::kDof> eq;
  const auto& tet = model.mesh().tets[e];
  for (int a = 0; a < mini::kNodes; ++a) {
    for (int k = 0; k < 3; ++k)
      eq[mini::dof_u(a, k)] = model.dofs().equation(DofMap::dof(tet[a], k));
    eq[mini::dof_p(a)] = model.dofs().equation(DofMap::dof(tet[a], 3));
  }
  return eq;
}

}  // namespace

SparseMatrix assemble_mini_tangent(MixedModel& model) {
  Mat K = model.create_matrix();
  model.assemble_tangent(K);
  std::vector<Eigen::Triplet<double>> entries;
  for (PetscInt row = 0; row < model.n_free(); ++row) {
    PetscInt n = 0;
    const PetscInt* columns = nullptr;
    const PetscScalar* values = nullptr;
    PLISSE_PETSC(MatGetRow(K, row, &n, &columns, &values));
    for (PetscInt i = 0; i < n; ++i) entries.emplace_back(row, columns[i], values[i]);
    PLISSE_PETSC(MatRestoreRow(K, row, &n, &columns, &values));
  }
  MatDestroy(&K);
  SparseMatrix result(model.n_free(), model.n_free());
  result.setFromTriplets(entries.begin(), entries.end());
  return result;
}

SparseMatrix assemble_p1p1_tangent(const MixedModel& model, const AnyMaterial& material,
                                   double inverse_bulk_modulus) {
  const Mesh& mesh = model.mesh();
  std::vector<Eigen::Triplet<double>> entries;
  std::visit(
      [&](const auto& m) {
        for (int e = 0; e < mesh.n_tets(); ++e) {
          const auto& tet = mesh.tets[e];
          const mini::TetGeometry g = mini::compute_tet_geometry(
              {mesh.nodes[tet[0]], mesh.nodes[tet[1]], mesh.nodes[tet[2]], mesh.nodes[tet[3]]});
          const std::array<int, mini::kDof> eq = element_equations(model, e);
          mini::ElemVec x_e;
          for (int a = 0; a < mini::kNodes; ++a) {
            for (int k = 0; k < 3; ++k)
              x_e(mini::dof_u(a, k)) = model.state()[kPerNode * tet[a] + k];
            x_e(mini::dof_p(a)) = model.state()[kPerNode * tet[a] + 3];
          }
          mini::MiniLocalSystem sys;
          FE_CHECK(mini::assemble_mini_uncondensed(g, x_e, m, inverse_bulk_modulus,
                                                   mini::BubbleVec::Zero(), sys, true),
                   "P1/P1 tangent: inverted element " << e);
          for (int i = 0; i < mini::kDof; ++i)
            for (int j = 0; j < mini::kDof; ++j)
              if (eq[i] >= 0 && eq[j] >= 0) entries.emplace_back(eq[i], eq[j], sys.K_xx(i, j));
        }
      },
      material);
  SparseMatrix result(model.n_free(), model.n_free());
  result.setFromTriplets(entries.begin(), entries.end());
  return result;
}

SaddlePointBlocks split_blocks(const SparseMatrix& K, const MixedModel& model) {
  const Mesh& mesh = model.mesh();
  const DofMap& dofs = model.dofs();
  // Position of each free equation inside its block (displacement or pressure).
  std::vector<int> position(model.n_free(), -1);
  std::vector<bool> is_pressure(model.n_free(), false);
  int n_u = 0, n_p = 0;
  SaddlePointBlocks blocks;
  std::vector<int> pressure_position(mesh.n_nodes(), -1);
  for (int v = 0; v < mesh.n_nodes(); ++v)
    for (int k = 0; k < kPerNode; ++k) {
      const int eq = dofs.equation(DofMap::dof(v, k));
      if (eq < 0) continue;
      if (k == 3) {
        is_pressure[eq] = true;
        pressure_position[v] = n_p;
        blocks.pressure_node.push_back(v);
        position[eq] = n_p++;
      } else {
        position[eq] = n_u++;
      }
    }
  std::vector<Eigen::Triplet<double>> a_entries;
  blocks.B = Eigen::MatrixXd::Zero(n_p, n_u);
  blocks.C = Eigen::MatrixXd::Zero(n_p, n_p);
  for (int col = 0; col < K.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
      const int i = static_cast<int>(it.row()), j = static_cast<int>(it.col());
      if (!is_pressure[i] && !is_pressure[j])
        a_entries.emplace_back(position[i], position[j], it.value());
      else if (is_pressure[i] && !is_pressure[j])
        blocks.B(position[i], position[j]) = it.value();
      else if (is_pressure[i] && is_pressure[j])
        blocks.C(position[i], position[j]) = -it.value();
    }
  blocks.A.resize(n_u, n_u);
  blocks.A.setFromTriplets(a_entries.begin(), a_entries.end());
  blocks.M = Eigen::MatrixXd::Zero(n_p, n_p);
  for (const auto& tet : mesh.tets) {
    const Vec3d X0 = mesh.nodes[tet[0]];
    const double V =
        (mesh.nodes[tet[1]] - X0).cross(mesh.nodes[tet[2]] - X0).dot(mesh.nodes[tet[3]] - X0) / 6.0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const int i = pressure_position[tet[a]], j = pressure_position[tet[b]];
        if (i >= 0 && j >= 0) blocks.M(i, j) += V * (a == b ? 2.0 : 1.0) / 20.0;
      }
  }
  return blocks;
}

SchurSpectrum schur_spectrum(const SaddlePointBlocks& blocks) {
  SchurSpectrum spectrum;
  Eigen::SimplicialLLT<SparseMatrix> A_factor(blocks.A);
  spectrum.A_positive_definite = A_factor.info() == Eigen::Success;
  if (!spectrum.A_positive_definite) return spectrum;
  const Eigen::MatrixXd A_inv_Bt = A_factor.solve(Eigen::MatrixXd(blocks.B.transpose()));
  Eigen::MatrixXd S = blocks.B * A_inv_Bt + blocks.C;
  S = 0.5 * (S + S.transpose()).eval();  // symmetric up to round-off
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(S, blocks.M);
  spectrum.eigenvalues = solver.eigenvalues();
  spectrum.eigenvectors = solver.eigenvectors();
  return spectrum;
}

double checkerboard_indicator(const Mesh& mesh, const std::vector<double>& values) {
  std::set<std::pair<int, int>> edges;
  for (const auto& tet : mesh.tets)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        edges.emplace(std::min(tet[a], tet[b]), std::max(tet[a], tet[b]));
  double mean = 0.0;
  for (double v : values) mean += v;
  mean /= static_cast<double>(values.size());
  double jumps = 0.0, energy = 0.0;
  for (const auto& [i, j] : edges) {
    jumps += (values[i] - values[j]) * (values[i] - values[j]);
    energy += (values[i] - mean) * (values[i] - mean) + (values[j] - mean) * (values[j] - mean);
  }
  return jumps / energy;
}

}  // namespace plisse::test
