#include "solver/mixed_model.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <exception>
#include <limits>
#include <set>

#include "element/strain_energy.hpp"
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

/// Elements evaluated per chunk of the element loop (results 2.2 kB each: 9 MB of buffer). Each
/// chunk ends in a barrier, which waits for the slowest thread: on a machine with more runnable
/// processes than cores a descheduled thread holds it for a whole time slice, so chunks are large
/// (with 512 a 2-thread residual was 8 times slower than a serial one under such load).
constexpr int kChunkElements = 4096;

/// The default thread count: OpenMP's count as the process started when OMP_NUM_THREADS asks for
/// one, else 1 (threads pay only on cores nobody else uses; see docs/performance.md). Read during
/// static initialisation: Gmsh's initialisation later sets OpenMP's count to its own
/// General.NumThreads (1 by default), which would override OMP_NUM_THREADS.
const int kOpenMPThreadsAtStart = std::getenv("OMP_NUM_THREADS") ? omp_get_max_threads() : 1;

/// Local node (0..3) of element unknown i of x_e (mini_layout.hpp).
constexpr int local_node(int i) { return i < mini::kDofU ? i / 3 : i - mini::kDofU; }

/// Tangent entries by full-state index into any PETSc matrix, through MatSetValues.
class EquationSink : public TangentSink {
 public:
  EquationSink(Mat K, const DofMap& dofs, std::vector<PetscInt>& scratch)
      : K_(K), dofs_(dofs), equations_(scratch) {}
  void add(std::span<const int> rows, std::span<const int> cols,
           std::span<const double> values) override {
    equations_.resize(rows.size() + cols.size());  // capacity kept between calls: no allocation
    for (size_t i = 0; i < rows.size(); ++i) equations_[i] = dofs_.equation(rows[i]);
    for (size_t j = 0; j < cols.size(); ++j) equations_[rows.size() + j] = dofs_.equation(cols[j]);
    // Negative (constrained) indices are skipped by PETSc.
    PLISSE_PETSC(MatSetValues(K_, static_cast<PetscInt>(rows.size()), equations_.data(),
                              static_cast<PetscInt>(cols.size()), equations_.data() + rows.size(),
                              values.data(), ADD_VALUES));
  }

 private:
  Mat K_;
  const DofMap& dofs_;
  std::vector<PetscInt>& equations_;
};

/// Tangent entries by full-state index added straight into the value array of an AIJ matrix
/// (row starts `ia`, sorted columns `ja`), found by binary search in the row. The terms touch few
/// entries, so no positions are stored for them.
class ArraySink : public TangentSink {
 public:
  ArraySink(const PetscInt* ia, const PetscInt* ja, PetscScalar* values, const DofMap& dofs)
      : ia_(ia), ja_(ja), values_(values), dofs_(dofs) {}
  void add(std::span<const int> rows, std::span<const int> cols,
           std::span<const double> values) override {
    for (size_t i = 0; i < rows.size(); ++i) {
      const int row = dofs_.equation(rows[i]);
      if (row < 0) continue;
      const PetscInt* begin = ja_ + ia_[row];
      const PetscInt* end = ja_ + ia_[row + 1];
      for (size_t j = 0; j < cols.size(); ++j) {
        const int col = dofs_.equation(cols[j]);
        if (col < 0) continue;
        const PetscInt* at = std::lower_bound(begin, end, static_cast<PetscInt>(col));
        FE_CHECK(at != end && *at == col,
                 "a model term adds the tangent entry (" << rows[i] << ", " << cols[j]
                     << ") outside the couplings it declares (ModelTerm::add_couplings)");
        values_[at - ja_] += values[i * cols.size() + j];
      }
    }
  }

 private:
  const PetscInt* ia_;
  const PetscInt* ja_;
  PetscScalar* values_;
  const DofMap& dofs_;
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
  build_tangent_layout();
  save_converged();
}

int MixedModel::assembly_threads() const {
  return threads_ > 0 ? threads_ : std::max(1, kOpenMPThreadsAtStart);
}

void MixedModel::build_tangent_layout() {
  const int n_nodes = mesh_.n_nodes();
  const int n_nodal = DofMap::kPerNode * n_nodes;
  node_free_.assign(n_nodes, 0);
  node_first_equation_.assign(n_nodes, -1);
  for (int v = 0; v < n_nodes; ++v)
    for (int k = DofMap::kPerNode - 1; k >= 0; --k)
      if (const int eq = dofs_.equation(DofMap::dof(v, k)); eq >= 0) {
        ++node_free_[v];
        node_first_equation_[v] = eq;
      }
  // Node graph: the nodes of each tet couple, each node couples itself, and so do the nodes of
  // the terms' declared couplings. Filled by counting, then sorted and made unique per node.
  std::vector<std::pair<int, int>> couplings;
  for (const auto& term : terms_) term->add_couplings(couplings);
  std::vector<int> count(n_nodes + 1, 0);
  for (const auto& tet : mesh_.tets)
    for (int a : tet) count[a + 1] += 4;
  for (int v = 0; v < n_nodes; ++v) ++count[v + 1];
  for (const auto& [row, col] : couplings)
    if (row < n_nodal && col < n_nodal) ++count[row / DofMap::kPerNode + 1];
  for (int v = 0; v < n_nodes; ++v) count[v + 1] += count[v];
  std::vector<int> fill(count.begin(), count.end() - 1);
  std::vector<int> all(count[n_nodes]);
  for (const auto& tet : mesh_.tets)
    for (int a : tet)
      for (int b : tet) all[fill[a]++] = b;
  for (int v = 0; v < n_nodes; ++v) all[fill[v]++] = v;
  for (const auto& [row, col] : couplings)
    if (row < n_nodal && col < n_nodal)
      all[fill[row / DofMap::kPerNode]++] = col / DofMap::kPerNode;
  node_start_.assign(n_nodes + 1, 0);
  node_neighbours_.clear();
  node_neighbours_.reserve(all.size() / 3);
  for (int v = 0; v < n_nodes; ++v) {
    auto begin = all.begin() + count[v], end = all.begin() + count[v + 1];
    std::sort(begin, end);
    node_neighbours_.insert(node_neighbours_.end(), begin, std::unique(begin, end));
    node_start_[v + 1] = static_cast<int>(node_neighbours_.size());
  }
  // Couplings that involve a global unknown, and the diagonal of every free global unknown. Their
  // equations follow all nodal ones, so in a nodal row they come after the node columns.
  extra_entries_.clear();
  for (const auto& [row, col] : couplings) {
    const int r = dofs_.equation(row), c = dofs_.equation(col);
    if ((row >= n_nodal || col >= n_nodal) && r >= 0 && c >= 0) extra_entries_.emplace_back(r, c);
  }
  for (int d = n_nodal; d < dofs_.n_dofs(); ++d)
    if (const int eq = dofs_.equation(d); eq >= 0) extra_entries_.emplace_back(eq, eq);
  std::sort(extra_entries_.begin(), extra_entries_.end());
  extra_entries_.erase(std::unique(extra_entries_.begin(), extra_entries_.end()), extra_entries_.end());
  // Row lengths: the free columns of the neighbour nodes, then the extra entries of the row.
  const int n_free = dofs_.n_free();
  std::vector<int> node_columns(n_nodes, 0);
  std::vector<int> length(n_free, 0);
  for (int v = 0; v < n_nodes; ++v) {
    for (int k = node_start_[v]; k < node_start_[v + 1]; ++k) node_columns[v] += node_free_[node_neighbours_[k]];
    for (int i = 0; i < node_free_[v]; ++i) length[node_first_equation_[v] + i] = node_columns[v];
  }
  for (const auto& [row, col] : extra_entries_) ++length[row];
  row_start_.assign(n_free + 1, 0);
  for (int eq = 0; eq < n_free; ++eq) row_start_[eq + 1] = row_start_[eq] + length[eq];
  FE_CHECK(row_start_[n_free] <= std::numeric_limits<int>::max(),
           "the tangent has " << row_start_[n_free] << " nonzeros, more than 32-bit positions hold");
  // Per element and local node pair (a, b): where node b's run of columns starts in a row of node
  // a, minus b's first equation, so that adding a column's equation gives its position.
  element_shift_.resize(mesh_.n_tets());
  for (int e = 0; e < mesh_.n_tets(); ++e) {
    const auto& tet = mesh_.tets[e];
    for (int a = 0; a < mini::kNodes; ++a) {
      const int* begin = node_neighbours_.data() + node_start_[tet[a]];
      for (int b = 0; b < mini::kNodes; ++b) {
        int offset = 0;
        for (const int* w = begin; *w != tet[b]; ++w) offset += node_free_[*w];
        element_shift_[e][4 * a + b] = node_free_[tet[b]] > 0 ? offset - node_first_equation_[tet[b]] : 0;
      }
    }
  }
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

template <class Scatter>
AssemblyStatus MixedModel::for_each_element(bool with_tangent, Scatter&& scatter) {
  AssemblyStatus status;
  const int n = mesh_.n_tets();
  chunk_.resize(std::min(n, kChunkElements));
  const int threads = assembly_threads();
  std::visit(
      [&](const auto& material) {
        for (int first = 0; first < n; first += kChunkElements) {
          const int last = std::min(n, first + kChunkElements);
          std::exception_ptr error;
          // Elements differ in cost (local bubble iterations) and the machine may be shared:
          // small dynamic batches. Each element writes only its own result and bubble.
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
          for (int e = first; e < last; ++e) {
            try {
              std::array<int, mini::kDof> full;
              element_dofs(e, full);
              ElementResult& out = chunk_[e - first];
              out.status = mini::assemble_mini(geometry_[e], gather(full), material,
                                               inverse_bulk_modulus_, bubble_[e], out.r,
                                               with_tangent ? &out.K : nullptr);
            } catch (...) {
#pragma omp critical(plisse_element_loop_error)
              if (!error) error = std::current_exception();
            }
          }
          if (error) std::rethrow_exception(error);
          for (int e = first; e < last; ++e) {
            track(status, chunk_[e - first].status, e);
            scatter(e, chunk_[e - first]);
          }
        }
      },
      material_);
  return status;
}

AssemblyStatus MixedModel::assemble_residual(Vec f) {
  std::fill(full_residual_.begin(), full_residual_.end(), 0.0);
  const AssemblyStatus status = for_each_element(false, [&](int e, const ElementResult& out) {
    std::array<int, mini::kDof> full;
    element_dofs(e, full);
    for (int i = 0; i < mini::kDof; ++i) full_residual_[full[i]] += out.r[i];
  });
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

bool MixedModel::has_tangent_layout(Mat K) const {
  PetscBool seqaij = PETSC_FALSE;
  PLISSE_PETSC(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(K), MATSEQAIJ, &seqaij));
  if (!seqaij) return false;
  PetscInt n = 0;
  const PetscInt *ia = nullptr, *ja = nullptr;
  PetscBool done = PETSC_FALSE;
  PLISSE_PETSC(MatGetRowIJ(K, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  const bool same = done && n == dofs_.n_free() && std::equal(row_start_.begin(), row_start_.end(), ia);
  PLISSE_PETSC(MatRestoreRowIJ(K, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  return same;
}

AssemblyStatus MixedModel::assemble_tangent(Mat K) {
  AssemblyStatus status;
  PLISSE_PETSC(MatZeroEntries(K));
  term_residual_.assign(state_.size(), 0.0);  // the terms' residual part is discarded here
  if (has_tangent_layout(K)) {
    PetscInt n = 0;
    const PetscInt *ia = nullptr, *ja = nullptr;
    PetscBool done = PETSC_FALSE;
    PetscScalar* values = nullptr;
    PLISSE_PETSC(MatGetRowIJ(K, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
    PLISSE_PETSC(MatSeqAIJGetArray(K, &values));
    // Each entry receives its element contributions in element order, then the terms', exactly
    // as MatSetValues(ADD_VALUES) would add them: the same bits.
    status = for_each_element(true, [&](int e, const ElementResult& out) {
      std::array<int, mini::kDof> full, eq;
      element_dofs(e, full);
      for (int i = 0; i < mini::kDof; ++i) eq[i] = dofs_.equation(full[i]);
      const std::array<int, 16>& shift = element_shift_[e];
      for (int i = 0; i < mini::kDof; ++i) {
        if (eq[i] < 0) continue;
        PetscScalar* row = values + ia[eq[i]];
        const int* row_shift = shift.data() + 4 * local_node(i);
        for (int j = 0; j < mini::kDof; ++j)
          if (eq[j] >= 0) row[row_shift[local_node(j)] + eq[j]] += out.K(i, j);
      }
    });
    ArraySink sink(ia, ja, values, dofs_);
    for (auto& term : terms_) term->assemble(time_, state_, term_residual_, &sink);
    PLISSE_PETSC(MatSeqAIJRestoreArray(K, &values));
    PLISSE_PETSC(MatRestoreRowIJ(K, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  } else {
    std::vector<PetscInt>& rows = equations_;
    Eigen::Matrix<double, mini::kDof, mini::kDof, Eigen::RowMajor> k_row;
    status = for_each_element(true, [&](int e, const ElementResult& out) {
      std::array<int, mini::kDof> full;
      element_dofs(e, full);
      rows.resize(mini::kDof);
      for (int i = 0; i < mini::kDof; ++i) rows[i] = dofs_.equation(full[i]);
      k_row = out.K;  // PETSc takes row-major blocks; negative indices (constrained) are skipped
      PLISSE_PETSC(MatSetValues(K, mini::kDof, rows.data(), mini::kDof, rows.data(), k_row.data(),
                                ADD_VALUES));
    });
    EquationSink sink(K, dofs_, equations_);
    for (auto& term : terms_) term->assemble(time_, state_, term_residual_, &sink);
  }
  PLISSE_PETSC(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY));
  PLISSE_PETSC(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY));
  return status;
}

Mat MixedModel::create_matrix() const {
  const int n_free = dofs_.n_free();
  std::vector<PetscInt> columns(row_start_[n_free]);
  std::vector<PetscInt> fill(row_start_.begin(), row_start_.end() - 1);
  for (int v = 0; v < mesh_.n_nodes(); ++v)
    for (int i = 0; i < node_free_[v]; ++i) {
      const int row = node_first_equation_[v] + i;
      for (int k = node_start_[v]; k < node_start_[v + 1]; ++k) {
        const int w = node_neighbours_[k];
        for (int c = 0; c < node_free_[w]; ++c) columns[fill[row]++] = node_first_equation_[w] + c;
      }
    }
  for (const auto& [row, col] : extra_entries_) columns[fill[row]++] = col;
  Mat K = nullptr;
  PLISSE_PETSC(MatCreate(PETSC_COMM_SELF, &K));
  PLISSE_PETSC(MatSetSizes(K, n_free, n_free, n_free, n_free));
  PLISSE_PETSC(MatSetType(K, MATSEQAIJ));
  PLISSE_PETSC(MatSeqAIJSetPreallocationCSR(K, row_start_.data(), columns.data(), nullptr));
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
  const int n = mesh_.n_tets(), threads = assembly_threads();
  std::exception_ptr error;
  std::visit(
      [&](const auto& material) {
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads)
        for (int e = 0; e < n; ++e) {
          try {
            std::array<int, mini::kDof> full;
            element_dofs(e, full);
            out[e] = mini::compute_element_fields(geometry_[e], gather(full), material, bubble_[e]);
          } catch (...) {
#pragma omp critical(plisse_element_fields_error)
            if (!error) error = std::current_exception();
          }
        }
      },
      material_);
  if (error) std::rethrow_exception(error);
  return out;
}

double MixedModel::strain_energy() const {
  double energy = 0.0;
  for (int e = 0; e < mesh_.n_tets(); ++e) {
    std::array<int, mini::kDof> full;
    element_dofs(e, full);
    energy += mini::compute_strain_energy(geometry_[e], gather(full), material_,
                                          inverse_bulk_modulus_, bubble_[e])
                  .total();
  }
  return energy;
}

BodyAverages MixedModel::averages() const { return averages(element_fields()); }

BodyAverages MixedModel::averages(const std::vector<mini::ElementFields>& fields) const {
  FE_CHECK(fields.size() == static_cast<std::size_t>(mesh_.n_tets()),
           "averages: " << fields.size() << " element fields for " << mesh_.n_tets() << " elements");
  BodyAverages avg;
  avg.F.setZero();
  double reference_volume = 0.0;
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
