#pragma once
/// Mooney-Rivlin model, isochoric part (the pressure term lives in the element).
///   W = c1 (Ī1 - 3) + c2 (Ī2 - 3)      [paper, Table 1 and eq. 7; isochoric split: Holzapfel,
///                                       Nonlinear Solid Mechanics, 2000, ch. 6]
///   small-strain shear modulus mu = 2 (c1 + c2) (materials.md, M13)
/// Admissible parameters (registry): c1 >= 0, c1 + c2 > 0. In incompressible uniaxial tension
/// sigma = 2 (λ² - 1/λ)(c1 + c2/λ) (M14): c1 < 0 makes the stress fall at large stretch and is
/// refused; c2 < 0 makes it fall in compression (below λ = -c2/c1 and before), as sets fitted to
/// test data often have: it is accepted, and a run reports the stretches over which the set is
/// stable and warns when an element leaves them (app/run_recorder.hpp).
#include "core/types.hpp"
#include "material/isochoric_invariants.hpp"
#include "material/point_response.hpp"

namespace plisse {

struct MooneyRivlin {
  double c1 = 0.0;  ///< [MPa], >= 0
  double c2 = 0.0;  ///< [MPa], c1 + c2 > 0

  /// W(F) for any scalar type (dual numbers in tests). Precondition: det F > 0.
  template <class T>
  T energy(const Mat3<T>& F) const {
    const IsochoricInvariants<T> inv = compute_isochoric_invariants(F);
    return c1 * (inv.I1bar - 3.0) + c2 * (inv.I2bar - 3.0);
  }
  /// W and its partial derivatives in (Ī1, Ī2).
  InvariantDerivatives invariant_derivatives(double I1bar, double I2bar) const {
    InvariantDerivatives d;
    d.W = c1 * (I1bar - 3.0) + c2 * (I2bar - 3.0);
    d.W_1 = c1;
    d.W_2 = c2;
    return d;
  }
  /// W, P = dW/dF, A = dP/dF. Throws InadmissibleDeformation if det F <= 0.
  PointResponse evaluate(const Mat3d& F) const { return evaluate_isochoric(*this, F); }
  /// [MPa]
  double shear_modulus() const { return 2.0 * (c1 + c2); }
};

}  // namespace plisse
