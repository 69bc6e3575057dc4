#pragma once
/// Output averages of one element, the same for every element family.
#include <Eigen/Eigenvalues>
#include <algorithm>
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

/// The eigenvalues of the symmetric matrix `s`, largest first.
inline Vec3d principal_values(const Mat3d& s) {
  const Eigen::SelfAdjointEigenSolver<Mat3d> eigen(s, Eigen::EigenvaluesOnly);
  const Vec3d& ascending = eigen.eigenvalues();
  return {ascending[2], ascending[1], ascending[0]};
}

/// The principal stretches of the deformation gradient F, largest first: the square roots of
/// the eigenvalues of C = Fᵀ F [-].
inline Vec3d principal_stretches(const Mat3d& F) {
  const Vec3d c = principal_values(F.transpose() * F);
  return {std::sqrt(std::max(c[0], 0.0)), std::sqrt(std::max(c[1], 0.0)),
          std::sqrt(std::max(c[2], 0.0))};
}

/// All fields zero.
inline ElementFields zero_element_fields() {
  ElementFields zero;
  zero.cauchy.setZero();
  zero.J = zero.von_mises = zero.pressure = 0.0;
  return zero;
}

}  // namespace plisse
