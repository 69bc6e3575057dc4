#pragma once
/// The exact compressed-row layout of the tangent over the free equations, built once, and the
/// precomputed positions through which element matrices are added straight into a matrix's value
/// array (docs/performance.md, "How the assembly works now").
///
/// The free equations of a node are consecutive (solver/dof_map.hpp), so each owned row of node a
/// holds, for each neighbour b of a in the node graph, the free equations of b as one run of
/// columns, then the columns of the terms' global unknowns. Entry (row eq_i of node a, column eq_j
/// of node b) is at row_start[eq_i - first] + shift(e, a, b) + eq_j for the local nodes a, b of an
/// element e, where `first` is the first owned equation: one integer per element and local node
/// pair. The layout knows no element type: an element is its node list (any width).
#include <petscmat.h>

#include <array>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "physics/model_term.hpp"
#include "solver/distribution.hpp"
#include "solver/element_nodes.hpp"
#include "solver/node_graph.hpp"

namespace plisse {

class TangentLayout {
 public:
  /// The layout of the rows `distribution` owns: the free equations of the nodes coupled in
  /// `graph`, the (row, column) `couplings` of full-state dofs the terms declare beyond the
  /// elements, and the diagonal of every free global unknown; positions for the local elements
  /// of `elements`. Borrows `distribution` (must outlive the layout).
  TangentLayout(const NodeGraph& graph, ElementNodes elements, const Distribution& distribution,
                const std::vector<std::pair<int, int>>& couplings);

  /// An AIJ matrix with this layout, entries zero, flagged symmetric when `symmetric`:
  /// sequential on one rank, else distributed by the owned equation ranges. The caller owns it.
  Mat create_matrix(bool symmetric) const;
  /// True when K is an AIJ matrix with this layout (made by create_matrix).
  bool matches(Mat K) const;
  /// Stored entries of the owned rows.
  PetscInt n_entries() const { return row_start_.back(); }

  /// The zeroed values of the owned rows of K (precondition: matches(K)), in this layout's order:
  /// the matrix's own array on one rank, else a buffer of the layout handed to K by close_values.
  PetscScalar* open_values(Mat K);
  /// Gives the values from open_values back to K (not yet assembled: MatAssemblyBegin/End
  /// follow).
  void close_values(Mat K, PetscScalar* values);

  /// Adds the owned rows of the dense element matrix `K` (kDof x kDof, entries K(i, j)) of
  /// element e into `values` (from open_values). equations[i]: the equation of element unknown
  /// i (negative: constrained, skipped); local_node[i]: the position of its node in the element's
  /// node list. Each entry receives the element's terms in (i, j) order, as MatSetValues
  /// (ADD_VALUES) would add them. No allocation.
  template <std::size_t kDof, class Matrix>
  void add_element(int e, const std::array<int, kDof>& equations,
                   const std::array<int, kDof>& local_node, const Matrix& K,
                   PetscScalar* values) const;

  /// Tangent entries of the model terms by full-state index, added into `values` (from
  /// open_values). The terms touch few entries, so their columns are found by binary search in
  /// the row instead of stored positions; an entry outside the layout throws plisse::Error.
  class TermSink : public TangentSink {
   public:
    /// Borrows `layout` and `values`.
    TermSink(const TangentLayout& layout, PetscScalar* values) : layout_(layout), values_(values) {}
    void add(std::span<const int> rows, std::span<const int> cols,
             std::span<const double> values) override;

   private:
    const TangentLayout& layout_;
    PetscScalar* values_;
  };

 private:
  /// row_start_ and columns_ of the owned rows: the free equations of each node's neighbours in
  /// `graph`, then `extra_entries` (sorted (row, column) equations of the global unknowns).
  /// `node_free` and `node_first_equation`: per node, its free components and the equation of the
  /// first (-1: none).
  void set_rows(const NodeGraph& graph, const std::vector<int>& node_free,
                const std::vector<int>& node_first_equation,
                const std::vector<std::pair<int, int>>& extra_entries);
  /// element_shift_ of the local elements, from the rows set by set_rows.
  void set_element_shifts(const ElementNodes& elements, const std::vector<int>& node_free,
                          const std::vector<int>& node_first_equation);

  const Distribution& distribution_;
  int width_ = 0;                          ///< nodes per element
  std::vector<PetscInt> row_start_;        ///< owned rows + 1 row starts (local rows)
  std::vector<PetscInt> columns_;          ///< column equations of the owned rows, sorted per row
  std::vector<int> element_shift_;         ///< width_ * width_ per element: shift(e, a, b)
  std::vector<PetscScalar> local_values_;  ///< owned rows' values (distributed matrix fill)
};

template <std::size_t kDof, class Matrix>
void TangentLayout::add_element(int e, const std::array<int, kDof>& equations,
                                const std::array<int, kDof>& local_node, const Matrix& K,
                                PetscScalar* values) const {
  const int first = distribution_.first_equation();
  const int* shift = element_shift_.data() + static_cast<std::size_t>(e) * width_ * width_;
  // The free columns, and where each lands in a row of the current row node: the unknowns of a
  // node are consecutive in i (Element::kLocalNode), so the positions are found once per node
  // instead of once per entry.
  std::array<int, kDof> column{};
  std::array<int, kDof> position{};
  std::size_t n_free = 0;
  for (std::size_t j = 0; j < kDof; ++j)
    if (equations[j] >= 0) column[n_free++] = static_cast<int>(j);
  int row_node = -1;
  for (std::size_t i = 0; i < kDof; ++i) {
    if (!distribution_.owns_equation(equations[i])) continue;
    if (local_node[i] != row_node) {
      row_node = local_node[i];
      const int* row_shift = shift + width_ * row_node;
      for (std::size_t k = 0; k < n_free; ++k)
        position[k] = row_shift[local_node[column[k]]] + equations[column[k]];
    }
    PetscScalar* row = values + row_start_[equations[i] - first];
    for (std::size_t k = 0; k < n_free; ++k) row[position[k]] += K(i, column[k]);
  }
}

}  // namespace plisse
