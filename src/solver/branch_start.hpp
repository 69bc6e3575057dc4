#pragma once
/// Where a branch switch starts Newton: Koiter's asymptotic estimate of the buckled state at the
/// current load from the critical mode, the tangent's factor and a few residuals
/// (docs/theory/stability.md, S10a).
#include <petscmat.h>

#include <vector>

#include "solver/mixed_model.hpp"

namespace plisse {

/// The estimate of a buckled state near the unstable equilibrium u along the mode φ.
struct BranchStart {
  /// The one-mode residual g(s) = Φ · R(u + s Φ + s² V) [N] ≈ g0 + k s + q s² + c s³ (S10a),
  /// s [mm], Φ the mode's free vector (scaled as Eigenmode::state: largest nodal displacement 1)
  /// and V the second-order field [1/mm]: k [N/mm], q [N/mm²], c [N/mm³].
  double k = 0.0, q = 0.0, c = 0.0;
  /// The root of k + q s + c s² nearest 0 [mm]: the mode's largest nodal amplitude in the
  /// buckled state; 0 when there is none (k >= 0, or no real root: a subcritical or transcritical
  /// branch that does not come back, S11).
  double amplitude = 0.0;
  /// The full state u + s Φ + s² V at s = amplitude (MixedModel::state() layout); empty when
  /// amplitude is 0.
  std::vector<double> state;
};

/// Koiter's estimate at the model's current state u (a converged, unstable equilibrium):
/// V = K⁻¹ r with r = −½ R″[Φ, Φ] from central differences of the residual at u ± h Φ, its
/// component along Φ removed (Φ · r = 0), then k, q, c fitted to g at s = ±h, ±2h. `mode` is an
/// Eigenmode::state of the tangent at u, `factor` the LDL^T factor of that tangent
/// (InertiaCheck::factor), `h` [mm] the difference step (a fraction of the buckled amplitude;
/// S10a). Throws plisse::Error when an assembly fails (an inverted element at a trial state).
/// Collective; the model is back at its last converged state (restore_converged) on return.
BranchStart asymptotic_branch_start(MixedModel& model, Mat factor, const std::vector<double>& mode,
                                    double h);

}  // namespace plisse
