#include "solver/mixed_model.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <exception>
#include <limits>
#include <set>

#include "element/strain_energy.hpp"
#include "solver/partition.hpp"
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
  /// Rows outside [first, end) are someone else's (distributed runs): skipped.
  EquationSink(Mat K, const DofMap& dofs, int first, int end, std::vector<PetscInt>& scratch)
      : K_(K), dofs_(dofs), first_(first), end_(end), equations_(scratch) {}
  void add(std::span<const int> rows, std::span<const int> cols,
           std::span<const double> values) override {
    equations_.resize(rows.size() + cols.size());  // capacity kept between calls: no allocation
    for (size_t i = 0; i < rows.size(); ++i) {
      const int eq = dofs_.equation(rows[i]);
      equations_[i] = eq >= first_ && eq < end_ ? eq : -1;
    }
    for (size_t j = 0; j < cols.size(); ++j) equations_[rows.size() + j] = dofs_.equation(cols[j]);
    // Negative (constrained) indices are skipped by PETSc.
    PLISSE_PETSC(MatSetValues(K_, static_cast<PetscInt>(rows.size()), equations_.data(),
                              static_cast<PetscInt>(cols.size()), equations_.data() + rows.size(),
                              values.data(), ADD_VALUES));
  }

 private:
  Mat K_;
  const DofMap& dofs_;
  int first_, end_;
  std::vector<PetscInt>& equations_;
};

/// Tangent entries by full-state index added straight into the value array of the owned rows
/// [first, end) of an AIJ matrix (local row starts `ia`, sorted columns `ja`), found by binary
/// search in the row. The terms touch few entries, so no positions are stored for them.
class ArraySink : public TangentSink {
 public:
  ArraySink(const PetscInt* ia, const PetscInt* ja, PetscScalar* values, const DofMap& dofs,
            int first, int end)
      : ia_(ia), ja_(ja), values_(values), dofs_(dofs), first_(first), end_(end) {}
  void add(std::span<const int> rows, std::span<const int> cols,
           std::span<const double> values) override {
    for (size_t i = 0; i < rows.size(); ++i) {
      const int equation = dofs_.equation(rows[i]);
      if (equation < first_ || equation >= end_) continue;
      const int row = equation - first_;
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
  int first_, end_;
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
  // (row, column) full-state dofs the terms couple, beyond the elements.
  std::vector<std::pair<int, int>> couplings;
  for (const auto& term : terms_) term->add_couplings(couplings);
  build_node_graph(couplings);
  distribute();
  build_tangent_layout(couplings);
  save_converged();
}

MixedModel::~MixedModel() {
  VecScatterDestroy(&gather_all_);
  VecDestroy(&gathered_);
}

MPI_Comm MixedModel::comm() const { return size_ > 1 ? PETSC_COMM_WORLD : PETSC_COMM_SELF; }

void MixedModel::distribute() {
  const int n_nodes = mesh_.n_nodes();
  PetscBool initialized = PETSC_FALSE;
  PLISSE_PETSC(PetscInitialized(&initialized));
  if (initialized) {
    PLISSE_PETSC(MPI_Comm_size(PETSC_COMM_WORLD, &size_));
    PLISSE_PETSC(MPI_Comm_rank(PETSC_COMM_WORLD, &rank_));
  }
  node_rank_.assign(n_nodes, 0);
  if (size_ > 1) {
    // Balance the free unknowns (every node has at least its pressure unless constrained).
    std::vector<int> weights(n_nodes, 1);
    for (int v = 0; v < n_nodes; ++v) {
      int free = 0;
      for (int k = 0; k < DofMap::kPerNode; ++k) free += dofs_.equation(DofMap::dof(v, k)) >= 0;
      weights[v] = std::max(1, free);
    }
    node_rank_ = partition_graph(node_start_, node_neighbours_, weights, size_, PETSC_COMM_WORLD);
    std::vector<int> order(n_nodes);
    for (int v = 0; v < n_nodes; ++v) order[v] = v;
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return node_rank_[a] < node_rank_[b]; });
    dofs_ = DofMap(n_nodes, count_global_unknowns(terms_), constraints_, order);
  }
  // Owned range: the free equations of the nodes of lower ranks come first; the last rank also
  // owns the terms' global unknowns, numbered after every node.
  std::vector<int> before(size_ + 1, 0);
  for (int v = 0; v < n_nodes; ++v)
    for (int k = 0; k < DofMap::kPerNode; ++k)
      before[node_rank_[v] + 1] += dofs_.equation(DofMap::dof(v, k)) >= 0;
  for (int r = 0; r < size_; ++r) before[r + 1] += before[r];
  first_equation_ = before[rank_];
  end_equation_ = rank_ == size_ - 1 ? dofs_.n_free() : before[rank_ + 1];
  local_elements_.clear();
  owned_elements_.clear();
  for (int e = 0; e < mesh_.n_tets(); ++e) {
    const auto& tet = mesh_.tets[e];
    if (node_rank_[tet[0]] == rank_) owned_elements_.push_back(e);
    for (int a : tet)
      if (node_rank_[a] == rank_) {
        local_elements_.push_back(e);
        break;
      }
  }
  if (size_ > 1) {
    Vec x = create_vector();
    PLISSE_PETSC(VecScatterCreateToAll(x, &gather_all_, &gathered_));
    PLISSE_PETSC(VecDestroy(&x));
  }
}

Vec MixedModel::create_vector() const {
  Vec x = nullptr;
  if (size_ > 1)
    PLISSE_PETSC(VecCreateMPI(PETSC_COMM_WORLD, n_owned(), dofs_.n_free(), &x));
  else
    PLISSE_PETSC(VecCreateSeq(PETSC_COMM_SELF, dofs_.n_free(), &x));
  return x;
}

template <class Use>
void MixedModel::for_each_free_value(Vec x, Use&& use) const {
  Vec source = x;
  if (size_ > 1) {  // every rank needs every free value
    PLISSE_PETSC(VecScatterBegin(gather_all_, x, gathered_, INSERT_VALUES, SCATTER_FORWARD));
    PLISSE_PETSC(VecScatterEnd(gather_all_, x, gathered_, INSERT_VALUES, SCATTER_FORWARD));
    source = gathered_;
  }
  const PetscScalar* a = nullptr;
  PLISSE_PETSC(VecGetArrayRead(source, &a));
  for (int d = 0; d < dofs_.n_dofs(); ++d)
    if (const int eq = dofs_.equation(d); eq >= 0) use(d, a[eq]);
  PLISSE_PETSC(VecRestoreArrayRead(source, &a));
}

std::vector<double> MixedModel::full_from_free(Vec x) const {
  std::vector<double> full(dofs_.n_dofs(), 0.0);
  for_each_free_value(x, [&](int d, double value) { full[d] = value; });
  return full;
}

AssemblyStatus MixedModel::reduce(const AssemblyStatus& local) const {
  if (size_ == 1) return local;
  // (failed, min J, worst element) of every rank; every rank picks the same one.
  const double mine[3] = {local.ok ? 0.0 : 1.0, local.min_J, static_cast<double>(local.worst_element)};
  std::vector<double> all(3 * size_);
  PLISSE_PETSC(MPI_Allgather(mine, 3, MPI_DOUBLE, all.data(), 3, MPI_DOUBLE, PETSC_COMM_WORLD));
  int pick = -1;
  for (int r = 0; r < size_ && pick < 0; ++r)
    if (all[3 * r] != 0.0) pick = r;
  if (pick < 0) {
    pick = 0;
    for (int r = 1; r < size_; ++r)
      if (all[3 * r + 1] < all[3 * pick + 1]) pick = r;
  }
  AssemblyStatus status;
  status.ok = all[3 * pick] == 0.0;
  status.min_J = all[3 * pick + 1];
  status.worst_element = static_cast<int>(all[3 * pick + 2]);
  return status;
}

void MixedModel::sum_over_ranks(double* values, std::size_t count) const {
  if (size_ == 1 || count == 0) return;
  // In slices: MPI counts are ints.
  constexpr std::size_t kSlice = std::size_t{1} << 28;
  for (std::size_t first = 0; first < count; first += kSlice)
    PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, values + first,
                               static_cast<int>(std::min(kSlice, count - first)), MPI_DOUBLE,
                               MPI_SUM, PETSC_COMM_WORLD));
}

int MixedModel::assembly_threads() const {
  return threads_ > 0 ? threads_ : std::max(1, kOpenMPThreadsAtStart);
}

void MixedModel::build_node_graph(const std::vector<std::pair<int, int>>& couplings) {
  const int n_nodes = mesh_.n_nodes();
  const int n_nodal = DofMap::kPerNode * n_nodes;
  // Node graph: the nodes of each tet couple, each node couples itself, and so do the nodes of
  // the terms' declared couplings. Filled by counting, then sorted and made unique per node.
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
}

void MixedModel::build_tangent_layout(const std::vector<std::pair<int, int>>& couplings) {
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
  const auto owned = [&](int eq) { return eq >= first_equation_ && eq < end_equation_; };
  // Owned couplings that involve a global unknown, and the diagonal of every owned free global
  // unknown. Their equations follow all nodal ones, so in a nodal row they come after the node
  // columns.
  extra_entries_.clear();
  for (const auto& [row, col] : couplings) {
    const int r = dofs_.equation(row), c = dofs_.equation(col);
    if ((row >= n_nodal || col >= n_nodal) && owned(r) && c >= 0) extra_entries_.emplace_back(r, c);
  }
  for (int d = n_nodal; d < dofs_.n_dofs(); ++d)
    if (const int eq = dofs_.equation(d); owned(eq)) extra_entries_.emplace_back(eq, eq);
  std::sort(extra_entries_.begin(), extra_entries_.end());
  extra_entries_.erase(std::unique(extra_entries_.begin(), extra_entries_.end()), extra_entries_.end());
  // Row lengths of the owned rows: the free columns of the neighbour nodes, then the extra
  // entries of the row.
  const int n_rows = n_owned();
  std::vector<int> length(n_rows, 0);
  for (int v = 0; v < n_nodes; ++v) {
    if (node_free_[v] == 0 || !owned(node_first_equation_[v])) continue;
    int columns = 0;
    for (int k = node_start_[v]; k < node_start_[v + 1]; ++k) columns += node_free_[node_neighbours_[k]];
    for (int i = 0; i < node_free_[v]; ++i) length[node_first_equation_[v] + i - first_equation_] = columns;
  }
  for (const auto& [row, col] : extra_entries_) ++length[row - first_equation_];
  row_start_.assign(n_rows + 1, 0);
  for (int r = 0; r < n_rows; ++r) {
    FE_CHECK(row_start_[r] + length[r] <= std::numeric_limits<int>::max(),
             "the tangent has more nonzeros than 32-bit positions hold");
    row_start_[r + 1] = row_start_[r] + length[r];
  }
  // Column equations, sorted within each row (node runs in node order; global unknowns last).
  columns_.assign(row_start_[n_rows], 0);
  std::vector<PetscInt> fill(row_start_.begin(), row_start_.end() - 1);
  for (int v = 0; v < n_nodes; ++v) {
    if (node_free_[v] == 0 || !owned(node_first_equation_[v])) continue;
    for (int i = 0; i < node_free_[v]; ++i) {
      const int row = node_first_equation_[v] + i - first_equation_;
      for (int k = node_start_[v]; k < node_start_[v + 1]; ++k) {
        const int w = node_neighbours_[k];
        for (int c = 0; c < node_free_[w]; ++c) columns_[fill[row]++] = node_first_equation_[w] + c;
      }
    }
  }
  for (const auto& [row, col] : extra_entries_) columns_[fill[row - first_equation_]++] = col;
  // Distributed runs number the nodes by rank, so the node runs of a row are not in increasing
  // equation order: sort each row (PETSc's CSR creation wants sorted columns), keeping each
  // node's run consecutive, so that the element positions below still hold.
  if (size_ > 1)
    for (int r = 0; r < n_rows; ++r) std::sort(columns_.begin() + row_start_[r], columns_.begin() + row_start_[r + 1]);
  // Per local element and local node pair (a, b): where node b's run of columns starts in a row
  // of node a, minus b's first equation, so that adding a column's equation gives its position.
  // The run of b starts where its first equation sits in the (sorted) row.
  element_shift_.assign(mesh_.n_tets(), std::array<int, 16>{});
  for (int e : local_elements_) {
    const auto& tet = mesh_.tets[e];
    for (int a = 0; a < mini::kNodes; ++a) {
      const int first_row = node_first_equation_[tet[a]];
      if (node_free_[tet[a]] == 0 || !owned(first_row)) continue;
      const PetscInt* row_begin = columns_.data() + row_start_[first_row - first_equation_];
      const PetscInt* row_end = columns_.data() + row_start_[first_row - first_equation_ + 1];
      for (int b = 0; b < mini::kNodes; ++b) {
        if (node_free_[tet[b]] == 0) continue;
        const PetscInt* at = std::lower_bound(row_begin, row_end, static_cast<PetscInt>(node_first_equation_[tet[b]]));
        element_shift_[e][4 * a + b] = static_cast<int>(at - row_begin) - node_first_equation_[tet[b]];
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
    if (const int eq = dofs_.equation(d); eq >= first_equation_ && eq < end_equation_)
      a[eq - first_equation_] = state_[d];
  PLISSE_PETSC(VecRestoreArray(x, &a));
}

void MixedModel::set_free(Vec x) {
  for_each_free_value(x, [&](int d, double value) { state_[d] = value; });
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
  const int n = static_cast<int>(local_elements_.size());
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
          for (int k = first; k < last; ++k) {
            try {
              const int e = local_elements_[k];
              std::array<int, mini::kDof> full;
              element_dofs(e, full);
              ElementResult& out = chunk_[k - first];
              out.status = mini::assemble_mini(geometry_[e], gather(full), material,
                                               inverse_bulk_modulus_, bubble_[e], out.r,
                                               with_tangent ? &out.K : nullptr);
            } catch (...) {
#pragma omp critical(plisse_element_loop_error)
              if (!error) error = std::current_exception();
            }
          }
          if (error) std::rethrow_exception(error);
          for (int k = first; k < last; ++k) {
            track(status, chunk_[k - first].status, local_elements_[k]);
            scatter(local_elements_[k], chunk_[k - first]);
          }
        }
      },
      material_);
  return reduce(status);
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
    if (const int eq = dofs_.equation(d); eq >= first_equation_ && eq < end_equation_)
      a[eq - first_equation_] = full_residual_[d];
  PLISSE_PETSC(VecRestoreArray(f, &a));
  return status;
}

bool MixedModel::has_tangent_layout(Mat K) const {
  if (size_ > 1) {
    PetscBool mpiaij = PETSC_FALSE;
    PLISSE_PETSC(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(K), MATMPIAIJ, &mpiaij));
    if (!mpiaij) return false;
    PetscInt first = 0, end = 0;
    PLISSE_PETSC(MatGetOwnershipRange(K, &first, &end));
    if (first != first_equation_ || end != end_equation_) return false;
    // Same number of stored entries in the diagonal and off-diagonal blocks as the layout.
    Mat diagonal = nullptr, off_diagonal = nullptr;
    const PetscInt* garray = nullptr;
    PLISSE_PETSC(MatMPIAIJGetSeqAIJ(K, &diagonal, &off_diagonal, &garray));
    MatInfo d{}, o{};
    PLISSE_PETSC(MatGetInfo(diagonal, MAT_LOCAL, &d));
    PLISSE_PETSC(MatGetInfo(off_diagonal, MAT_LOCAL, &o));
    return static_cast<PetscInt>(d.nz_allocated + o.nz_allocated) == row_start_.back();
  }
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
  term_residual_.assign(state_.size(), 0.0);  // the terms' residual part is discarded here
  const int first = first_equation_, end = end_equation_;
  if (has_tangent_layout(K)) {
    // The owned rows' values: the matrix's own array on one rank, else a local copy handed to
    // the distributed matrix at the end.
    PetscScalar* values = nullptr;
    if (size_ > 1) {
      local_values_.assign(row_start_.back(), 0.0);
      values = local_values_.data();
    } else {
      PLISSE_PETSC(MatZeroEntries(K));
      PLISSE_PETSC(MatSeqAIJGetArray(K, &values));
    }
    const PetscInt* ia = row_start_.data();
    // Each entry receives its element contributions in element order, then the terms', exactly
    // as MatSetValues(ADD_VALUES) would add them: the same bits.
    status = for_each_element(true, [&](int e, const ElementResult& out) {
      std::array<int, mini::kDof> full, eq;
      element_dofs(e, full);
      for (int i = 0; i < mini::kDof; ++i) eq[i] = dofs_.equation(full[i]);
      const std::array<int, 16>& shift = element_shift_[e];
      for (int i = 0; i < mini::kDof; ++i) {
        if (eq[i] < first || eq[i] >= end) continue;
        PetscScalar* row = values + ia[eq[i] - first];
        const int* row_shift = shift.data() + 4 * local_node(i);
        for (int j = 0; j < mini::kDof; ++j)
          if (eq[j] >= 0) row[row_shift[local_node(j)] + eq[j]] += out.K(i, j);
      }
    });
    ArraySink sink(ia, columns_.data(), values, dofs_, first, end);
    for (auto& term : terms_) term->assemble(time_, state_, term_residual_, &sink);
    if (size_ > 1)
      PLISSE_PETSC(MatUpdateMPIAIJWithArray(K, values));
    else
      PLISSE_PETSC(MatSeqAIJRestoreArray(K, &values));
  } else {
    PLISSE_PETSC(MatZeroEntries(K));
    std::vector<PetscInt>& rows = equations_;
    std::vector<PetscInt> columns(mini::kDof);
    Eigen::Matrix<double, mini::kDof, mini::kDof, Eigen::RowMajor> k_row;
    status = for_each_element(true, [&](int e, const ElementResult& out) {
      std::array<int, mini::kDof> full;
      element_dofs(e, full);
      rows.resize(mini::kDof);
      for (int i = 0; i < mini::kDof; ++i) {
        columns[i] = dofs_.equation(full[i]);
        rows[i] = columns[i] >= first && columns[i] < end ? columns[i] : -1;  // owned rows only
      }
      k_row = out.K;  // PETSc takes row-major blocks; negative indices (constrained) are skipped
      PLISSE_PETSC(MatSetValues(K, mini::kDof, rows.data(), mini::kDof, columns.data(), k_row.data(),
                                ADD_VALUES));
    });
    EquationSink sink(K, dofs_, first, end, equations_);
    for (auto& term : terms_) term->assemble(time_, state_, term_residual_, &sink);
  }
  PLISSE_PETSC(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY));
  PLISSE_PETSC(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY));
  return status;
}

Mat MixedModel::create_matrix() const {
  const int n_free = dofs_.n_free();
  Mat K = nullptr;
  if (size_ > 1) {
    PLISSE_PETSC(MatCreateMPIAIJWithArrays(PETSC_COMM_WORLD, n_owned(), n_owned(), n_free, n_free,
                                           row_start_.data(), columns_.data(), nullptr, &K));
  } else {
    PLISSE_PETSC(MatCreate(PETSC_COMM_SELF, &K));
    PLISSE_PETSC(MatSetSizes(K, n_free, n_free, n_free, n_free));
    PLISSE_PETSC(MatSetType(K, MATSEQAIJ));
    PLISSE_PETSC(MatSeqAIJSetPreallocationCSR(K, row_start_.data(), columns_.data(), nullptr));
  }
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
  if (size_ > 1) {
    // Each rank's bubbles are current only on its own elements: the owners' values, summed with
    // zeros from everyone else.
    std::vector<char> mine(converged_bubble_.size(), 0);
    for (int e : owned_elements_) mine[e] = 1;
    for (std::size_t e = 0; e < mine.size(); ++e)
      if (!mine[e]) std::fill_n(s.bubbles.begin() + e * mini::kDofBubble, mini::kDofBubble, 0.0);
    sum_over_ranks(s.bubbles.data(), s.bubbles.size());
  }
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
    if (node_rank_[v] == rank_)  // the residual is complete on the owned nodes only
      for (int k = 0; k < 3; ++k)
        if (dofs_.equation(DofMap::dof(v, k)) < 0) force[k] += full_residual_[DofMap::dof(v, k)];
  sum_over_ranks(force.data(), 3);
  return force;
}

std::vector<mini::ElementFields> MixedModel::element_fields() const {
  // Fixed-size Eigen matrices and doubles only: the array is summed over the ranks as doubles.
  static_assert(sizeof(mini::ElementFields) == 12 * sizeof(double),
                "element fields are summed over the ranks as doubles");
  mini::ElementFields zero;
  zero.cauchy.setZero();
  zero.J = zero.von_mises = zero.pressure = 0.0;
  std::vector<mini::ElementFields> out(mesh_.n_tets(), zero);
  const int n = static_cast<int>(owned_elements_.size()), threads = assembly_threads();
  std::exception_ptr error;
  std::visit(
      [&](const auto& material) {
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads)
        for (int k = 0; k < n; ++k) {
          const int e = owned_elements_[k];
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
  // Every element is owned by one rank: the sum of the ranks' arrays is every element's fields.
  sum_over_ranks(reinterpret_cast<double*>(out.data()),
                 out.size() * (sizeof(mini::ElementFields) / sizeof(double)));
  return out;
}

double MixedModel::strain_energy() const {
  double energy = 0.0;
  for (int e : owned_elements_) {
    std::array<int, mini::kDof> full;
    element_dofs(e, full);
    energy += mini::compute_strain_energy(geometry_[e], gather(full), material_,
                                          inverse_bulk_modulus_, bubble_[e])
                  .total();
  }
  sum_over_ranks(&energy, 1);
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
