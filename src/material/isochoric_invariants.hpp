#pragma once
/// Isochoric invariants of C = F^T F and the one shared map from an energy W(Ī1, Ī2) to the point
/// response (W, P = dW/dF, A = dP/dF). Every isotropic model of this folder goes through it, so the
/// tensor algebra is written, tested and tuned once (docs/architecture.md, "Coding conventions").
/// Derivations and equation numbers: docs/theory/materials.md, eqs. (M1)-(M14).
#include <cmath>

#include "core/types.hpp"
#include "material/point_response.hpp"

namespace plisse {

/// J = det F, Ī1 = J^{-2/3} I1, Ī2 = J^{-4/3} I2 of C = F^T F  (materials.md, M1-M3).
template <class T>
struct IsochoricInvariants {
  T J;
  T I1bar;
  T I2bar;
};

/// The invariants for any scalar type (double, or a dual number in tests). No domain check: for
/// det F <= 0 the result is NaN. The hot path uses compute_isochoric_kinematics instead.
template <class T>
IsochoricInvariants<T> compute_isochoric_invariants(const Mat3<T>& F) {
  using std::exp;  // dual-number overloads are found by argument-dependent lookup
  using std::log;
  const Mat3<T> C = F.transpose() * F;
  const T J = F.determinant();
  const T I1 = C.trace();
  const T I2 = 0.5 * (I1 * I1 - C.squaredNorm());  // tr C^2 = C:C because C is symmetric (M1)
  // J^{-2/3} as exp(-2/3 ln J): Eigen's AutoDiff pow does not nest (dual of dual, for Hessians).
  const T J_m23 = exp(-2.0 / 3.0 * log(J));
  return {J, J_m23 * I1, J_m23 * J_m23 * I2};
}

/// Everything at one point that the response needs, computed once (double only).
struct IsochoricKinematics {
  Mat3d F;
  Mat3d G;             ///< F^{-T} = (1/J) cof F
  Mat3d C;             ///< F^T F
  double J = 1.0;      ///< det F > 0
  double J_m23 = 1.0;  ///< J^{-2/3}
  double I1 = 3.0;
  double I2 = 3.0;
  double I1bar = 3.0;
  double I2bar = 3.0;
};

/// Kinematic quantities of F (materials.md, M1-M3).
/// Throws InadmissibleDeformation when det F is not > 0 (also when F holds NaN): the energy is
/// not defined there, and a silent NaN would only surface later as a failed linear solve.
IsochoricKinematics compute_isochoric_kinematics(const Mat3d& F);

/// A model's energy in the isochoric invariants and its partial derivatives at (Ī1, Ī2):
/// W_1 = dW/dĪ1, W_12 = d^2W/dĪ1dĪ2, ... [MPa].
struct InvariantDerivatives {
  double W = 0.0;
  double W_1 = 0.0;
  double W_2 = 0.0;
  double W_11 = 0.0;
  double W_12 = 0.0;
  double W_22 = 0.0;
};

/// P and A of the energy W(Ī1(F), Ī2(F)) by the chain rule (materials.md, M4-M12):
///   P = W_1 dĪ1/dF + W_2 dĪ2/dF,
///   A = W_1 d²Ī1/dF² + W_2 d²Ī2/dF² + W_11 dĪ1⊗dĪ1 + W_12 (dĪ1⊗dĪ2 + dĪ2⊗dĪ1) + W_22 dĪ2⊗dĪ2.
/// A is symmetric (it is a Hessian). The Ī2 terms are skipped when W_2 = W_12 = W_22 = 0 exactly.
/// No heap; safe to call concurrently.
PointResponse compute_isochoric_response(const IsochoricKinematics& kin,
                                         const InvariantDerivatives& d);

/// The whole evaluation for a model that provides
///   InvariantDerivatives invariant_derivatives(double I1bar, double I2bar) const;
/// Throws InadmissibleDeformation as compute_isochoric_kinematics (and as the model does).
template <class Model>
PointResponse evaluate_isochoric(const Model& model, const Mat3d& F) {
  const IsochoricKinematics k = compute_isochoric_kinematics(F);
  return compute_isochoric_response(k, model.invariant_derivatives(k.I1bar, k.I2bar));
}

}  // namespace plisse
