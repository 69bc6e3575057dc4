#pragma once
/// The manufactured displacement and pressure fields of the convergence tests on the unit cube
/// (derivation in docs/verification/mms.md, equations M1-M6).
///
///   χ(X) = (X1 + g(X2, X3), X2 + h(X3), X3)        Grad χ unit upper triangular, det = 1  (M1)
///   ψ(y) = (y1, y2, y3 + k(y1, y2))                 Grad ψ unit lower triangular, det = 1  (M2)
///   x = φ(X) = ψ(χ(X)) + ε w(X),  w = ½ (X1², X2², X3²)                                     (M3)
///   g = a cos(π X2 / 2) sin(π X3),  h = b sin(π X3 / 2),  k = c sin(π y1 / 2) cos(π y2 / 2)
///   p(X) = p0 sin(π (X1 + X2 / 2)) cos(π X3 / 2)                                            (M4)
///
/// With ε = 0 the map is exactly isochoric, J = det(Grad ψ) det(Grad χ) = 1 everywhere, and all
/// three displacement components vary in all directions. ε > 0 adds a smooth volume change for the
/// near-incompressible case. Lengths in mm, pressures in MPa.
#include <cmath>
#include <numbers>

#include "core/types.hpp"

namespace plisse::test {

struct ManufacturedSolution {
  double a = 0.1, b = 0.1, c = 0.1;  ///< amplitudes of g, h, k [mm]
  double epsilon = 0.0;              ///< amplitude of the dilatational part w [1/mm]
  double p0 = 0.5;                   ///< pressure amplitude [MPa]

  static constexpr double kPi = std::numbers::pi;

  /// Displacement u = φ(X) - X [mm].
  Vec3d u(const Vec3d& X) const {
    const Vec3d y = chi(X);
    const double k = c * std::sin(kPi * y(0) / 2) * std::cos(kPi * y(1) / 2);
    return Vec3d(y(0) - X(0), y(1) - X(1), k) + epsilon * 0.5 * X.cwiseProduct(X);
  }

  /// F = Grad φ = Grad ψ(χ(X)) Grad χ(X) + ε diag(X) (chain rule, M5).
  Mat3d F(const Vec3d& X) const {
    const Vec3d y = chi(X);
    Mat3d grad_chi = Mat3d::Identity();
    grad_chi(0, 1) = -a * kPi / 2 * std::sin(kPi * X(1) / 2) * std::sin(kPi * X(2));
    grad_chi(0, 2) = a * kPi * std::cos(kPi * X(1) / 2) * std::cos(kPi * X(2));
    grad_chi(1, 2) = b * kPi / 2 * std::cos(kPi * X(2) / 2);
    Mat3d grad_psi = Mat3d::Identity();
    grad_psi(2, 0) = c * kPi / 2 * std::cos(kPi * y(0) / 2) * std::cos(kPi * y(1) / 2);
    grad_psi(2, 1) = -c * kPi / 2 * std::sin(kPi * y(0) / 2) * std::sin(kPi * y(1) / 2);
    Mat3d result = grad_psi * grad_chi;
    result.diagonal() += epsilon * X;
    return result;
  }
  Mat3d grad_u(const Vec3d& X) const { return F(X) - Mat3d::Identity(); }

  /// Pressure [MPa], positive in compression.
  double p(const Vec3d& X) const {
    return p0 * std::sin(kPi * (X(0) + X(1) / 2)) * std::cos(kPi * X(2) / 2);
  }
  /// Grad p [MPa/mm].
  Vec3d grad_p(const Vec3d& X) const {
    const double s = std::sin(kPi * (X(0) + X(1) / 2)), co = std::cos(kPi * (X(0) + X(1) / 2));
    const double z = std::cos(kPi * X(2) / 2), dz = -kPi / 2 * std::sin(kPi * X(2) / 2);
    return p0 * Vec3d(kPi * co * z, kPi / 2 * co * z, s * dz);
  }

 private:
  Vec3d chi(const Vec3d& X) const {
    return Vec3d(X(0) + a * std::cos(kPi * X(1) / 2) * std::sin(kPi * X(2)),
                 X(1) + b * std::sin(kPi * X(2) / 2), X(2));
  }
};

}  // namespace plisse::test
