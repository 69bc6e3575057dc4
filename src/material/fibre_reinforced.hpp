#pragma once
/// Fibre-reinforced model for woven fabrics and reinforced membranes (Holzapfel, Gasser & Ogden,
/// J. Elasticity 61 (2000) 1, eq. (4.3) with the isochoric fibre invariants), isochoric part (the
/// pressure term lives in the element):
///   W = c1 (Ī1 - 3) + Σ_f ψ(Ī4f),   ψ(x) = k1 / (2 k2) (exp(k2 (x - 1)²) - 1) for x > 1, 0 else,
///   Ī4f = J^(-2/3) a_f · C a_f, a_f a unit fibre direction of the reference configuration
/// (materials.md, F1-F5). Up to two families, each constant in space. The fibres carry load in
/// extension only (Ī4f > 1), as fabric yarns that buckle when shortened; ψ is then continuous
/// with its first derivative, and its second jumps from 0 to k1 at Ī4f = 1. k2 = 0 gives the
/// quadratic limit ψ = k1 (x - 1)² / 2.
/// Not isotropic: W(F Q) ≠ W(F) for a rotation Q of the reference. `plisse fit` and the run's
/// Drucker watch, which assume isotropy, leave it out (kIsotropic).
#include <cmath>

#include "core/types.hpp"
#include "material/isochoric_invariants.hpp"
#include "material/point_response.hpp"

namespace plisse {

struct FibreReinforced {
  static constexpr bool kIsotropic = false;

  double c1 = 0.0;    ///< [MPa], > 0: the matrix, neo-Hookean
  double k1 = 0.0;    ///< [MPa], >= 0: fibre stiffness
  double k2 = 0.0;    ///< [-], >= 0: fibre stiffening
  double a1_x = 0.0;  ///< first fibre direction (normalised here), not zero
  double a1_y = 0.0;
  double a1_z = 0.0;
  double a2_x = 0.0;  ///< second fibre direction; all zero: no second family
  double a2_y = 0.0;
  double a2_z = 0.0;

  /// The unit fibre directions, `n` of them (1 or 2).
  struct Fibres {
    Vec3d a[2];
    int n = 0;
  };
  Fibres fibres() const;

  /// W(F) for any scalar type (dual numbers in tests). Precondition: det F > 0.
  template <class T>
  T energy(const Mat3<T>& F) const {
    using std::exp;
    using std::log;
    const IsochoricInvariants<T> inv = compute_isochoric_invariants(F);
    T W = c1 * (inv.I1bar - 3.0);
    const T J_m23 = exp(-2.0 / 3.0 * log(inv.J));
    const Fibres f = fibres();
    for (int k = 0; k < f.n; ++k) {
      const Vec3<T> Fa = F * f.a[k].cast<T>();
      const T x = J_m23 * Fa.squaredNorm() - 1.0;
      if (!(x > 0.0)) continue;
      if (k2 > 0.0) {
        W += k1 / (2.0 * k2) * (exp(k2 * x * x) - 1.0);
      } else {
        W += 0.5 * k1 * x * x;
      }
    }
    return W;
  }
  /// W(F) [MPa]. Throws InadmissibleDeformation if det F <= 0.
  double energy_density(const Mat3d& F) const;
  /// W, P = dW/dF, A = dP/dF. Throws InadmissibleDeformation if det F <= 0.
  PointResponse evaluate(const Mat3d& F) const;
  /// [MPa]: the matrix's 2 c1 (at F = I the fibres are at Ī4 = 1 and add nothing).
  double shear_modulus() const { return 2.0 * c1; }
};

}  // namespace plisse
