#include "solver/mixed_model.hpp"

#include <algorithm>
#include <array>
#include <set>

#include "solver/petsc_call.hpp"

namespace plisse {
namespace {
/// Keeps the first failed element, or else the one with the smallest J.
void track(AssemblyStatus& status, const mini::ElementStatus& s, int e) {
  if (!status.ok) return;
  if (!s.ok || s.min_J < status.min_J) {
    status.ok = s.ok;
    status.min_J = s.min_J;
    status.worst_element = e;
  }
}
int count_global_unknowns(const std::vector<std::unique_ptr<ModelTerm>>& terms) {
  int n = 0;
  for (const auto& term : terms) n += term->n_global_unknowns();
  return n;
}

/// Tangent entries by full-state index into the free-dof PETSc matrix.
class EquationSink : public TangentSink {
 public:
  EquationSink(Mat K, const DofMap& dofs) : K_(K), dofs_(dofs) {}
  void add(std::span<const int> rows, std::span<const int> cols,
           std::span<const double> values) override {
    rows_.resize(rows.size());
    cols_.resize(cols.size());
    for (size_t i = 0; i < rows.size(); ++i) rows_[i] = dofs_.equation(rows[i]);
    for (size_t j = 0; j < cols.size(); ++j) cols_[j] = dofs_.equation(cols[j]);
    PLISSE_PETSC(MatSetValues(K_, static_cast<PetscInt>(rows.size()), rows_.data(),
                              static_cast<PetscInt>(cols.size()), cols_.data(), values.data(),
                              ADD_VALUES));
  }

 private:
  Mat K_;
  const DofMap& dofs_;
  std::vector<PetscInt> rows_, cols_;
};
}  // namespace

bool MixedModel::symmetric() const {
  for (const auto& term : terms_)
    if (!term->symmetric()) return false;
  return true;
}

MixedModel::MixedModel(const Mesh& mesh, AnyMaterial material, double inverse_bulk_modulus,
                       std::vector<ConstrainedComponent> constraints,
                       std::vector<std::unique_ptr<ModelTerm>> terms)
    : mesh_(mesh),
      material_(std::move(material)),
      inverse_bulk_modulus_(inverse_bulk_modulus),
      constraints_(std::move(constraints)),
      terms_(std::move(terms)),
      dofs_(mesh.n_nodes(), count_global_unknowns(terms_), constraints_),
      state_(dofs_.n_dofs(), 0.0),
      bubble_(mesh.n_tets(), mini::BubbleVec::Zero()),
      full_residual_(state_.size(), 0.0) {
  int next_global = 0;
  for (auto& term : terms_) {
    term->set_first_global_dof(dofs_.global_dof(next_global));
    next_global += term->n_global_unknowns();
  }
  geometry_.reserve(mesh.n_tets());
  for (const auto& tet : mesh.tets)
    geometry_.push_back(mini::compute_tet_geometry(
        {mesh.nodes[tet[0]], mesh.nodes[tet[1]], mesh.nodes[tet[2]], mesh.nodes[tet[3]]}));
  save_converged();
}

void MixedModel::set_time(double t) {
  time_ = t;
  for (const auto& c : constraints_) state_[DofMap::dof(c.node, c.component)] = c.at(t);
}

void MixedModel::set_external_force(std::vector<double> force, Ramp ramp) {
  FE_CHECK(force.size() == state_.size(), "external force has " << force.size()
                                              << " entries, the model " << state_.size() << " dofs");
  external_force_ = std::move(force);
  external_ramp_ = ramp;
}

void MixedModel::get_free(Vec x) const {
  PetscScalar* a = nullptr;
  PLISSE_PETSC(VecGetArray(x, &a));
  for (int d = 0; d < dofs_.n_dofs(); ++d)
    if (const int eq = dofs_.equation(d); eq >= 0) a[eq] = state_[d];
  PLISSE_PETSC(VecRestoreArray(x, &a));
}

void MixedModel::set_free(Vec x) {
  const PetscScalar* a = nullptr;
  PLISSE_PETSC(VecGetArrayRead(x, &a));
  for (int d = 0; d < dofs_.n_dofs(); ++d)
    if (const int eq = dofs_.equation(d); eq >= 0) state_[d] = a[eq];
  PLISSE_PETSC(VecRestoreArrayRead(x, &a));
}

void MixedModel::element_dofs(int e, std::array<int, mini::kDof>& full) const {
  const auto& tet = mesh_.tets[e];
  for (int a = 0; a < mini::kNodes; ++a) {
    for (int k = 0; k < 3; ++k) full[3 * a + k] = DofMap::dof(tet[a], k);
    full[mini::kDofU + a] = DofMap::dof(tet[a], 3);
  }
}

mini::ElemVec MixedModel::gather(const std::array<int, mini::kDof>& full) const {
  mini::ElemVec x;
  for (int i = 0; i < mini::kDof; ++i) x[i] = state_[full[i]];
  return x;
}

AssemblyStatus MixedModel::assemble_residual(Vec f) {
  AssemblyStatus status;
  std::fill(full_residual_.begin(), full_residual_.end(), 0.0);
  std::visit(
      [&](const auto& material) {
        std::array<int, mini::kDof> full;
        mini::ElemVec r;
        for (int e = 0; e < mesh_.n_tets(); ++e) {
          element_dofs(e, full);
          const mini::ElementStatus s =
              mini::assemble_mini(geometry_[e], gather(full), material, inverse_bulk_modulus_,
                                  bubble_[e], r, nullptr);
          track(status, s, e);
          for (int i = 0; i < mini::kDof; ++i) full_residual_[full[i]] += r[i];
        }
      },
      material_);
  for (auto& term : terms_) term->assemble(time_, state_, full_residual_, nullptr);
  if (!external_force_.empty()) {
    const double factor = external_ramp_.factor(time_);
    for (size_t d = 0; d < full_residual_.size(); ++d) full_residual_[d] -= factor * external_force_[d];
  }
  PetscScalar* a = nullptr;
  PLISSE_PETSC(VecGetArray(f, &a));
  for (int d = 0; d < dofs_.n_dofs(); ++d)
    if (const int eq = dofs_.equation(d); eq >= 0) a[eq] = full_residual_[d];
  PLISSE_PETSC(VecRestoreArray(f, &a));
  return status;
}

AssemblyStatus MixedModel::assemble_tangent(Mat K) {
  AssemblyStatus status;
  PLISSE_PETSC(MatZeroEntries(K));
  std::visit(
      [&](const auto& material) {
        std::array<int, mini::kDof> full;
        std::array<PetscInt, mini::kDof> rows;
        mini::ElemVec r;
        mini::ElemMat k;
        Eigen::Matrix<double, mini::kDof, mini::kDof, Eigen::RowMajor> k_row;
        for (int e = 0; e < mesh_.n_tets(); ++e) {
          element_dofs(e, full);
          const mini::ElementStatus s = mini::assemble_mini(
              geometry_[e], gather(full), material, inverse_bulk_modulus_, bubble_[e], r, &k);
          track(status, s, e);
          for (int i = 0; i < mini::kDof; ++i) rows[i] = dofs_.equation(full[i]);
          k_row = k;  // PETSc takes row-major blocks; negative indices (constrained) are skipped
          PLISSE_PETSC(MatSetValues(K, mini::kDof, rows.data(), mini::kDof, rows.data(),
                                    k_row.data(), ADD_VALUES));
        }
      },
      material_);
  if (!terms_.empty()) {
    // Terms add residual and tangent together; their residual part is discarded here.
    std::vector<double> scratch(state_.size(), 0.0);
    EquationSink sink(K, dofs_);
    for (auto& term : terms_) term->assemble(time_, state_, scratch, &sink);
  }
  PLISSE_PETSC(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY));
  PLISSE_PETSC(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY));
  return status;
}

Mat MixedModel::create_matrix() const {
  // Exact nonzeros per free row: the free dofs of all nodes sharing a tet with the row's node.
  const int n_nodes = mesh_.n_nodes();
  std::vector<std::set<int>> neighbours(n_nodes);
  for (const auto& tet : mesh_.tets)
    for (int a : tet)
      for (int b : tet) neighbours[a].insert(b);
  std::vector<int> free_per_node(n_nodes, 0);
  for (int v = 0; v < n_nodes; ++v)
    for (int k = 0; k < DofMap::kPerNode; ++k) free_per_node[v] += dofs_.equation(DofMap::dof(v, k)) >= 0;
  std::vector<PetscInt> nnz(dofs_.n_free(), 0);
  for (int v = 0; v < n_nodes; ++v) {
    int count = 0;
    for (int w : neighbours[v]) count += free_per_node[w];
    for (int k = 0; k < DofMap::kPerNode; ++k)
      if (const int eq = dofs_.equation(DofMap::dof(v, k)); eq >= 0) nnz[eq] = count;
  }
  // Couplings of the terms beyond the elements (an upper bound: duplicates only over-allocate).
  std::vector<std::pair<int, int>> couplings;
  for (const auto& term : terms_) term->add_couplings(couplings);
  for (const auto& [row, col] : couplings)
    if (dofs_.equation(row) >= 0 && dofs_.equation(col) >= 0) ++nnz[dofs_.equation(row)];
  for (PetscInt& n : nnz) n = std::min<PetscInt>(std::max<PetscInt>(n, 1), dofs_.n_free());
  Mat K = nullptr;
  PLISSE_PETSC(MatCreateSeqAIJ(PETSC_COMM_SELF, dofs_.n_free(), dofs_.n_free(), 0, nnz.data(), &K));
  PLISSE_PETSC(MatSetOption(K, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  if (symmetric()) {
    PLISSE_PETSC(MatSetOption(K, MAT_SYMMETRIC, PETSC_TRUE));
    PLISSE_PETSC(MatSetOption(K, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  }
  return K;
}

bool MixedModel::update_multipliers() {
  bool again = false;
  for (auto& term : terms_) again = term->update_multipliers(state_) || again;
  return again;
}

MixedModel::Snapshot MixedModel::snapshot() const {
  Snapshot s;
  s.state = converged_state_;
  s.bubbles.reserve(converged_bubble_.size() * mini::kDofBubble);
  for (const auto& b : converged_bubble_) s.bubbles.insert(s.bubbles.end(), b.data(), b.data() + b.size());
  for (const auto& term : terms_) s.term_states.push_back(term->save_state());
  return s;
}

void MixedModel::restore(const Snapshot& s) {
  FE_CHECK(s.state.size() == state_.size() &&
               s.bubbles.size() == bubble_.size() * mini::kDofBubble &&
               s.term_states.size() == terms_.size(),
           "the checkpoint does not fit this model (" << s.state.size() << " values for "
                                                      << state_.size() << " dofs)");
  state_ = s.state;
  for (size_t e = 0; e < bubble_.size(); ++e)
    bubble_[e] = Eigen::Map<const mini::BubbleVec>(s.bubbles.data() + e * mini::kDofBubble);
  for (size_t k = 0; k < terms_.size(); ++k) terms_[k]->load_state(s.term_states[k]);
  converged_state_ = state_;
  converged_bubble_ = bubble_;
}

void MixedModel::save_converged() {
  converged_state_ = state_;
  converged_bubble_ = bubble_;
  for (auto& term : terms_) term->accept_step(state_);
}

void MixedModel::restore_converged() {
  state_ = converged_state_;
  bubble_ = converged_bubble_;
  for (auto& term : terms_) term->reject_step();
}

Vec3d MixedModel::reaction(const std::vector<int>& triangles) const {
  std::set<int> nodes;
  for (int t : triangles)
    for (int v : mesh_.triangles[t]) nodes.insert(v);
  Vec3d force = Vec3d::Zero();
  for (int v : nodes)
    for (int k = 0; k < 3; ++k)
      if (dofs_.equation(DofMap::dof(v, k)) < 0) force[k] += full_residual_[DofMap::dof(v, k)];
  return force;
}

std::vector<mini::ElementFields> MixedModel::element_fields() const {
  std::vector<mini::ElementFields> out(mesh_.n_tets());
  std::visit(
      [&](const auto& material) {
        std::array<int, mini::kDof> full;
        for (int e = 0; e < mesh_.n_tets(); ++e) {
          element_dofs(e, full);
          out[e] = mini::compute_element_fields(geometry_[e], gather(full), material, bubble_[e]);
        }
      },
      material_);
  return out;
}

BodyAverages MixedModel::averages() const {
  BodyAverages avg;
  avg.F.setZero();
  double reference_volume = 0.0;
  const auto fields = element_fields();
  for (int e = 0; e < mesh_.n_tets(); ++e) {
    const auto& tet = mesh_.tets[e];
    const Vec3d X0 = mesh_.nodes[tet[0]];
    Mat3d dX, dx;
    for (int a = 1; a < 4; ++a) {
      dX.col(a - 1) = mesh_.nodes[tet[a]] - X0;
      dx.col(a - 1) = dX.col(a - 1);
      for (int k = 0; k < 3; ++k)
        dx(k, a - 1) += state_[DofMap::dof(tet[a], k)] - state_[DofMap::dof(tet[0], k)];
    }
    const double V0 = dX.determinant() / 6.0;
    // The bubble vanishes on the element boundary, so the mean of F over the tet is the F of its
    // linear part: F_mean = dx dX^-1 (divergence theorem).
    avg.F += V0 * dx * dX.inverse();
    const double v = fields[e].J * V0;
    avg.cauchy += v * fields[e].cauchy;
    avg.volume += v;
    reference_volume += V0;
  }
  avg.F /= reference_volume;
  if (avg.volume > 0) avg.cauchy /= avg.volume;
  return avg;
}

}  // namespace plisse
