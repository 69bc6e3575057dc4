#pragma once
/// Fung-type exponential model, isochoric part (the pressure term lives in the element).
///   W = mu / (2 gamma) (exp(gamma (Ī1 - 3)) - 1)      [paper, Table 1, and its ref. 3 (Fung)]
///   W_1 = mu/2 exp(gamma (Ī1 - 3)),  W_11 = gamma W_1
///   small-strain shear modulus = mu (materials.md, M13)
#include <cmath>

#include "core/types.hpp"
#include "material/isochoric_invariants.hpp"
#include "material/point_response.hpp"

namespace plisse {

struct Fung {
  double mu = 0.0;     ///< [MPa], > 0
  double gamma = 0.0;  ///< [-], > 0 (stiffening exponent)

  /// W(F) for any scalar type (dual numbers in tests). Precondition: det F > 0.
  template <class T>
  T energy(const Mat3<T>& F) const {
    using std::exp;
    const IsochoricInvariants<T> inv = compute_isochoric_invariants(F);
    return mu / (2.0 * gamma) * (exp(gamma * (inv.I1bar - 3.0)) - 1.0);
  }
  /// W and its partial derivatives in (Ī1, Ī2).
  InvariantDerivatives invariant_derivatives(double I1bar, double /*I2bar*/) const {
    const double x = gamma * (I1bar - 3.0);
    InvariantDerivatives d;
    d.W = mu / (2.0 * gamma) * std::expm1(x);  // expm1: no cancellation near the reference state
    d.W_1 = 0.5 * mu * std::exp(x);
    d.W_11 = gamma * d.W_1;
    return d;
  }
  /// W, P = dW/dF, A = dP/dF. Throws InadmissibleDeformation if det F <= 0.
  PointResponse evaluate(const Mat3d& F) const { return evaluate_isochoric(*this, F); }
  /// [MPa]
  double shear_modulus() const { return mu; }
};

}  // namespace plisse
