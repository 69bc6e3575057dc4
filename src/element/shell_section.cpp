#include "element/shell_section.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace plisse::shell {

namespace {

/// Legendre polynomial P_n(z) and its derivative, by the three-term recurrence.
void legendre(int n, double z, double& p, double& dp) {
  double p_previous = 1.0;
  p = z;
  for (int k = 2; k <= n; ++k) {
    const double p_next = ((2.0 * k - 1.0) * z * p - (k - 1.0) * p_previous) / k;
    p_previous = p;
    p = p_next;
  }
  dp = n * (z * p - p_previous) / (z * z - 1.0);
}

}  // namespace

ShellSection make_shell_section(double thickness, int n_points) {
  PLISSE_CHECK(thickness > 0.0 && std::isfinite(thickness),
               "shell section: thickness must be > 0 (got " << thickness << ")");
  PLISSE_CHECK(n_points >= kMinThicknessPoints && n_points <= kMaxThicknessPoints,
               "shell section: " << n_points << " points through the thickness; must be "
                                 << kMinThicknessPoints << " to " << kMaxThicknessPoints);
  ShellSection s;
  s.thickness = thickness;
  s.n_points = n_points;
  for (int g = 0; g < n_points; ++g) {
    // Newton's method on P_n from Chebyshev's estimate of the g-th root; converges in a few steps.
    double z = std::cos(std::numbers::pi * (g + 0.75) / (n_points + 0.5));
    double p = 0.0;
    double dp = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      legendre(n_points, z, p, dp);
      const double step = p / dp;
      z -= step;
      if (std::abs(step) < 1e-16) break;
    }
    legendre(n_points, z, p, dp);
    const double w = 2.0 / ((1.0 - z * z) * dp * dp);  // on [-1, 1], sums to 2
    s.zeta[g] = 0.5 * thickness * z;
    s.weight[g] = 0.5 * thickness * w;
  }
  return s;
}

}  // namespace plisse::shell
