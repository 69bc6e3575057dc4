#pragma once
/// Yeoh model, isochoric part (the pressure term lives in the element).
///   W = c1 (Ī1 - 3) + c2 (Ī1 - 3)^2 + c3 (Ī1 - 3)^3     [Yeoh, Rubber Chem. Technol. 66 (1993)
///   754] small-strain shear modulus mu = 2 c1 (materials.md, M13)
/// Admissible parameters (registry): c1 > 0, c3 >= 0 and W_1 = c1 + 2 c2 x + 3 c3 x^2 > 0 for all
/// x = Ī1 - 3 >= 0, i.e. c2 >= 0 or c2^2 < 3 c1 c3 (a negative c2, as in Yeoh's own fits, is
/// allowed when c3 keeps the stiffness positive).
#include "core/types.hpp"
#include "material/isochoric_invariants.hpp"
#include "material/point_response.hpp"

namespace plisse {

struct Yeoh {
  double c1 = 0.0;  ///< [MPa], > 0
  double c2 = 0.0;  ///< [MPa]
  double c3 = 0.0;  ///< [MPa], >= 0

  /// W(F) for any scalar type (dual numbers in tests). Precondition: det F > 0.
  template <class T>
  T energy(const Mat3<T>& F) const {
    const IsochoricInvariants<T> inv = compute_isochoric_invariants(F);
    const T x = inv.I1bar - 3.0;
    return x * (c1 + x * (c2 + x * c3));
  }
  /// W and its partial derivatives in (Ī1, Ī2).
  InvariantDerivatives invariant_derivatives(double I1bar, double /*I2bar*/) const {
    const double x = I1bar - 3.0;
    InvariantDerivatives d;
    d.W = x * (c1 + x * (c2 + x * c3));
    d.W_1 = c1 + x * (2.0 * c2 + 3.0 * c3 * x);
    d.W_11 = 2.0 * c2 + 6.0 * c3 * x;
    return d;
  }
  /// W, P = dW/dF, A = dP/dF. Throws InadmissibleDeformation if det F <= 0.
  PointResponse evaluate(const Mat3d& F) const { return evaluate_isochoric(*this, F); }
  /// [MPa]
  double shear_modulus() const { return 2.0 * c1; }
};

}  // namespace plisse
