#pragma once
/// The iterative solver of the Newton systems K dx = -R of the mixed u-p problem: flexible GMRES
/// preconditioned by a Schur-complement field split,
///
///   K = [A  B^T]   displacement equations (u): A, the tangent stiffness
///       [B  C  ]   pressure equations and the terms' global unknowns (p): C, the condensed
///                  bubble (and -M_p/kappa); C = 0 on a volume-control cavity row
///
/// with S = C - B A^-1 B^T the Schur complement. The preconditioner is the upper block factor
///
///   P = [A  B^T]      P^-1 [r_u; r_p]:  y_p = S^-1 r_p,  y_u = A^-1 (r_u - B^T y_p)
///       [0  S  ]
///
/// (Murphy, Golub & Wathen, SIAM J. Sci. Comput. 21 (2000) 1969: with exact A^-1 and S^-1, GMRES
/// converges in two iterations; PETSc manual, "Solving block matrices"). Inside P, A^-1 is one
/// V-cycle of algebraic multigrid (hypre BoomerAMG) and S^-1 one Jacobi sweep on the "selfp"
/// approximation S_p = C - B diag(A)^-1 B^T, a sparse matrix PETSc assembles. The upper factor
/// costs one V-cycle per iteration like the lower one and took the fewest iterations (stretched
/// cube, 14^3 cells: 50 against 55 lower and 57 full; diag about 4 times more). Every
/// choice can be overridden with PETSc's own options (-ksp_*, -pc_fieldsplit_*, -fieldsplit_u_*,
/// -fieldsplit_p_*): plisse sets a default only where the options database has none.
///
/// Everything here works on a communicator and on the equations a process owns, [first, end),
/// so the same calls serve a distributed (MPIAIJ) tangent.
#include <mpi.h>
#include <petscis.h>
#include <petscksp.h>

#include <string>

#include "solver/dof_map.hpp"
#include "solver/newton_settings.hpp"

namespace plisse {
class MixedModel;
}  // namespace plisse

namespace plisse {

/// The two fields of the split, as index sets of equation numbers (PETSc's global row numbers).
/// Owns its IS handles (destroyed with it); PCFieldSplitSetIS keeps its own reference, so the
/// object may go once configure_iterative has been called.
class FieldIndexSets {
 public:
  FieldIndexSets() = default;
  FieldIndexSets(IS u, IS p) : u_(u), p_(p) {}
  ~FieldIndexSets();
  FieldIndexSets(const FieldIndexSets&) = delete;
  FieldIndexSets& operator=(const FieldIndexSets&) = delete;
  FieldIndexSets(FieldIndexSets&& other) noexcept;
  FieldIndexSets& operator=(FieldIndexSets&& other) noexcept;

  /// Free displacement equations (components 0..2 of the nodes), ascending.
  IS u() const { return u_; }
  /// Free pressure equations (component 3) and the terms' global unknowns, ascending.
  IS p() const { return p_; }

 private:
  IS u_ = nullptr;
  IS p_ = nullptr;
};

/// The index sets of the owned equations [first, end) of `dofs`, split into displacement and
/// pressure (nodal pressures plus every global unknown of the model terms, e.g. a cavity
/// pressure, which is a Lagrange multiplier like p). Collective on `comm`; each process passes its
/// own range, and every free equation in it lands in exactly one of the two sets. Only
/// dofs.equation(d) is used, so any numbering that keeps a process's equations contiguous works.
/// Precondition: 0 <= first <= end <= dofs.n_free().
FieldIndexSets make_field_index_sets(MPI_Comm comm, const DofMap& dofs, PetscInt first,
                                     PetscInt end);

/// Sets plisse's iterative solver on `ksp` (FGMRES with `settings` rtol, max_iterations and
/// restart; PCFIELDSPLIT of Schur type with fields "u" and "p", upper factorisation, selfp
/// preconditioner for S; "u": preonly + hypre BoomerAMG; "p": preonly + Jacobi). The PETSc
/// options database, applied afterwards by KSPSetFromOptions/SNESSetFromOptions, may override
/// every choice: the sub-solver defaults go into the database under the KSP's prefix only where
/// the user gave no value. `u` and `p` may be null only to validate options (the KSP is then
/// never set up); otherwise they come from make_field_index_sets on the matrix's communicator.
/// Calling it again on the same KSP replaces the earlier split.
void configure_iterative(KSP ksp, IS u, IS p, const LinearSolverSettings& settings);

/// Asks MUMPS for `percent` % more working space than its analysis estimates (ICNTL(14)) in the
/// Newton and stability factorisations, unless the user gave that option. A tangent bordered by
/// many multipliers (a rigid cap's ties) delays pivots beyond MUMPS' default 20 %, which fails
/// with INFO(1) = -9. Call before the solvers are set up; needs PETSc initialised.
void request_factor_workspace(int percent);

/// MUMPS's estimate of the operations of a factorisation of the symmetric pattern of K (its
/// analysis alone, RINFOG(1)) with the ordering ICNTL(7) = `ordering`. Collective on K.
double estimated_factor_operations(Mat K, int ordering);

/// The fill-reducing ordering of a shell model's factorisations: MUMPS's analysis of the model's
/// tangent at its current state with the approximate minimum degree (ICNTL(7) = 0) and with the
/// ordering MUMPS picks itself (7: PORD but for small matrices, Debian's MUMPS having neither
/// METIS nor SCOTCH), and the one with the fewer estimated operations made the default of the
/// Newton, stability, arc-length and eigenmode factorisations, unless the user gave
/// -mat_mumps_icntl_7 for that solver. A shell's tangent is denser per node than a solid's (a
/// patch couples nodes up to four edges apart), and which ordering wins depends on the mesh:
/// minimum degree on the structured sheet of 12k unknowns, PORD on the Gmsh balloon of 32k
/// (factor_ordering_test.cpp, docs/performance.md "The ordering of a shell's factorisation").
/// Returns the ordering chosen. Collective; call before the solvers are set up.
int choose_factor_ordering(MixedModel& model);

/// What a MUMPS factorisation that failed says about memory (MUMPS user's guide, INFOG(1)).
struct FactorMemory {
  /// A work array or buffer smaller than the factorisation turned out to need (INFOG(1) = -8,
  /// -9, -11, -14, -15, -17, -20: "increase ICNTL(14)"): grow_factor_workspace mends it.
  bool workspace_too_small = false;
  /// An allocation the system refused (-13), or one beyond the limit ICNTL(23) (-19).
  bool out_of_memory = false;
  int status = 0;              ///< INFOG(1)
  double requested_mib = 0.0;  ///< the allocation refused (-13) or the memory missing (-19)
  /// out_of_memory: "out of memory: the factorisation ... could not allocate N MiB (MUMPS ...)".
  std::string message() const;
};

/// True when `F` is a factor made by MUMPS (not null).
bool is_mumps_factor(Mat F);

/// A count MUMPS reports in INFO/INFOG (entries of a factor or of a work array): a negative value
/// is the count in millions (MUMPS user's guide).
inline double mumps_count(PetscInt value) {
  return value < 0 ? -1e6 * static_cast<double>(value) : static_cast<double>(value);
}

/// The memory status of `F`'s last factorisation; all false when it did not fail for memory, or
/// when `F` is null or not a MUMPS factor.
FactorMemory factor_memory(Mat F);

/// After the factorisation of `pc` failed with `memory.workspace_too_small`: doubles the margin
/// ICNTL(14) (at least to 40 %) in the options of the factor's prefix and resets `pc`, so that
/// its next set-up makes a new factor with that margin (PETSc does not factorise a failed MUMPS
/// factor again). False, with nothing done, for another failure or once the margin has been
/// doubled kMaxWorkspaceGrowths times in this process.
bool grow_factor_workspace(PC pc, const FactorMemory& memory);
constexpr int kMaxWorkspaceGrowths = 6;

/// What grow_factor_workspace did so far in this process, for the log.
struct WorkspaceGrowth {
  int count = 0;    ///< doublings
  int percent = 0;  ///< the margin ICNTL(14) after the last one [%]
  int status = 0;   ///< the INFOG(1) that asked for the last one
};
WorkspaceGrowth factor_workspace_growth();

}  // namespace plisse
