#pragma once
/// The manufactured-solution problem on the unit cube and its error norms
/// (docs/verification/mms.md).
///
/// Body force f0 = -Div P with P = P_iso(F) - p cof F (reference configuration), dead traction
/// t0 = P N on the faces right (x = 1), back (y = 1) and top (z = 1), the exact displacement
/// prescribed on left (x = 0), front (y = 0) and bottom (z = 0); for finite κ the pressure rows get
/// the source that makes (u, p) satisfy  J - 1 + p/κ = s.
#include <string>
#include <vector>

#include "material/registry.hpp"
#include "mesh/mesh.hpp"
#include "physics/dirichlet.hpp"
#include "verification/manufactured_solution.hpp"

namespace plisse::test {

struct MmsProblem {
  AnyMaterial material;
  double inverse_bulk_modulus = 0.0;  ///< 1/κ [1/MPa]; 0: exact incompressibility
  ManufacturedSolution solution;
};

/// P = P_iso(F) - p cof F at X [MPa] (mms.md, M6).
Mat3d total_stress(const MmsProblem& problem, const Vec3d& X);

/// Div P at X [N/mm³] by the chain rule (mms.md, M7):
///   (Div P)_i = A_iJkL ∂F_kL/∂X_J - cof_iJ ∂p/∂X_J       (Piola identity: Div cof F = 0)
/// with ∂F/∂X_J from central differences of the analytic F, step `step` [mm].
Vec3d divergence_of_stress(const MmsProblem& problem, const Vec3d& X, double step = 1e-5);

/// Consistent nodal loads on the full dofs (kPerNode per node): ∫ f0 N_a dV (degree-3 rule),
/// ∫ t0 N_a dA on the traction faces, and on the pressure rows -∫ N_a s dV with
/// s = J(X) - 1 + p(X)/κ (mms.md, M8-M10). The bubble's share of f0 is left out (mms.md, M11).
std::vector<double> manufactured_loads(const Mesh& mesh, const MmsProblem& problem);

/// The exact displacement prescribed at every node of the faces left, front, bottom (ramp [0, 1]).
std::vector<ConstrainedComponent> manufactured_constraints(const Mesh& mesh,
                                                           const ManufacturedSolution& solution);

/// Errors of the P1 parts of a discrete state (kPerNode per node) against the exact fields.
struct FieldErrors {
  double u_L2 = 0.0;  ///< ||u - u_h||_L2 [mm · mm^{3/2}]
  double u_H1 = 0.0;  ///< |u - u_h|_H1 = ||Grad u - Grad u_h||_L2
  double p_L2 = 0.0;  ///< ||p - p_h||_L2
  double u_L2_exact = 0.0, u_H1_exact = 0.0, p_L2_exact = 0.0;  ///< norms of the exact fields
};
/// By a collapsed Gauss rule with `points_per_direction`^3 points per tetrahedron (exact for
/// degree 2n - 3, 5 by default: far below the discretisation error, mms.md, Q1).
FieldErrors compute_errors(const Mesh& mesh, const std::vector<double>& state,
                           const ManufacturedSolution& solution, int points_per_direction = 4);

/// One level of the convergence study.
struct MmsLevel {
  int divisions = 0;
  double h = 0.0;  ///< cell edge 1/divisions [mm]
  int n_free = 0;
  int newton_iterations = 0;
  double final_residual = 0.0;
  std::vector<double> residual_history;  ///< Newton residual norms, from the interpolant
  bool converged = false;
  double seconds = 0.0;
  FieldErrors errors;
};

/// Meshes the unit cube with `divisions` cells per edge, starts Newton from the nodal interpolant
/// of the exact fields and solves; returns the errors of the converged discrete solution.
MmsLevel solve_manufactured(const MmsProblem& problem, int divisions);

/// The convergence table (h, errors, observed rates log(e_i-1/e_i)/log(h_i-1/h_i)) as text.
std::string convergence_table(const std::string& title, const std::vector<MmsLevel>& levels);

/// Observed rate between levels i-1 and i of an error sequence.
double observed_rate(const std::vector<MmsLevel>& levels, std::size_t i,
                     double FieldErrors::*error);

}  // namespace plisse::test
