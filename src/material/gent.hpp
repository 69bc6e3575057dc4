#pragma once
/// Gent model (limiting chain extensibility), isochoric part (pressure term lives in the element).
///   W = -mu jm / 2 ln(1 - (Ī1 - 3) / jm)      [Gent, Rubber Chem. Technol. 69 (1996) 59]
///   W_1 = mu / (2 s),  W_11 = mu / (2 jm s^2),  s = 1 - (Ī1 - 3) / jm
///   small-strain shear modulus = mu (materials.md, M13); jm -> infinity gives neo-Hookean.
/// Domain: Ī1 - 3 < jm. evaluate() throws InadmissibleDeformation at or past the limit (the energy
/// is infinite there); energy<T>() does not check and returns NaN or inf.
#include <cmath>

#include "core/types.hpp"
#include "material/isochoric_invariants.hpp"
#include "material/point_response.hpp"

namespace plisse {

struct Gent {
  double mu = 0.0;  ///< [MPa], > 0
  double jm = 0.0;  ///< [-], > 0: limit of Ī1 - 3

  /// W(F) for any scalar type (dual numbers in tests). Preconditions: det F > 0, Ī1 - 3 < jm.
  template <class T>
  T energy(const Mat3<T>& F) const {
    using std::log;
    const IsochoricInvariants<T> inv = compute_isochoric_invariants(F);
    return -0.5 * mu * jm * log(1.0 - (inv.I1bar - 3.0) / jm);
  }
  /// W and its partial derivatives in (Ī1, Ī2). Throws InadmissibleDeformation if Ī1 - 3 >= jm.
  InvariantDerivatives invariant_derivatives(double I1bar, double /*I2bar*/) const {
    const double x = (I1bar - 3.0) / jm;
    if (!(x < 1.0)) throw_past_limit(I1bar);
    const double s = 1.0 - x;
    InvariantDerivatives d;
    d.W = -0.5 * mu * jm * std::log1p(-x);  // log1p: accurate near the reference state
    d.W_1 = 0.5 * mu / s;
    d.W_11 = d.W_1 / (jm * s);
    return d;
  }
  /// W, P = dW/dF, A = dP/dF. Throws InadmissibleDeformation if det F <= 0 or Ī1 - 3 >= jm.
  PointResponse evaluate(const Mat3d& F) const { return evaluate_isochoric(*this, F); }
  /// [MPa]
  double shear_modulus() const { return mu; }

 private:
  [[noreturn]] void throw_past_limit(double I1bar) const;  // cold path, in gent.cpp
};

}  // namespace plisse
