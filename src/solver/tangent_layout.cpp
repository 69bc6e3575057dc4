#include "solver/tangent_layout.hpp"

#include <algorithm>
#include <limits>

#include "core/error.hpp"
#include "solver/petsc_call.hpp"

namespace plisse {

namespace {

/// The free components of every node and the equation of its first free one (-1: none).
struct NodeEquations {
  std::vector<int> n_free;
  std::vector<int> first;
};

NodeEquations node_equations(const DofMap& dofs) {
  const int n_nodes = dofs.n_nodes();
  NodeEquations nodes{std::vector<int>(n_nodes, 0), std::vector<int>(n_nodes, -1)};
  for (int v = 0; v < n_nodes; ++v)
    for (int k = DofMap::kPerNode - 1; k >= 0; --k)
      if (const int eq = dofs.equation(DofMap::dof(v, k)); eq >= 0) {
        ++nodes.n_free[v];
        nodes.first[v] = eq;
      }
  return nodes;
}

/// Owned couplings that involve a global unknown, and the diagonal of every owned free global
/// unknown, as sorted unique (row, column) equations. Their equations follow all nodal ones, so
/// in a nodal row they come after the node columns.
std::vector<std::pair<int, int>> global_unknown_entries(
    const Distribution& distribution, const std::vector<std::pair<int, int>>& couplings) {
  const DofMap& dofs = distribution.dofs();
  const int n_nodal = DofMap::kPerNode * dofs.n_nodes();
  const auto owned = [&](int eq) { return distribution.owns_equation(eq); };
  std::vector<std::pair<int, int>> entries;
  for (const auto& [row, col] : couplings) {
    const int r = dofs.equation(row), c = dofs.equation(col);
    if ((row >= n_nodal || col >= n_nodal) && owned(r) && c >= 0) entries.emplace_back(r, c);
  }
  for (int d = n_nodal; d < dofs.n_dofs(); ++d)
    if (const int eq = dofs.equation(d); owned(eq)) entries.emplace_back(eq, eq);
  std::sort(entries.begin(), entries.end());
  entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
  return entries;
}

}  // namespace

TangentLayout::TangentLayout(const NodeGraph& graph, ElementNodes elements,
                             const Distribution& distribution,
                             const std::vector<std::pair<int, int>>& couplings)
    : distribution_(distribution), width_(elements.width) {
  const NodeEquations nodes = node_equations(distribution.dofs());
  const std::vector<std::pair<int, int>> extra_entries =
      global_unknown_entries(distribution, couplings);
  set_rows(graph, nodes.n_free, nodes.first, extra_entries);
  set_element_shifts(elements, nodes.n_free, nodes.first);
}

void TangentLayout::set_rows(const NodeGraph& graph, const std::vector<int>& node_free,
                             const std::vector<int>& node_first_equation,
                             const std::vector<std::pair<int, int>>& extra_entries) {
  const Distribution& distribution = distribution_;
  const int n_nodes = static_cast<int>(node_free.size());
  const int first_equation = distribution.first_equation();
  const auto owned = [&](int eq) { return distribution.owns_equation(eq); };
  // Row lengths of the owned rows: the free columns of the neighbour nodes, then the extra
  // entries of the row.
  const int n_rows = distribution.n_owned();
  std::vector<int> length(n_rows, 0);
  for (int v = 0; v < n_nodes; ++v) {
    if (node_free[v] == 0 || !owned(node_first_equation[v])) continue;
    int columns = 0;
    for (int k = graph.start[v]; k < graph.start[v + 1]; ++k)
      columns += node_free[graph.neighbours[k]];
    for (int i = 0; i < node_free[v]; ++i)
      length[node_first_equation[v] + i - first_equation] = columns;
  }
  for (const auto& [row, col] : extra_entries) ++length[row - first_equation];
  row_start_.assign(n_rows + 1, 0);
  for (int r = 0; r < n_rows; ++r) {
    PLISSE_CHECK(row_start_[r] + length[r] <= std::numeric_limits<int>::max(),
                 "the tangent has more nonzeros than 32-bit positions hold");
    row_start_[r + 1] = row_start_[r] + length[r];
  }
  // Column equations, sorted within each row (node runs in node order; global unknowns last).
  columns_.assign(row_start_[n_rows], 0);
  std::vector<PetscInt> fill(row_start_.begin(), row_start_.end() - 1);
  for (int v = 0; v < n_nodes; ++v) {
    if (node_free[v] == 0 || !owned(node_first_equation[v])) continue;
    for (int i = 0; i < node_free[v]; ++i) {
      const int row = node_first_equation[v] + i - first_equation;
      for (int k = graph.start[v]; k < graph.start[v + 1]; ++k) {
        const int w = graph.neighbours[k];
        for (int c = 0; c < node_free[w]; ++c) columns_[fill[row]++] = node_first_equation[w] + c;
      }
    }
  }
  for (const auto& [row, col] : extra_entries) columns_[fill[row - first_equation]++] = col;
  // Distributed runs number the nodes by rank, so the node runs of a row are not in increasing
  // equation order: sort each row (PETSc's CSR creation wants sorted columns), keeping each
  // node's run consecutive, so that the element positions below still hold.
  if (distribution.n_ranks() > 1)
    for (int r = 0; r < n_rows; ++r)
      std::sort(columns_.begin() + row_start_[r], columns_.begin() + row_start_[r + 1]);
}

void TangentLayout::set_element_shifts(const ElementNodes& elements,
                                       const std::vector<int>& node_free,
                                       const std::vector<int>& node_first_equation) {
  const int first_equation = distribution_.first_equation();
  // Per local element and local node pair (a, b): where node b's run of columns starts in a row
  // of node a, minus b's first equation, so that adding a column's equation gives its position.
  // The run of b starts where its first equation sits in the (sorted) row.
  element_shift_.assign(static_cast<std::size_t>(elements.n_elements()) * width_ * width_, 0);
  for (int e : distribution_.local_elements()) {
    const auto nodes = elements.of(e);
    int* shift = element_shift_.data() + static_cast<std::size_t>(e) * width_ * width_;
    for (int a = 0; a < width_; ++a) {
      const int first_row = node_first_equation[nodes[a]];
      if (node_free[nodes[a]] == 0 || !distribution_.owns_equation(first_row)) continue;
      const PetscInt* row_begin = columns_.data() + row_start_[first_row - first_equation];
      const PetscInt* row_end = columns_.data() + row_start_[first_row - first_equation + 1];
      for (int b = 0; b < width_; ++b) {
        if (node_free[nodes[b]] == 0) continue;
        const int column = node_first_equation[nodes[b]];
        const PetscInt* at = std::lower_bound(row_begin, row_end, static_cast<PetscInt>(column));
        shift[width_ * a + b] = static_cast<int>(at - row_begin) - column;
      }
    }
  }
}

Mat TangentLayout::create_matrix(bool symmetric) const {
  const int n_free = distribution_.dofs().n_free();
  const int n_owned = distribution_.n_owned();
  Mat K = nullptr;
  if (distribution_.n_ranks() > 1) {
    PLISSE_PETSC(MatCreateMPIAIJWithArrays(PETSC_COMM_WORLD, n_owned, n_owned, n_free, n_free,
                                           row_start_.data(), columns_.data(), nullptr, &K));
  } else {
    PLISSE_PETSC(MatCreate(PETSC_COMM_SELF, &K));
    PLISSE_PETSC(MatSetSizes(K, n_free, n_free, n_free, n_free));
    PLISSE_PETSC(MatSetType(K, MATSEQAIJ));
    PLISSE_PETSC(MatSeqAIJSetPreallocationCSR(K, row_start_.data(), columns_.data(), nullptr));
  }
  PLISSE_PETSC(MatSetOption(K, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  if (symmetric) {
    PLISSE_PETSC(MatSetOption(K, MAT_SYMMETRIC, PETSC_TRUE));
    PLISSE_PETSC(MatSetOption(K, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  }
  return K;
}

bool TangentLayout::matches(Mat K) const {
  if (distribution_.n_ranks() > 1) {
    PetscBool mpiaij = PETSC_FALSE;
    PLISSE_PETSC(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(K), MATMPIAIJ, &mpiaij));
    if (!mpiaij) return false;
    PetscInt first = 0, end = 0;
    PLISSE_PETSC(MatGetOwnershipRange(K, &first, &end));
    if (first != distribution_.first_equation() || end != distribution_.end_equation())
      return false;
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
  const bool same = done && n == distribution_.dofs().n_free() &&
                    std::equal(row_start_.begin(), row_start_.end(), ia);
  PLISSE_PETSC(MatRestoreRowIJ(K, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  return same;
}

PetscScalar* TangentLayout::open_values(Mat K) {
  PetscScalar* values = nullptr;
  if (distribution_.n_ranks() > 1) {
    local_values_.assign(row_start_.back(), 0.0);
    values = local_values_.data();
  } else {
    PLISSE_PETSC(MatZeroEntries(K));
    PLISSE_PETSC(MatSeqAIJGetArray(K, &values));
  }
  return values;
}

void TangentLayout::close_values(Mat K, PetscScalar* values) {
  if (distribution_.n_ranks() > 1)
    PLISSE_PETSC(MatUpdateMPIAIJWithArray(K, values));
  else
    PLISSE_PETSC(MatSeqAIJRestoreArray(K, &values));
}

void TangentLayout::TermSink::add(std::span<const int> rows, std::span<const int> cols,
                                  std::span<const double> values) {
  const Distribution& distribution = layout_.distribution_;
  const DofMap& dofs = distribution.dofs();
  const int first = distribution.first_equation();
  const PetscInt* ia = layout_.row_start_.data();
  const PetscInt* ja = layout_.columns_.data();
  for (size_t i = 0; i < rows.size(); ++i) {
    const int equation = dofs.equation(rows[i]);
    if (!distribution.owns_equation(equation)) continue;
    const int row = equation - first;
    const PetscInt* begin = ja + ia[row];
    const PetscInt* end = ja + ia[row + 1];
    // The terms list a node's unknowns together, whose free equations are consecutive and so
    // are their columns in the row: the entry after the last one found is tried first.
    const PetscInt* at = end;
    for (size_t j = 0; j < cols.size(); ++j) {
      const int col = dofs.equation(cols[j]);
      if (col < 0) continue;
      if (at == end || at + 1 == end || at[1] != col)
        at = std::lower_bound(begin, end, static_cast<PetscInt>(col));
      else
        ++at;
      PLISSE_CHECK(at != end && *at == col,
                   "a model term adds the tangent entry ("
                       << rows[i] << ", " << cols[j]
                       << ") outside the couplings it declares (ModelTerm::add_couplings)");
      values_[at - ja] += values[i * cols.size() + j];
    }
  }
}

}  // namespace plisse
