#include "physics/rotation.hpp"

#include <cmath>

#include "core/error.hpp"

namespace plisse {
namespace {

/// f(s), f'(s), f''(s) for f(s) = Σ_n (−s)^n / (2n + k)!: k = 1 gives a = sin φ / φ, k = 2 gives
/// b = (1 − cos φ) / φ², s = φ² (G2). 40 terms reach round-off for s <= (2π)².
std::array<double, 3> series(double s, int k) {
  std::array<double, 3> f{0.0, 0.0, 0.0};
  double coefficient = 1.0;  // (−1)^n / (2n + k)!
  for (int j = 2; j <= k; ++j) coefficient /= j;
  double power = 1.0, power1 = 0.0, power2 = 0.0;  // s^n, s^(n−1), s^(n−2)
  for (int n = 0; n < 40; ++n) {
    f[0] += coefficient * power;
    f[1] += n * coefficient * power1;
    f[2] += n * (n - 1) * coefficient * power2;
    coefficient /= -(2.0 * n + k + 1) * (2.0 * n + k + 2);
    power2 = power1;
    power1 = power;
    power *= s;
  }
  return f;
}

}  // namespace

RotatedVector rotate(const Vec3d& theta, const Vec3d& d) {
  const double s = theta.squaredNorm();
  PLISSE_CHECK(s <= kMaxRotationAngle * kMaxRotationAngle,
               "rotation angle " << std::sqrt(s) << " rad is beyond 2 pi");
  const auto [a, da, dda] = series(s, 1);
  const auto [b, db, ddb] = series(s, 2);
  const Vec3d c = theta.cross(d);     // θ × d
  const double p = theta.dot(d);      // θ · d
  const Vec3d v = p * theta - s * d;  // θ × (θ × d)
  RotatedVector out;
  out.value = d + a * c + b * v;  // (G1)
  // ∂c/∂θ_j = e_j × d = −[d]× e_j;  ∂v/∂θ_j = e_j p + θ d_j − 2 θ_j d   (G2)
  const Mat3d dc = -cross_matrix(d);
  const Mat3d dv = p * Mat3d::Identity() + theta * d.transpose() - 2.0 * d * theta.transpose();
  out.jacobian =
      2.0 * da * c * theta.transpose() + a * dc + 2.0 * db * v * theta.transpose() + b * dv;
  // (G3): second derivatives, component i of R d.
  for (int i = 0; i < 3; ++i) {
    Mat3d H;
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const double djk = j == k ? 1.0 : 0.0;
        // ∂²v_i/∂θ_j∂θ_k = δ_ij d_k + δ_ik d_j − 2 δ_jk d_i; ∂²c/∂θ² = 0
        const double ddv = (i == j ? d[k] : 0.0) + (i == k ? d[j] : 0.0) - 2.0 * djk * d[i];
        H(j, k) = 4.0 * dda * theta[j] * theta[k] * c[i] + 2.0 * da * djk * c[i] +
                  2.0 * da * (theta[j] * dc(i, k) + theta[k] * dc(i, j)) +
                  4.0 * ddb * theta[j] * theta[k] * v[i] + 2.0 * db * djk * v[i] +
                  2.0 * db * (theta[j] * dv(i, k) + theta[k] * dv(i, j)) + b * ddv;
      }
    out.hessian[i] = H;
  }
  return out;
}

}  // namespace plisse
