#pragma once
/// The saddle-point structure of the mixed tangent and its discrete inf-sup constant
/// (docs/verification/inf_sup.md).
///
/// Ordering the free unknowns as (displacements, pressures), the tangent at a state is
///   K = [ A   Bᵀ ]      A: displacement block (symmetric positive definite when stable),
///       [ B  -C  ]      B: pressure-displacement coupling, C >= 0 (bubble stabilisation, M/κ).
/// Eliminating the displacements gives the pressure Schur complement S = B A⁻¹ Bᵀ + C, and
///   β_h² = min_q (qᵀ S q) / (qᵀ M q)        (IS1)
/// with M the P1 pressure mass matrix is the discrete inf-sup constant (squared) in the norms
/// ||v||_A and ||q||_L2 [Brezzi & Fortin, Mixed and Hybrid FE Methods, 1991, ch. II; Chapelle &
/// Bathe, Comput. Struct. 47 (1993) 537, the numerical inf-sup test]. β_h bounded below under
/// refinement means no spurious pressure modes; β_h -> 0 (or zero eigenvalues) means locking or
/// checkerboards.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

#include "material/registry.hpp"
#include "mesh/mesh.hpp"
#include "solver/mixed_model.hpp"

namespace plisse::test {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// The tangent MixedModel assembles at its current state (free dofs), as an Eigen sparse matrix.
SparseMatrix assemble_mini_tangent(MixedModel& model);

/// The tangent of P1/P1 without the bubble at the state of `model` (bubbles zero): the sum of the
/// element blocks K_xx of assemble_mini_uncondensed, which carry no bubble contribution.
SparseMatrix assemble_p1p1_tangent(const MixedModel& model, const AnyMaterial& material,
                                   double inverse_bulk_modulus);

/// Blocks of a tangent over the free dofs of `model`, pressures in node order.
struct SaddlePointBlocks {
  SparseMatrix A;     ///< displacement-displacement
  Eigen::MatrixXd B;  ///< pressure-displacement (rows: pressures)
  Eigen::MatrixXd C;  ///< minus the pressure-pressure block
  Eigen::MatrixXd M;  ///< P1 pressure mass matrix, ∫ N_a N_b dV = V (1 + δ_ab) / 20 per tet
  std::vector<int> pressure_node;  ///< node of each pressure row
};
SaddlePointBlocks split_blocks(const SparseMatrix& K, const MixedModel& model);

/// Generalised eigenvalues λ of S q = λ M q, ascending, with the eigenvectors (columns, M-normed).
struct SchurSpectrum {
  Eigen::VectorXd eigenvalues;
  Eigen::MatrixXd eigenvectors;
  bool A_positive_definite = false;
};
SchurSpectrum schur_spectrum(const SaddlePointBlocks& blocks);

/// The checkerboard indicator of a nodal pressure field (inf_sup.md, IS3):
///   η = Σ_edges (p_i - p_j)² / Σ_edges [(p_i - p̄)² + (p_j - p̄)²],  p̄ = mean nodal value.
/// For a smooth field the jumps are h |Grad p|, so η = O(h²) (O(h^{2-2α}) near a singularity
/// p ~ r^-α); for a node-to-node oscillation η = O(1) (at most 2). `values` is indexed by node.
double checkerboard_indicator(const Mesh& mesh, const std::vector<double>& values);

}  // namespace plisse::test
