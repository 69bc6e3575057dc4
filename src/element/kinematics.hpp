#pragma once
/// Pointwise kinematics shared by the element kernels (docs/theory/mixed_up.md).
#include "core/types.hpp"

namespace plisse {

/// cof F = J F⁻ᵀ, by columns: f1 × f2, f2 × f0, f0 × f1 for F = [f0 f1 f2].
inline Mat3d cofactor(const Mat3d& F) {
  Mat3d cof;
  cof.col(0) = F.col(1).cross(F.col(2));
  cof.col(1) = F.col(2).cross(F.col(0));
  cof.col(2) = F.col(0).cross(F.col(1));
  return cof;
}

/// det(I + H) - 1 = tr H + ½((tr H)² - tr H²) + det H: exact, and free of the cancellation of
/// det F - 1 when |H| is small (mixed_up.md, U4).
inline double det_minus_one(const Mat3d& H) {
  const double trace = H.trace();
  return trace + 0.5 * (trace * trace - (H * H).trace()) + H.determinant();
}

/// E(v)_ik = ε_ikm v_m (= -[v]_×). The pressure term of the tangent contracted with two
/// gradients, G·𝔻·H, equals E(F (G × H)) (mixed_up.md, K1a).
inline Mat3d epsilon_dot(const Vec3d& v) {
  Mat3d E;
  E << 0.0, v(2), -v(1),  //
      -v(2), 0.0, v(0),   //
      v(1), -v(0), 0.0;
  return E;
}

}  // namespace plisse
