#pragma once
/// Settings of the Newton iteration and of its linear solver (plain data: no PETSc here, so that
/// the case reader can fill them).
#include "core/error.hpp"

namespace plisse {

enum class LineSearch { bt, basic, l2, cp };

enum class LinearSolverType { direct, iterative };

/// The solver of the linear system K dx = -R of each Newton iteration (`solver.newton.linear`).
/// direct: MUMPS LDL^T (LU for an unsymmetric tangent). iterative: flexible GMRES preconditioned
/// by a Schur-complement field split of the mixed u-p system with algebraic multigrid (hypre
/// BoomerAMG) on the displacement block (solver/linear_solver.hpp). The stability check and the
/// eigenmodes factorise with MUMPS whatever the choice here.
struct LinearSolverSettings {
  LinearSolverType type = LinearSolverType::direct;
  /// iterative: GMRES stops when ||K dx + R|| <= rtol ||R|| (true, unpreconditioned residual);
  /// in (0, 1). The Newton residual then falls by about this factor per iteration at least.
  double rtol = 1e-6;
  int max_iterations = 1000;  ///< iterative: GMRES iterations per Newton iteration, >= 1
  int restart = 50;           ///< iterative: Krylov vectors kept before a restart, >= 1
  InputPlace place;           ///< where `linear:` is (empty when not given)
};

struct NewtonSettings {
  double rtol = 1e-8;       ///< relative residual tolerance, in (0, 1)
  double atol = 1e-10;      ///< absolute residual tolerance [N], >= 0
  int max_iterations = 25;  ///< >= 1
  /// A solve is given up (the step then is cut back) after this many iterations in a row that
  /// each leave ||R|| above stall_ratio times the one before (solver/stall_watch.hpp); 0: only
  /// max_iterations ends a solve. >= 0.
  int stall_iterations = 0;
  double stall_ratio = 0.9;  ///< in (0, 1)
  LineSearch line_search = LineSearch::bt;
  /// Direct solver only: before factorising anew, iterate x -= F^-1 R(x) with the freshest
  /// factorisation already at hand (the last Newton tangent, or the stability check's tangent of
  /// the last converged state) while every such iteration cuts ||R|| at least tenfold; Newton
  /// proper takes over from the last accepted iterate (newton_solver.hpp).
  bool reuse_factor = true;
  /// With reuse_factor: when an iteration with the kept factorisation cuts ||R|| less than
  /// tenfold, Newton steps whose linear system GMRES solves, preconditioned by that
  /// factorisation, with at most this many iterations (newton_solver.hpp); 0: none, Newton
  /// factorises anew instead.
  int reuse_krylov_iterations = 20;
  LinearSolverSettings linear;
};

}  // namespace plisse
