#pragma once
/// The limit of a quantity computed on three meshes, each with its cells halved, by Aitken's Δ²
/// (Richardson's extrapolation with the order observed from the three): exact when the changes
/// fall by a constant factor per halving.
#include <cmath>

namespace plisse::test {

struct Extrapolation {
  double limit = 0.0;  ///< r₀ = r₃ - (r₂ - r₃) / (q - 1), q = (r₁ - r₂) / (r₂ - r₃)
  double order = 0.0;  ///< log₂ q, the observed order of convergence
};

/// From the values on the coarsest (r1), the middle (r2) and the finest (r3) mesh.
inline Extrapolation extrapolate_halvings(double r1, double r2, double r3) {
  const double q = (r1 - r2) / (r2 - r3);
  return {r3 - (r2 - r3) / (q - 1.0), std::log2(q)};
}

}  // namespace plisse::test
