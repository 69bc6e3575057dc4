#pragma once
/// Neo-Hookean model, isochoric part (the pressure term lives in the element).
///   W = c1 (Ī1 - 3)          [paper, Table 1; isochoric split: Holzapfel, Nonlinear Solid
///                             Mechanics, 2000, ch. 6]
///   small-strain shear modulus mu = 2 c1 (materials.md, M13)
#include "core/types.hpp"
#include "material/isochoric_invariants.hpp"
#include "material/point_response.hpp"

namespace plisse {

struct NeoHookean {
  double c1 = 0.0;  ///< [MPa], > 0

  /// W(F) for any scalar type (dual numbers in tests). Precondition: det F > 0.
  template <class T>
  T energy(const Mat3<T>& F) const {
    const IsochoricInvariants<T> inv = compute_isochoric_invariants(F);
    return c1 * (inv.I1bar - 3.0);
  }
  /// W and its partial derivatives in (Ī1, Ī2).
  InvariantDerivatives invariant_derivatives(double I1bar, double /*I2bar*/) const {
    InvariantDerivatives d;
    d.W = c1 * (I1bar - 3.0);
    d.W_1 = c1;
    return d;
  }
  /// W, P = dW/dF, A = dP/dF. Throws InadmissibleDeformation if det F <= 0.
  PointResponse evaluate(const Mat3d& F) const { return evaluate_isochoric(*this, F); }
  /// [MPa]
  double shear_modulus() const { return 2.0 * c1; }
};

}  // namespace plisse
