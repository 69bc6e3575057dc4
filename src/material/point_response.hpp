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

}  // namespace plisse
