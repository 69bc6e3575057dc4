#pragma once
/// Lowest eigenmodes of the consistent tangent of a MixedModel, for the stability analysis:
///   K φ = λ M φ                                                     (eigenmodes.md, E1)
/// with K the tangent over the free dofs at the model's current state and M the lumped nodal
/// volume on the free displacement dofs (zero on pressure dofs and global unknowns). With this
/// singular M the problem is the stability problem of the displacement field on the
/// incompressibility constraint: the pressure (and the global unknowns) are eliminated by a Schur
/// complement, S φ_u = λ M_u φ_u with S = K_uu - K_up K_pp^{-1} K_pu (eigenmodes.md, E3).
/// Solved with SLEPc, shift-invert about a target with a MUMPS factorisation (LDL^T when the
/// tangent is symmetric, LU otherwise).
#include <vector>

#include "solver/mixed_model.hpp"

namespace plisse {

/// One eigenpair of (E1).
struct Eigenmode {
  double eigenvalue = 0;  ///< λ [N/mm^4 = (N/mm) / mm^3]; < 0: the state is unstable
  /// Full-state vector (MixedModel::state() layout), zeros on constrained dofs. The displacement
  /// part is scaled so that the largest nodal |u| is 1 and that node's largest |component| is
  /// positive; the pressure and global entries carry the mode's own values with the same scale.
  std::vector<double> state;
};

struct EigenSettings {
  int count = 4;            ///< number of eigenpairs wanted (nearest the target)
  double target = 0.0;      ///< shift σ of the shift-invert transformation [same unit as λ]
  double tolerance = 1e-8;  ///< SLEPc's relative tolerance on the residual of each pair
};

/// The lumped volume of every node [mm^3], the diagonal of M_u (E2): a quarter of the reference
/// volume of each tetrahedron at its corners (the edge nodes of a second-order mesh get none),
/// or, on the mid-surface of a shell (Mesh::is_shell), a third of each triangle's reference
/// area times its thickness (Mesh::triangle_thickness, as the shell element's). Their sum is the
/// body's reference volume.
std::vector<double> lumped_nodal_volumes(const Mesh& mesh);

/// The `options.count` eigenpairs of (E1) nearest `options.target` at the model's current state,
/// in ascending order of eigenvalue. The model's state is not changed (the tangent is assembled
/// at it). Throws plisse::SolverError when the tangent cannot be assembled (inverted element) or
/// SLEPc fails or does not converge to `count` pairs, plisse::Error on bad options or another
/// PETSc error. Requires a live PetscSession (which initialises SLEPc too). Options -eps_* and
/// -st_* (e.g. -st_pc_factor_mat_solver_type) in PETSc's database override the defaults.
std::vector<Eigenmode> lowest_eigenmodes(MixedModel& model, const EigenSettings& options);

}  // namespace plisse
