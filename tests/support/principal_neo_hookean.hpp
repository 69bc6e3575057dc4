#pragma once
/// The compressible neo-Hookean energy of a nearly incompressible plisse material (the isochoric
/// model plus the volumetric energy of the pressure term, docs/theory/shell.md KL12) written out
/// in principal stretches, with its plane-stress thickness found by bisection: a closed form for
/// the plane-stress tests that shares no code with the kernels.
#include <cmath>

#include "core/types.hpp"

namespace plisse::test {

/// Neo-Hookean W = c1 (J^(-2/3) (λ1² + λ2² + λ3²) - 3) + κ/2 (J - 1)², J = λ1 λ2 λ3, with its
/// derivatives in the principal stretches: the 3-D energy of KL12 written out by hand.
struct PrincipalNeoHookean {
  double c1, kappa;
  double energy(const Vec3d& l) const {
    const double J = l.prod();
    return c1 * (std::pow(J, -2.0 / 3.0) * l.squaredNorm() - 3.0) +
           0.5 * kappa * (J - 1.0) * (J - 1.0);
  }
  /// ∂W/∂λ_i.
  double derivative(const Vec3d& l, int i) const {
    const double J = l.prod();
    return c1 * std::pow(J, -2.0 / 3.0) * (2.0 * l(i) - 2.0 / 3.0 * l.squaredNorm() / l(i)) +
           kappa * (J - 1.0) * J / l(i);
  }
  /// The λ3 of plane stress, ∂W/∂λ3 = 0, by bisection on [0.2, 5] (W is convex in λ3 there).
  double plane_stress_thickness(double l1, double l2) const {
    double lo = 0.2, hi = 5.0;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (derivative(Vec3d(l1, l2, mid), 2) > 0.0 ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  }
};

}  // namespace plisse::test
