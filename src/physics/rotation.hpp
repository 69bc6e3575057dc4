#pragma once
/// A vector turned by the rotation with rotation vector θ (axis θ/|θ|, angle |θ|), with its first
/// and second derivatives in θ (docs/theory/caps.md, G1-G3): what a rigid cap needs for the
/// residual and tangent of its tied nodes.
#include <array>

#include "core/types.hpp"

namespace plisse {

/// Largest angle |θ| [rad] the series of rotate() are summed for (to round-off): 2π, where the
/// rotation vector parametrisation itself breaks down.
inline constexpr double kMaxRotationAngle = 6.283185307179586;

struct RotatedVector {
  Vec3d value;                   ///< R(θ) d
  Mat3d jacobian;                ///< ∂(R d)_i / ∂θ_j
  std::array<Mat3d, 3> hessian;  ///< hessian[i](j, k) = ∂²(R d)_i / ∂θ_j ∂θ_k
};

/// R(θ) d by Rodrigues' formula R d = d + a(s) θ × d + b(s) θ × (θ × d), s = θ·θ, with
/// a = sin φ / φ and b = (1 − cos φ) / φ² (φ = |θ|) summed as power series in s, which are smooth
/// through θ = 0 (G1-G3). Precondition: |θ| <= kMaxRotationAngle.
RotatedVector rotate(const Vec3d& theta, const Vec3d& d);

}  // namespace plisse
