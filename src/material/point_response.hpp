#pragma once
/// What a hyperelastic model returns at one material point.
#include "core/types.hpp"

namespace plisse {

/// Isochoric strain energy and its derivatives with respect to F (first Piola-Kirchhoff stress and
/// the material tangent acting on vec F, column-major: index i + 3 j for F(i, j)).
struct PointResponse {
  double W = 0.0;  ///< [MPa] = [mJ/mm^3]
  Mat3d P;         ///< dW/dF [MPa]
  Mat9d A;         ///< d vec(P) / d vec(F) [MPa]
};

/// The response of `material` at quadrature point q of an element, deformation F: what the element
/// kernels call. A model with history (material/inelastic_points.hpp) answers through
/// `evaluate_at(q, F)`, since its response depends on the point's own past; an elastic model
/// through `evaluate(F)`.
template <class Material>
PointResponse evaluate_at_point(const Material& material, int q, const Mat3d& F) {
  if constexpr (requires { material.evaluate_at(q, F); }) {
    return material.evaluate_at(q, F);
  } else {
    return material.evaluate(F);
  }
}

}  // namespace plisse
