#pragma once
/// The MINI (P1+/P1) mixed displacement-pressure tetrahedron, total Lagrangian, with the bubble
/// condensed statically and consistently (docs/theory/mixed_up.md).
///
///   Π_e(u, b, p) = ∫_Ωe [ W(F) - p_h (J - 1) - p_h² / (2κ) ] dV                      (U1)
///
/// W is the isochoric energy of the material, p the pressure (positive in compression),
/// σ = σ_iso - p I; 1/κ = 0 is exact incompressibility. The kernels are templates on the material:
/// any type with `PointResponse evaluate(const Mat3d& F) const` (W, P = ∂W/∂F, A = ∂P/∂F) works, or
/// with `evaluate_at(q, F)` for a model whose points carry history (material/point_response.hpp).
/// No heap allocation; inputs are const, outputs owned by the caller: thread-safe.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "element/mini_integrals.hpp"
#include "element/mini_layout.hpp"
#include "element/tet_geometry.hpp"
#include "material/inadmissible_deformation.hpp"
#include "material/point_response.hpp"

namespace plisse::mini {

namespace detail {

/// Adds all quadrature points at bubble b to `sums`; min_J receives min_q det F.
/// Returns false (and stops) at the first point with det F <= 0 or not finite, or where the
/// material rejects F (InadmissibleDeformation, e.g. Gent past its locking limit): the element
/// then reports a failed status instead of throwing out of an assembly loop.
template <class Material>
bool integrate_points(const TetGeometry& g, const NodalState& s, const BubbleVec& b,
                      const Material& mat, MiniIntegrals& sums, double& min_J) {
  min_J = std::numeric_limits<double>::infinity();
  for (int q = 0; q < kQuadPoints; ++q) {
    const PointKinematics k = compute_point_kinematics(g, s, b, q);
    min_J = std::min(min_J, k.J);
    if (!(k.J > 0.0) || !std::isfinite(k.J)) return false;
    try {
      sums.add_point(q, k, evaluate_at_point(mat, q, k.F));
    } catch (const InadmissibleDeformation&) {
      return false;
    }
  }
  return true;
}

}  // namespace detail

/// The uncondensed system in (x_e, b) at a given bubble b (eqs. R1-R3, K1-K6): for tests and
/// diagnostics. K_xx is filled only when `with_K_xx`. Returns false when det F <= 0 at a point.
template <class Material>
bool assemble_mini_uncondensed(const TetGeometry& g, const ElemVec& x_e, const Material& mat,
                               double inverse_bulk_modulus, const BubbleVec& bubble,
                               MiniLocalSystem& sys, bool with_K_xx) {
  const NodalState s = gather_nodal_state(g, x_e);
  MiniIntegrals sums(g, with_K_xx);
  double min_J = 0;
  if (!detail::integrate_points(g, s, bubble, mat, sums, min_J)) return false;
  sums.bubble_block(sys);
  sums.coupled_blocks(s, inverse_bulk_modulus, sys);
  return true;
}

/// Condensed residual and tangent of one element in the 16 nodal unknowns x_e.
///
/// Solves r_b(x_e, b) = 0 by Newton's method (B1), warm-started from `bubble` (or from 0 if the
/// warm start gives det F <= 0; steps into det F <= 0 are halved), to the tolerance (B2); then
/// returns r_e = r_x(x_e, b*) (linearised at the last iterate, B3) and, if K_e is given, the Schur
/// complement K_e = K_xx - K_xb K_bb⁻¹ K_bx (B4), which is the exact derivative dr_e/dx_e by the
/// implicit function theorem (B5).
///   inverse_bulk_modulus: 1/κ [1/MPa], 0 for exact incompressibility.
///   bubble: in, warm start [mm]; out, converged b* (unchanged when the status is not ok).
///   r_e [N for u rows, mm³ for p rows], K_e: outputs, overwritten; K_e == nullptr: residual only.
/// status.ok is false when det F <= 0 at a quadrature point or the bubble solve fails; r_e and
/// K_e are then zero.
///   db_dx: when not null, receives the bubble's sensitivity -K_bb⁻¹ K_bx at the solution (B6),
///   the warm start of the next evaluation (BubbleWarmStart).
template <class Material>
ElementStatus assemble_mini(const TetGeometry& g, const ElemVec& x_e, const Material& mat,
                            double inverse_bulk_modulus, BubbleVec& bubble, ElemVec& r_e,
                            ElemMat* K_e, BubbleSensitivity* db_dx = nullptr) {
  const NodalState s = gather_nodal_state(g, x_e);
  ElementStatus status;
  BubbleVec b = bubble;
  BubbleVec b_previous = b;             // last admissible iterate
  BubbleVec delta = BubbleVec::Zero();  // step taken from it
  int halvings = 0;
  int cuts = 0;  // successive halvings of a step that raised |r_b| (B1)
  double previous_r_norm = std::numeric_limits<double>::infinity();
  MiniLocalSystem sys;
  for (int iteration = 1; iteration <= kMaxBubbleIterations; ++iteration) {
    status.bubble_iterations = iteration;
    MiniIntegrals sums(g, K_e != nullptr);
    if (!detail::integrate_points(g, s, b, mat, sums, status.min_J)) {
      // Safeguards (B1): an inadmissible warm start is replaced by b = 0 (x_e may have moved
      // far since it was stored); a Newton step into det F <= 0 is halved, up to
      // kMaxBubbleHalvings.
      if (iteration == 1 && !b.isZero(0.0)) {
        b.setZero();
        b_previous = b;
        continue;
      }
      if (iteration == 1 || halvings == kMaxBubbleHalvings) break;
      ++halvings;
      delta *= 0.5;
      b = b_previous + delta;
      continue;
    }
    halvings = 0;
    sums.bubble_block(sys);
    // Past the first iterations, a step that raised |r_b| is halved instead of taken: where the
    // material's tangent jumps (Mullins softening at the largest energy reached), the points can
    // switch between its branches at every step and plain Newton cycles (B1).
    const double r_norm = sys.r_b.norm();
    if (iteration > kUndampedBubbleIterations && r_norm > previous_r_norm &&
        cuts < kMaxBubbleHalvings) {
      ++cuts;
      delta *= 0.5;
      b = b_previous + delta;
      continue;
    }
    cuts = 0;
    previous_r_norm = r_norm;
    const BubbleStep step = compute_bubble_step(sys, g.size);
    if (!step.ok) break;
    if (step.converged) {
      sums.coupled_blocks(s, inverse_bulk_modulus, sys);
      condense_bubble(sys, step, r_e, K_e);
      bubble = b + step.delta;
      if (db_dx != nullptr) db_dx->noalias() = -(step.K_bb_inverse * sys.K_xb.transpose());
      return status;
    }
    b_previous = b;
    delta = step.delta;
    b += delta;
  }
  status.ok = false;
  r_e.setZero();
  if (K_e != nullptr) K_e->setZero();
  return status;
}

/// assemble_mini warm-started from the first-order prediction of the bubble at x_e (B6) instead of
/// the last bubble: in the late iterations of a Newton solve, where x_e moves little, the
/// prediction already meets the tolerance (B2), and one material evaluation per point replaces
/// two. `warm` receives the new bubble, its sensitivity and x_e (unchanged when the status is not
/// ok).
template <class Material>
ElementStatus assemble_mini(const TetGeometry& g, const ElemVec& x_e, const Material& mat,
                            double inverse_bulk_modulus, BubbleWarmStart& warm, ElemVec& r_e,
                            ElemMat* K_e) {
  BubbleVec bubble = warm.predict(x_e);
  BubbleSensitivity db_dx;
  ElementStatus status = assemble_mini(g, x_e, mat, inverse_bulk_modulus, bubble, r_e, K_e, &db_dx);
  if (!status.ok) {
    // Far from x_at the prediction can be worse than the last bubble: the solve from the last
    // bubble, as without a prediction, decides.
    bubble = warm.b;
    status = assemble_mini(g, x_e, mat, inverse_bulk_modulus, bubble, r_e, K_e, &db_dx);
  }
  if (status.ok) {
    warm.b = bubble;
    warm.db_dx = db_dx;
    warm.x_at = x_e;
  }
  return status;
}

/// Volume averages of Cauchy stress, J, von Mises stress and pressure over the element at the
/// given state (x_e, bubble); the bubble is not re-solved (pass the converged one).
///   σ = J⁻¹ (P - p cof F) Fᵀ = J⁻¹ P Fᵀ - p I   (Y1)
/// Precondition: det F > 0 at every quadrature point (checked, throws plisse::Error).
template <class Material>
ElementFields compute_element_fields(const TetGeometry& g, const ElemVec& x_e, const Material& mat,
                                     const BubbleVec& bubble) {
  const NodalState s = gather_nodal_state(g, x_e);
  ElementFields fields;
  fields.cauchy.setZero();
  fields.J = 0.0;
  fields.pressure = 0.0;
  for (int q = 0; q < kQuadPoints; ++q) {
    const PointKinematics k = compute_point_kinematics(g, s, bubble, q);
    PLISSE_CHECK(k.J > 0.0, "element fields: det F = " << k.J << " <= 0 at quadrature point " << q);
    const double w = g.weight[q] / g.volume;
    const Mat3d sigma =
        evaluate_at_point(mat, q, k.F).P * k.F.transpose() / k.J - k.p * Mat3d::Identity();
    fields.cauchy += w * sigma;
    fields.J += w * k.J;
    fields.pressure += w * k.p;
  }
  fields.von_mises = von_mises_stress(fields.cauchy);
  return fields;
}

/// Element energy Π_e (U1) at (x_e, bubble) [mJ = N mm]; its gradient is the uncondensed
/// residual. For tests and line-search diagnostics. Returns NaN when det F <= 0 at a point.
template <class Material>
double compute_element_energy(const TetGeometry& g, const ElemVec& x_e, const Material& mat,
                              double inverse_bulk_modulus, const BubbleVec& bubble) {
  const NodalState s = gather_nodal_state(g, x_e);
  double energy = 0.0;
  for (int q = 0; q < kQuadPoints; ++q) {
    const PointKinematics k = compute_point_kinematics(g, s, bubble, q);
    if (!(k.J > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    energy += g.weight[q] * (evaluate_at_point(mat, q, k.F).W - k.p * k.J_minus_1 -
                             0.5 * inverse_bulk_modulus * k.p * k.p);
  }
  return energy;
}

}  // namespace plisse::mini
