#include "solver/linear_solver.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "solver/mixed_model.hpp"
#include "solver/petsc_call.hpp"

namespace plisse {
namespace {

/// Puts `-<prefix><name> value` into the options database unless the user has given that option.
void set_default_option(const char* prefix, const std::string& name, const char* value) {
  std::string option("-");  // appended, not "-" + string: g++ 12 warns wrongly (-Wrestrict)
  if (prefix) option += prefix;
  option += name;
  PetscBool given = PETSC_FALSE;
  PLISSE_PETSC(PetscOptionsHasName(nullptr, nullptr, option.c_str(), &given));
  if (!given) PLISSE_PETSC(PetscOptionsSetValue(nullptr, option.c_str(), value));
}

}  // namespace

FieldIndexSets::~FieldIndexSets() {
  ISDestroy(&u_);
  ISDestroy(&p_);
}

FieldIndexSets::FieldIndexSets(FieldIndexSets&& other) noexcept
    : u_(std::exchange(other.u_, nullptr)), p_(std::exchange(other.p_, nullptr)) {}

FieldIndexSets& FieldIndexSets::operator=(FieldIndexSets&& other) noexcept {
  if (this != &other) {
    ISDestroy(&u_);
    ISDestroy(&p_);
    u_ = std::exchange(other.u_, nullptr);
    p_ = std::exchange(other.p_, nullptr);
  }
  return *this;
}

FieldIndexSets make_field_index_sets(MPI_Comm comm, const DofMap& dofs, PetscInt first,
                                     PetscInt end) {
  PLISSE_CHECK(0 <= first && first <= end && end <= dofs.n_free(),
               "owned equation range [" + std::to_string(first) + ", " + std::to_string(end) +
                   ") is not inside [0, " + std::to_string(dofs.n_free()) + ")");
  std::vector<PetscInt> u, p;
  const int n_nodal = DofMap::kPerNode * dofs.n_nodes();
  for (int d = 0; d < dofs.n_dofs(); ++d) {
    const PetscInt eq = dofs.equation(d);
    if (eq < first || eq >= end) continue;  // constrained (-1) or owned by another process
    const bool displacement = d < n_nodal && d % DofMap::kPerNode < 3;
    (displacement ? u : p).push_back(eq);
  }
  // Equations need not follow the dof order (a renumbering for distribution): sort, as
  // PCFieldSplit extracts the blocks in the order of the set.
  std::sort(u.begin(), u.end());
  std::sort(p.begin(), p.end());
  IS is_u = nullptr, is_p = nullptr;
  PLISSE_PETSC(
      ISCreateGeneral(comm, static_cast<PetscInt>(u.size()), u.data(), PETSC_COPY_VALUES, &is_u));
  const PetscErrorCode code =
      ISCreateGeneral(comm, static_cast<PetscInt>(p.size()), p.data(), PETSC_COPY_VALUES, &is_p);
  FieldIndexSets sets(is_u, is_p);  // owns is_u even when the second call failed
  PLISSE_PETSC(code);
  return sets;
}

void request_factor_workspace(int percent) {
  const std::string value = std::to_string(percent);
  for (const char* prefix : {"", "stability_"})
    set_default_option(prefix, "mat_mumps_icntl_14", value.c_str());
}

double estimated_factor_operations(Mat K, int ordering) {
  // Only the analysis. MUMPS reads its controls from the options database when it analyses, so
  // the ordering goes there, under a prefix of this probe's own, and is taken out again.
  const char* const prefix = "plisse_ordering_probe_";
  const std::string option = std::string("-") + prefix + "mat_mumps_icntl_7";
  PLISSE_PETSC(PetscOptionsSetValue(nullptr, option.c_str(), std::to_string(ordering).c_str()));
  Mat F = nullptr;
  PetscReal operations = -1.0;
  const PetscErrorCode code = [&]() -> PetscErrorCode {
    PetscCall(MatGetFactor(K, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &F));
    PetscCall(MatSetOptionsPrefix(F, prefix));
    MatFactorInfo info;
    PetscCall(MatFactorInfoInitialize(&info));
    PetscCall(MatCholeskyFactorSymbolic(F, K, nullptr, &info));
    PetscCall(MatMumpsGetRinfog(F, 1, &operations));
    return 0;
  }();
  MatDestroy(&F);
  PetscOptionsClearValue(nullptr, option.c_str());
  PLISSE_PETSC(code);
  return operations;
}

int choose_factor_ordering(MixedModel& model) {
  Mat K = model.create_matrix();
  const AssemblyStatus status = model.assemble_tangent(K);
  int ordering = 7;  // MUMPS's own choice
  if (status.ok) {
    // The analysis reads the upper triangle as a symmetric matrix's, whatever the model's tangent.
    PLISSE_PETSC(MatSetOption(K, MAT_SYMMETRIC, PETSC_TRUE));
    const double minimum_degree = estimated_factor_operations(K, 0);
    const double own = estimated_factor_operations(K, 7);
    if (minimum_degree > 0.0 && minimum_degree < own) ordering = 0;
  }
  MatDestroy(&K);
  const std::string value = std::to_string(ordering);
  for (const char* prefix : {"", "stability_", "arc_length_", "st_"})
    set_default_option(prefix, "mat_mumps_icntl_7", value.c_str());
  return ordering;
}

std::string FactorMemory::message() const {
  char text[240];
  if (status == -19)
    std::snprintf(text, sizeof text,
                  "out of memory: the factorisation of the tangent needs %.0f MiB more than the "
                  "working memory MUMPS may use (ICNTL(23); MUMPS INFOG(1) = -19)",
                  requested_mib);
  else
    std::snprintf(text, sizeof text,
                  "out of memory: the factorisation of the tangent could not allocate %.0f MiB "
                  "(MUMPS INFOG(1) = %d)",
                  requested_mib, status);
  return text;
}

bool is_mumps_factor(Mat F) {
  MatSolverType type = nullptr;
  return F != nullptr && MatFactorGetSolverType(F, &type) == 0 && type != nullptr &&
         std::string(type) == MATSOLVERMUMPS;
}

FactorMemory factor_memory(Mat F) {
  FactorMemory memory;
  if (!is_mumps_factor(F)) return memory;
  PetscInt status = 0;
  PLISSE_PETSC(MatMumpsGetInfog(F, 1, &status));
  memory.status = static_cast<int>(status);
  switch (status) {
    case -8:
    case -9:
    case -11:
    case -14:
    case -15:
    case -17:
    case -20:
      memory.workspace_too_small = true;
      return memory;
    case -13:
    case -19:
      break;
    default:
      return memory;
  }
  memory.out_of_memory = true;
  // INFO(2) of the rank that failed: the size of the allocation refused (-13) or the memory
  // missing (-19), in entries (8 bytes). The other ranks have INFO(1) = -1 and INFOG(2) names the
  // failing one.
  PetscInt local = 0, size = 0;
  PLISSE_PETSC(MatMumpsGetInfo(F, 1, &local));
  if (local == status) PLISSE_PETSC(MatMumpsGetInfo(F, 2, &size));
  memory.requested_mib = mumps_count(size) * 8.0 / (1024.0 * 1024.0);
  return memory;
}

namespace {
WorkspaceGrowth g_workspace_growth;
}  // namespace

WorkspaceGrowth factor_workspace_growth() { return g_workspace_growth; }

bool grow_factor_workspace(PC pc, const FactorMemory& memory) {
  WorkspaceGrowth& growth = g_workspace_growth;
  if (!memory.workspace_too_small || growth.count >= kMaxWorkspaceGrowths) return false;
  Mat F = nullptr;
  PLISSE_PETSC(PCFactorGetMatrix(pc, &F));
  PetscInt percent = 0;
  PLISSE_PETSC(MatMumpsGetIcntl(F, 14, &percent));
  const PetscInt grown = std::max<PetscInt>(2 * percent, 40);
  // The next factor is made from the options of this one's prefix.
  const char* prefix = nullptr;
  PLISSE_PETSC(MatGetOptionsPrefix(F, &prefix));
  std::string name = "-";
  if (prefix) name += prefix;
  name += "mat_mumps_icntl_14";
  PLISSE_PETSC(PetscOptionsSetValue(nullptr, name.c_str(), std::to_string(grown).c_str()));
  PLISSE_PETSC(PCReset(pc));
  growth = {growth.count + 1, static_cast<int>(grown), memory.status};
  return true;
}

void configure_iterative(KSP ksp, IS u, IS p, const LinearSolverSettings& settings) {
  PLISSE_CHECK((u == nullptr) == (p == nullptr),
               "configure_iterative: give both index sets or none");
  // Flexible GMRES: right preconditioning, so the tolerance applies to the true residual
  // ||K dx + R||, and the preconditioner may change between iterations (an inner Krylov solve
  // chosen with -fieldsplit_p_ksp_type gmres, say).
  PLISSE_PETSC(KSPSetType(ksp, KSPFGMRES));
  PLISSE_PETSC(KSPGMRESSetRestart(ksp, settings.restart));
  // Classical Gram-Schmidt with a second pass where needed: without it a long restart cycle lost
  // orthogonality (200 vectors took 222 iterations where 100 took 125 on a shell).
  PLISSE_PETSC(KSPGMRESSetCGSRefinementType(ksp, KSP_GMRES_CGS_REFINE_IFNEEDED));
  PLISSE_PETSC(
      KSPSetTolerances(ksp, settings.rtol, PETSC_DEFAULT, PETSC_DEFAULT, settings.max_iterations));
  PLISSE_PETSC(KSPSetInitialGuessNonzero(ksp, PETSC_FALSE));
  PC pc = nullptr;
  PLISSE_PETSC(KSPGetPC(ksp, &pc));
  // A type change destroys the PC's data: the splits of an earlier call do not accumulate.
  PLISSE_PETSC(PCSetType(pc, PCNONE));
  PLISSE_PETSC(PCSetType(pc, PCFIELDSPLIT));
  if (u != nullptr) {
    PLISSE_PETSC(PCFieldSplitSetIS(pc, "u", u));
    PLISSE_PETSC(PCFieldSplitSetIS(pc, "p", p));
  }
  PLISSE_PETSC(PCFieldSplitSetType(pc, PC_COMPOSITE_SCHUR));
  PLISSE_PETSC(PCFieldSplitSetSchurFactType(pc, PC_FIELDSPLIT_SCHUR_FACT_UPPER));
  // selfp: S_p = C - B diag(A)^-1 B^T, assembled; C != 0 in general (the condensed bubble), and
  // B diag(A)^-1 B^T is a scaled pressure Laplacian-like operator where C vanishes.
  PLISSE_PETSC(PCFieldSplitSetSchurPre(pc, PC_FIELDSPLIT_SCHUR_PRE_SELFP, nullptr));

  // The sub-solvers are created at PCSetUp, after the options are read: their defaults go into
  // the database (PCFieldSplit names them <ksp prefix>fieldsplit_<field>_).
  const char* prefix = nullptr;
  PLISSE_PETSC(KSPGetOptionsPrefix(ksp, &prefix));
  set_default_option(prefix, "fieldsplit_u_ksp_type", KSPPREONLY);
  set_default_option(prefix, "fieldsplit_u_pc_type", PCHYPRE);
  set_default_option(prefix, "fieldsplit_u_pc_hypre_type", "boomeramg");
  // Coarsening for 3-D problems (hypre's BoomerAMG guide: HMIS coarsening with extended+i
  // interpolation, strength threshold 0.5 in 3-D; one level of aggressive coarsening): measured
  // on the stretched cube at 14^3 cells, the same GMRES iterations as hypre's defaults (50 against
  // 54) in a third of the time, the set-up of the default hierarchy being the cost.
  set_default_option(prefix, "fieldsplit_u_pc_hypre_boomeramg_coarsen_type", "HMIS");
  set_default_option(prefix, "fieldsplit_u_pc_hypre_boomeramg_interp_type", "ext+i");
  set_default_option(prefix, "fieldsplit_u_pc_hypre_boomeramg_strong_threshold", "0.5");
  set_default_option(prefix, "fieldsplit_u_pc_hypre_boomeramg_agg_nl", "1");
  set_default_option(prefix, "fieldsplit_p_ksp_type", KSPPREONLY);
  set_default_option(prefix, "fieldsplit_p_pc_type", PCJACOBI);
}

}  // namespace plisse
