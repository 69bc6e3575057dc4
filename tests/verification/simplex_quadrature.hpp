#pragma once
/// Collapsed (Duffy) Gauss rules on the triangle and the tetrahedron, of any order, for the error
/// norms and loads of the verification tests (docs/verification/mms.md, section "Quadrature").
///
/// The cube [0,1]^d is mapped onto the simplex by
///   triangle:     ξ1 = s,  ξ2 = t (1 - s),                       dA = (1 - s) ds dt
///   tetrahedron:  ξ1 = s,  ξ2 = t (1 - s),  ξ3 = w (1 - s)(1 - t), dV = (1 - s)² (1 - t) ds dt dw
/// [Duffy, SIAM J. Numer. Anal. 19 (1982) 1260; Karniadakis & Sherwin, Spectral/hp Element
/// Methods, 2nd ed., section 3.2]. With n Gauss-Legendre points per direction (exact for degree
/// 2n - 1 in each variable) the rule is exact for polynomials of total degree 2n - 2 on the
/// triangle and 2n - 3 on the tetrahedron (the Jacobian takes one, resp. two, of those degrees in
/// s), has positive weights and n^d points.
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace plisse::test {

/// Gauss-Legendre rule on [0, 1]: nodes and weights (sum 1).
struct GaussLegendre01 {
  std::vector<double> nodes, weights;
};

/// n-point Gauss-Legendre rule on [0, 1], nodes by Newton's method on P_n from the Chebyshev-like
/// guesses cos(π (i + 3/4) / (n + 1/2)) [Abramowitz & Stegun 22.16.6], to machine precision.
inline GaussLegendre01 gauss_legendre_01(int n) {
  GaussLegendre01 rule;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;  // three-term recurrence (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}
      for (int k = 1; k < n; ++k) {
        const double p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1);
        p0 = p1;
        p1 = p2;
      }
      const double Pn = n == 0 ? 1.0 : p1, Pn_1 = p0;
      derivative = n * (x * Pn - Pn_1) / (x * x - 1.0);
      const double dx = Pn / derivative;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // On [-1, 1]: w = 2 / ((1 - x²) P_n'(x)²); halve both for [0, 1].
    rule.nodes.push_back(0.5 * (1.0 - x));
    rule.weights.push_back(1.0 / ((1.0 - x * x) * derivative * derivative));
  }
  return rule;
}

/// Quadrature on a simplex of dimension D: barycentric points (D + 1 coordinates summing to 1) and
/// weights as fractions of the simplex measure (sum 1).
template <int D>
struct SimplexRule {
  std::vector<std::array<double, D + 1>> points;
  std::vector<double> weights;
};

/// Duffy rule with n Gauss points per direction on the triangle (exact for degree 2n - 2).
inline SimplexRule<2> collapsed_triangle_rule(int n) {
  const GaussLegendre01 g = gauss_legendre_01(n);
  SimplexRule<2> rule;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double s = g.nodes[i], t = g.nodes[j];
      const double xi1 = s, xi2 = t * (1.0 - s);
      rule.points.push_back({1.0 - xi1 - xi2, xi1, xi2});
      rule.weights.push_back(2.0 * g.weights[i] * g.weights[j] * (1.0 - s));  // area 1/2
    }
  return rule;
}

/// Duffy rule with n Gauss points per direction on the tetrahedron (exact for degree 2n - 3).
inline SimplexRule<3> collapsed_tet_rule(int n) {
  const GaussLegendre01 g = gauss_legendre_01(n);
  SimplexRule<3> rule;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const double s = g.nodes[i], t = g.nodes[j], w = g.nodes[k];
        const double xi1 = s, xi2 = t * (1.0 - s), xi3 = w * (1.0 - s) * (1.0 - t);
        rule.points.push_back({1.0 - xi1 - xi2 - xi3, xi1, xi2, xi3});
        rule.weights.push_back(6.0 * g.weights[i] * g.weights[j] * g.weights[k] * (1.0 - s) *
                               (1.0 - s) * (1.0 - t));  // volume 1/6
      }
  return rule;
}

}  // namespace plisse::test
