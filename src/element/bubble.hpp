#pragma once
/// The cubic bubble of the MINI element (P1+/P1) on a tetrahedron.
///
///   N_b = 256 L_0 L_1 L_2 L_3,   Grad N_b = 256 Σ_c (Π_{d≠c} L_d) Grad L_c
/// (docs/theory/mixed_up.md, eq. U2). N_b = 1 at the centroid and vanishes on every face, so the
/// bubble is local to one element [Arnold, Brezzi & Fortin, Calcolo 21 (1984) 337].
#include <array>

#include "core/types.hpp"

namespace plisse::mini {

/// Scale of the bubble: 256 = 1 / (1/4)^4 makes N_b(centroid) = 1.
inline constexpr double kBubbleScale = 256.0;

/// N_b at barycentric coordinates L (dimensionless).
inline double bubble_value(const std::array<double, 4>& L) {
  return kBubbleScale * L[0] * L[1] * L[2] * L[3];
}

/// Coefficients c_a of Grad N_b = Σ_a c_a Grad L_a at barycentric coordinates L:
/// c_a = 256 Π_{d≠a} L_d (dimensionless).
inline std::array<double, 4> bubble_gradient_coefficients(const std::array<double, 4>& L) {
  return {kBubbleScale * L[1] * L[2] * L[3], kBubbleScale * L[0] * L[2] * L[3],
          kBubbleScale * L[0] * L[1] * L[3], kBubbleScale * L[0] * L[1] * L[2]};
}

/// Grad N_b [1/mm] at barycentric coordinates L, given the constant Grad L_a [1/mm].
inline Vec3d bubble_gradient(const std::array<double, 4>& L, const std::array<Vec3d, 4>& grad_L) {
  const std::array<double, 4> c = bubble_gradient_coefficients(L);
  return c[0] * grad_L[0] + c[1] * grad_L[1] + c[2] * grad_L[2] + c[3] * grad_L[3];
}

}  // namespace plisse::mini
