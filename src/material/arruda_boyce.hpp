#pragma once
/// Arruda-Boyce (eight-chain) model, five-term series, isochoric part (pressure term in the
/// element).
///   W = mu sum_{i=1..5} alpha_i / lambda_m^(2i-2) (Ī1^i - 3^i),
///   alpha = (1/2, 1/20, 11/1050, 19/7000, 519/673750)
///     [Arruda & Boyce, J. Mech. Phys. Solids 41 (1993) 389; series as in Holzapfel, Nonlinear
///      Solid Mechanics, 2000, or the Abaqus theory manual]
///   small-strain shear modulus mu0 = 2 W_1(3) = mu (1 + 3/(5 lm^2) + 99/(175 lm^4)
///                                      + 513/(875 lm^6) + 42039/(67375 lm^8))   (M13)
/// The series is a polynomial: it has no locking singularity, unlike the inverse-Langevin model.
#include <array>

#include "core/types.hpp"
#include "material/isochoric_invariants.hpp"
#include "material/point_response.hpp"

namespace plisse {

struct ArrudaBoyce {
  double mu = 0.0;        ///< [MPa], > 0 (not the initial shear modulus: see shear_modulus())
  double lambda_m = 0.0;  ///< [-], > 1: locking stretch of the chain network

  static constexpr std::array<double, 5> kAlpha = {1.0 / 2.0, 1.0 / 20.0, 11.0 / 1050.0,
                                                   19.0 / 7000.0, 519.0 / 673750.0};

  /// W(F) for any scalar type (dual numbers in tests). Precondition: det F > 0.
  template <class T>
  T energy(const Mat3<T>& F) const {
    const IsochoricInvariants<T> inv = compute_isochoric_invariants(F);
    const double beta = 1.0 / (lambda_m * lambda_m);
    T W = 0.0 * inv.I1bar;
    T power = inv.I1bar;  // Ī1^i
    double power3 = 3.0, scale = mu;
    for (int i = 0; i < 5; ++i) {
      W = W + scale * kAlpha[i] * (power - power3);
      power = power * inv.I1bar;
      power3 *= 3.0;
      scale *= beta;
    }
    return W;
  }
  /// W and its partial derivatives in (Ī1, Ī2).
  InvariantDerivatives invariant_derivatives(double I1bar, double /*I2bar*/) const {
    const double beta = 1.0 / (lambda_m * lambda_m);
    InvariantDerivatives d;
    double power = 1.0, power3 = 1.0, scale = mu;  // Ī1^(i-1), 3^(i-1), mu beta^(i-1)
    double power_m2 = 0.0;                         // Ī1^(i-2)
    for (int i = 1; i <= 5; ++i) {
      const double c = scale * kAlpha[i - 1];
      d.W += c * (power * I1bar - power3 * 3.0);
      d.W_1 += c * i * power;
      d.W_11 += c * i * (i - 1) * power_m2;
      power_m2 = power;
      power *= I1bar;
      power3 *= 3.0;
      scale *= beta;
    }
    return d;
  }
  /// W, P = dW/dF, A = dP/dF. Throws InadmissibleDeformation if det F <= 0.
  PointResponse evaluate(const Mat3d& F) const { return evaluate_isochoric(*this, F); }
  /// mu0 = 2 W_1 at Ī1 = 3 [MPa]
  double shear_modulus() const { return 2.0 * invariant_derivatives(3.0, 3.0).W_1; }
};

}  // namespace plisse
