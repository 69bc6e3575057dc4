#include "solver/eigenmodes.hpp"

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "physics/body_force.hpp"
#include "solver/petsc_call.hpp"

namespace plisse {
namespace {

/// Owns the PETSc/SLEPc objects of one call, so an exception leaks none of them.
struct EigenObjects {
  Mat K = nullptr, M = nullptr;
  Vec x = nullptr;
  EPS eps = nullptr;
  ~EigenObjects() {
    EPSDestroy(&eps);
    VecDestroy(&x);
    MatDestroy(&M);
    MatDestroy(&K);
  }
};

/// The lumped "mass" of (eigenmodes.md, E2): lumped_nodal_volumes on the free displacement
/// dofs, 0 on the free pressure dofs and global unknowns. Every row stores its diagonal (explicit
/// zeros included), so the pattern of M is a subset of the tangent's and K - σ M can be formed in
/// place.
Mat create_lumped_volume(const MixedModel& model) {
  const DofMap& dofs = model.dofs();
  const std::vector<double> volumes = lumped_nodal_volumes(model.mesh());
  // Over the whole mesh on every rank; each rank sets its owned rows.
  std::vector<double> diagonal(dofs.n_free(), 0.0);
  for (int node = 0; node < dofs.n_nodes(); ++node)
    for (int k = 0; k < 3; ++k)
      if (const int eq = dofs.equation(DofMap::dof(node, k)); eq >= 0) diagonal[eq] = volumes[node];
  Mat M = nullptr;
  PLISSE_PETSC(MatCreateAIJ(model.comm(), model.n_owned(), model.n_owned(), dofs.n_free(),
                            dofs.n_free(), 1, nullptr, 0, nullptr, &M));
  for (PetscInt i = model.first_owned_equation(); i < model.end_owned_equation(); ++i)
    PLISSE_PETSC(MatSetValue(M, i, i, diagonal[i], INSERT_VALUES));
  PLISSE_PETSC(MatAssemblyBegin(M, MAT_FINAL_ASSEMBLY));
  PLISSE_PETSC(MatAssemblyEnd(M, MAT_FINAL_ASSEMBLY));
  PLISSE_PETSC(MatSetOption(M, MAT_SYMMETRIC, PETSC_TRUE));
  PLISSE_PETSC(MatSetOption(M, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  return M;
}

/// Free-dof vector -> full state with zeros on the constrained dofs, scaled so that the largest
/// nodal |u| is 1 and the largest |component| of that node is positive.
std::vector<double> to_normalised_state(const MixedModel& model, Vec x) {
  const DofMap& dofs = model.dofs();
  std::vector<double> state = model.full_from_free(x);  // collective

  int largest_node = -1;
  double largest = 0.0;
  for (int v = 0; v < dofs.n_nodes(); ++v) {
    const double norm =
        Vec3d(state[DofMap::dof(v, 0)], state[DofMap::dof(v, 1)], state[DofMap::dof(v, 2)]).norm();
    if (norm > largest) {
      largest = norm;
      largest_node = v;
    }
  }
  // A mode without displacement cannot be scaled by it; SLEPc's purification (eigenmodes.md)
  // keeps such vectors, the eigenvectors of the infinite eigenvalues, out of the results.
  if (largest_node < 0) return state;
  int component = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(state[DofMap::dof(largest_node, k)]) >
        std::abs(state[DofMap::dof(largest_node, component)]))
      component = k;
  const double sign = state[DofMap::dof(largest_node, component)] < 0 ? -1.0 : 1.0;
  const double scale = sign / largest;
  for (double& value : state) value *= scale;
  return state;
}

}  // namespace

std::vector<double> lumped_nodal_volumes(const Mesh& mesh) {
  // On a shell and on linear tetrahedra the lumped volumes are the consistent ones: A_e t_e / 3
  // and V_e / 4 per corner (loads.md, L6s and L6). A 10-node tetrahedron's consistent corner
  // volumes are negative (L10), so its edge nodes get none and its corners V_e / 4.
  if (mesh.is_shell() || mesh.order() == 1) return consistent_nodal_volumes(mesh);
  std::vector<double> volume(mesh.nodes.size(), 0.0);
  for (const auto& tet : mesh.tets) {
    const Vec3d X0 = mesh.nodes[tet[0]];
    Mat3d dX;
    for (int a = 1; a < 4; ++a) dX.col(a - 1) = mesh.nodes[tet[a]] - X0;
    for (int node : tet) volume[node] += dX.determinant() / 24.0;  // V_e / 4 [mm^3]
  }
  return volume;
}

std::vector<Eigenmode> lowest_eigenmodes(MixedModel& model, const EigenSettings& options) {
  PLISSE_CHECK(options.count >= 1,
               "lowest_eigenmodes: count must be at least 1, not " << options.count);
  PLISSE_CHECK(options.count <= model.n_free(),
               "lowest_eigenmodes: " << options.count << " modes asked of a model with "
                                     << model.n_free() << " free dofs");
  PLISSE_CHECK(options.tolerance > 0, "lowest_eigenmodes: tolerance must be positive");
  EigenObjects o;
  o.K = model.create_matrix();
  const AssemblyStatus status = model.assemble_tangent(o.K);
  if (!status.ok) {
    std::ostringstream out;
    out << "eigenmodes: the tangent cannot be assembled at this state (element "
        << status.worst_element << ", J = " << status.min_J << ")";
    throw SolverError(out.str());
  }
  o.M = create_lumped_volume(model);
  const bool symmetric = model.symmetric();

  PLISSE_PETSC(EPSCreate(model.comm(), &o.eps));
  PLISSE_PETSC(EPSSetOperators(o.eps, o.K, o.M));
  // Symmetric K with semi-definite M: a GHEP in SLEPc's sense (the B-inner product is only a
  // semi-inner product; with shift-invert the null space of M maps to the eigenvalue 0 of the
  // operator, far from the wanted ones, and purification removes what is left of it).
  PLISSE_PETSC(EPSSetProblemType(o.eps, symmetric ? EPS_GHEP : EPS_GNHEP));
  PLISSE_PETSC(EPSSetDimensions(o.eps, options.count, PETSC_DEFAULT, PETSC_DEFAULT));
  PLISSE_PETSC(EPSSetTarget(o.eps, options.target));
  PLISSE_PETSC(EPSSetWhichEigenpairs(o.eps, EPS_TARGET_MAGNITUDE));
  PLISSE_PETSC(EPSSetTolerances(o.eps, options.tolerance, PETSC_DEFAULT));
  PLISSE_PETSC(EPSSetPurify(o.eps, PETSC_TRUE));
  ST st = nullptr;
  PLISSE_PETSC(EPSGetST(o.eps, &st));
  PLISSE_PETSC(STSetType(st, STSINVERT));
  PLISSE_PETSC(STSetMatStructure(st, SUBSET_NONZERO_PATTERN));  // M's pattern is K's diagonal
  KSP ksp = nullptr;
  PC pc = nullptr;
  PLISSE_PETSC(STGetKSP(st, &ksp));
  PLISSE_PETSC(KSPSetType(ksp, KSPPREONLY));
  PLISSE_PETSC(KSPGetPC(ksp, &pc));
  // K - σ M is indefinite (saddle point): MUMPS LDL^T (sym = 2) when symmetric, else LU.
  PLISSE_PETSC(PCSetType(pc, symmetric ? PCCHOLESKY : PCLU));
  PLISSE_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PLISSE_PETSC(EPSSetFromOptions(o.eps));  // -eps_*, -st_* options override these defaults

  const PetscErrorCode code = EPSSolve(o.eps);
  if (code != 0) {
    const char* text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    std::ostringstream out;
    out << "eigenmodes: SLEPc failed (" << (text ? text : "unknown error") << "); a singular K - "
        << options.target << " M (target exactly on an eigenvalue) is a common cause";
    throw SolverError(out.str());
  }
  PetscInt n_converged = 0;
  PLISSE_PETSC(EPSGetConverged(o.eps, &n_converged));
  if (n_converged < options.count) {
    EPSConvergedReason reason = EPS_CONVERGED_ITERATING;
    PLISSE_PETSC(EPSGetConvergedReason(o.eps, &reason));
    std::ostringstream out;
    out << "eigenmodes: SLEPc converged " << n_converged << " of " << options.count
        << " eigenpairs near " << options.target << " (reason " << EPSConvergedReasons[reason]
        << ", tolerance " << options.tolerance << ")";
    throw SolverError(out.str());
  }

  PLISSE_PETSC(MatCreateVecs(o.K, &o.x, nullptr));
  std::vector<Eigenmode> modes(options.count);
  for (int i = 0; i < options.count; ++i) {
    PetscScalar real = 0, imaginary = 0;
    // An unsymmetric tangent may have complex pairs; the real part and real vector are kept.
    PLISSE_PETSC(EPSGetEigenpair(o.eps, i, &real, &imaginary, o.x, nullptr));
    modes[i].eigenvalue = real;
    modes[i].state = to_normalised_state(model, o.x);
  }
  std::stable_sort(modes.begin(), modes.end(), [](const Eigenmode& a, const Eigenmode& b) {
    return a.eigenvalue < b.eigenvalue;
  });
  return modes;
}

}  // namespace plisse
