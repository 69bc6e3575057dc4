#pragma once
/// Fully symmetric quadrature rules on the tetrahedron, in barycentric coordinates.
///
/// A rule maps  ∫_T f dV  ≈  V Σ_q w_q f(L^q),  with Σ_q w_q = 1 (weights are fractions of the
/// volume V) and L^q = (L_0, L_1, L_2, L_3) the barycentric coordinates of point q.
/// All rules here are invariant under the 24 permutations of the vertices and have positive weights
/// (docs/theory/mixed_up.md, section 5, Q1-Q5, explains which rule the MINI kernel uses).
#include <array>

namespace plisse {

template <int N>
struct TetQuadrature {
  static constexpr int n_points = N;
  int degree = 0;  ///< polynomials of total degree <= degree are exact
  std::array<std::array<double, 4>, N> points{};  ///< barycentric coordinates, each row sums to 1
  std::array<double, N> weights{};                ///< fractions of the volume, sum to 1, all > 0
};

namespace quadrature_detail {
/// The 4-point S31 orbit {(a, b, b, b) and permutations}, b = (1 - a) / 3.
constexpr std::array<std::array<double, 4>, 4> s31_orbit(double a) {
  const double b = (1.0 - a) / 3.0;
  return {{{a, b, b, b}, {b, a, b, b}, {b, b, a, b}, {b, b, b, a}}};
}
}  // namespace quadrature_detail

/// Degree 2, 4 points: one S31 orbit with a = (5 + 3√5)/20, weights 1/4.
/// [Keast, Comput. Methods Appl. Mech. Engrg. 55 (1986) 339, rule 2; any FE text, e.g.
/// Zienkiewicz & Taylor, The Finite Element Method vol. 1, table 5.4.]
inline constexpr TetQuadrature<4> kTetQuadratureDegree2 = {
    2, quadrature_detail::s31_orbit(0.58541019662496845446), {0.25, 0.25, 0.25, 0.25}};

/// Degree 5, 14 points, positive weights: two S31 orbits and one S22 orbit
/// {(c, c, d, d) and permutations, d = 1/2 - c}. [Walkington, "Quadrature on simplices of
/// arbitrary dimension", CMU report (2000); Keast (1986) rule 6.] The values were recomputed here
/// to 25 digits (mpmath) from the six moment conditions for 1, L0², L0³, L0⁴, L0² L1², L0³ L1²;
/// tests/unit/element/quadrature_test.cpp checks all monomials of degree <= 5 on a distorted
/// tetrahedron. Not used by the MINI kernel (docs/theory/mixed_up.md, Q5); kept to measure the
/// effect of exact bubble integration.
inline constexpr TetQuadrature<14> kTetQuadratureDegree5 = [] {
  TetQuadrature<14> rule{};
  rule.degree = 5;
  const auto outer = quadrature_detail::s31_orbit(0.7217942490673263207930283);
  const auto inner = quadrature_detail::s31_orbit(0.0673422422100981706079628);
  const double c = 0.04550370412564964949188053, d = 0.5 - c;
  const std::array<std::array<double, 4>, 6> edges = {
      {{c, c, d, d}, {c, d, c, d}, {c, d, d, c}, {d, c, c, d}, {d, c, d, c}, {d, d, c, c}}};
  for (int i = 0; i < 4; ++i) {
    rule.points[i] = outer[i];
    rule.weights[i] = 0.07349304311636194954371021;
    rule.points[4 + i] = inner[i];
    rule.weights[4 + i] = 0.1126879257180158507991857;
  }
  for (int i = 0; i < 6; ++i) {
    rule.points[8 + i] = edges[i];
    rule.weights[8 + i] = 0.04254602077708146643806943;
  }
  return rule;
}();

}  // namespace plisse
