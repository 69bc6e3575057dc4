#pragma once
/// Output averages of one element, the same for every element family.
#include <cmath>

#include "core/types.hpp"

namespace plisse {

/// Volume averages over one element (for output).
struct ElementFields {
  Mat3d cauchy;      ///< (1/V) ∫ σ dV,  σ = J⁻¹ P Fᵀ - p I  [MPa]
  double J;          ///< (1/V) ∫ det F dV  [-]
  double von_mises;  ///< sqrt(3/2 dev σ̄ : dev σ̄) of the averaged Cauchy stress σ̄  [MPa]
  double pressure;   ///< (1/V) ∫ p_h dV  [MPa], the element's pressure field (positive in
                     ///< compression); not -tr σ̄ / 3, which differs by the isochoric part
};

/// sqrt(3/2 dev σ : dev σ), the von Mises stress of the Cauchy stress σ [MPa].
inline double von_mises_stress(const Mat3d& cauchy) {
  const Mat3d deviator = cauchy - cauchy.trace() / 3.0 * Mat3d::Identity();
  return std::sqrt(1.5 * deviator.squaredNorm());
}

/// All fields zero.
inline ElementFields zero_element_fields() {
  ElementFields zero;
  zero.cauchy.setZero();
  zero.J = zero.von_mises = zero.pressure = 0.0;
  return zero;
}

}  // namespace plisse
