#pragma once
/// Ogden model with up to three terms, isochoric part (the pressure term lives in the element).
///   W = Σ_p μ_p / α_p (λ̄1^α_p + λ̄2^α_p + λ̄3^α_p - 3),   λ̄_a = J^(-1/3) λ_a
///   [Ogden, Proc. R. Soc. Lond. A 326 (1972) 565, eq. (4.3) with the isochoric stretches;
///    isochoric split: Holzapfel, Nonlinear Solid Mechanics, 2000, section 6.5]
///   small-strain shear modulus mu = 1/2 Σ_p μ_p α_p (materials.md, O7)
/// W is a function of the principal stretches, not of (Ī1, Ī2), so the stress and tangent come
/// from the spectral decomposition of C = FᵀF (materials.md, O1-O6). The tangent's coefficients
/// between two principal directions are divided differences, written so that they stay exact as
/// two stretches meet (uniaxial and equibiaxial states have two equal stretches, the reference
/// state three).
/// Admissible parameters (registry): each term with μ_p ≠ 0 has μ_p α_p > 0 (Ogden's condition,
/// which makes every term's small-strain shear modulus positive and W convex in the logarithmic
/// stretches); a term with μ_p = 0 is absent.
/// No `energy<T>` for dual numbers: the stretches are eigenvalues, whose second derivatives are
/// singular where two of them meet although W is smooth there. The tests check P and A by finite
/// differences and against the invariant models the Ogden form contains (α = 2: neo-Hookean;
/// α = 2 and -2: Mooney-Rivlin).
#include <array>

#include "core/types.hpp"
#include "material/point_response.hpp"

namespace plisse {

struct Ogden {
  double mu1 = 0.0;     ///< [MPa], μ1 α1 > 0
  double alpha1 = 0.0;  ///< [-]
  double mu2 = 0.0;     ///< [MPa], 0 (no second term) or μ2 α2 > 0
  double alpha2 = 0.0;  ///< [-]
  double mu3 = 0.0;     ///< [MPa], 0 (no third term) or μ3 α3 > 0
  double alpha3 = 0.0;  ///< [-]

  /// W(F) [MPa]. Throws InadmissibleDeformation if det F <= 0.
  double energy_density(const Mat3d& F) const;
  /// W, P = dW/dF, A = dP/dF. Throws InadmissibleDeformation if det F <= 0. No heap.
  PointResponse evaluate(const Mat3d& F) const;
  /// [MPa]
  double shear_modulus() const { return 0.5 * (mu1 * alpha1 + mu2 * alpha2 + mu3 * alpha3); }

  /// The terms with μ_p ≠ 0, as (μ_p, α_p); `n` of them.
  struct Terms {
    std::array<double, 3> mu{};
    std::array<double, 3> alpha{};
    int n = 0;
  };
  Terms terms() const;
};

}  // namespace plisse
