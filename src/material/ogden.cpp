#include "material/ogden.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "material/isochoric_invariants.hpp"

namespace plisse {
namespace {

/// (x^k - y^k) / (x - y) for x, y > 0 given x^k and y^k, and its limit k y^(k-1) at x = y.
/// Formed as written only while x and y are apart (|d| > 1e-2 with d = (x - y) / y: at most 100
/// ulps lost); closer, as y^(k-1) ((1 + d)^k - 1) / d with (1 + d)^k - 1 = expm1(k log1p(d)), which
/// keeps its relative accuracy as d -> 0 (materials.md, O6).
double divided_power_difference(double x, double y, double x_k, double y_k, double k) {
  const double d = (x - y) / y;
  if (std::abs(d) > 1e-2) return (x_k - y_k) / (x - y);
  if (d == 0.0) return k * y_k / y;
  return y_k / y * std::expm1(k * std::log1p(d)) / d;
}

/// C = FᵀF in its principal basis: eigenvalues e_a = λ_a² (ascending), unit eigenvectors N_a as
/// the columns of N, and the logarithms of the isochoric ones, ln ē_a = ln e_a - 2/3 ln J.
struct Principal {
  double J = 1.0;
  double J_m23 = 1.0;
  Vec3d e;
  Vec3d log_ebar;
  Mat3d N;
};

Principal principal_kinematics(const Mat3d& F) {
  const IsochoricKinematics k = compute_isochoric_kinematics(F);  // throws for det F <= 0
  // The QR-based solver, not the closed form (computeDirect): its eigenvectors stay orthonormal
  // and accurate when eigenvalues coincide, where the tangent needs them. computeDirect was 20 %
  // faster per point and failed the tangent, frame-indifference and equibiaxial tests (1e-6 to
  // 1e-12 relative) at equal and near-equal stretches.
  const Eigen::SelfAdjointEigenSolver<Mat3d> eig(k.C);
  Principal s;
  s.J = k.J;
  s.J_m23 = k.J_m23;
  s.e = eig.eigenvalues();
  s.N = eig.eigenvectors();
  const double log_J_m23 = std::log(k.J_m23);
  for (int a = 0; a < 3; ++a) s.log_ebar(a) = std::log(s.e(a)) + log_J_m23;
  return s;
}

}  // namespace

Ogden::Terms Ogden::terms() const {
  Terms t;
  const double mus[3] = {mu1, mu2, mu3}, alphas[3] = {alpha1, alpha2, alpha3};
  for (int p = 0; p < 3; ++p) {
    if (mus[p] == 0.0) continue;
    t.mu[t.n] = mus[p];
    t.alpha[t.n] = alphas[p];
    ++t.n;
  }
  return t;
}

double Ogden::energy_density(const Mat3d& F) const {
  const Principal s = principal_kinematics(F);
  const Terms t = terms();
  double W = 0.0;
  for (int p = 0; p < t.n; ++p) {
    const double m = 0.5 * t.alpha[p];
    // Σ_a (ē_a^m - 1) with expm1: exact to rounding near the reference state (O1).
    double sum = 0.0;
    for (int a = 0; a < 3; ++a) sum += std::expm1(m * s.log_ebar(a));
    W += t.mu[p] / t.alpha[p] * sum;
  }
  return W;
}

PointResponse Ogden::evaluate(const Mat3d& F) const {
  const Principal s = principal_kinematics(F);
  const Terms t = terms();
  const Vec3d& e = s.e;
  const double J_m43 = s.J_m23 * s.J_m23;

  // w_a = ∂W/∂e_a (O2), w_ab = ∂²W/∂e_a∂e_b (O3) and D_ab = (w_a - w_b) / (e_a - e_b) (O5), summed
  // over the terms. Per term, with m = α/2, x_a = ē_a^m - 1 and T = Σ_a ē_a^m:
  //   w_a  = μ/2 (ē_a^m - T/3) / e_a,
  //   w_ab = μ m / (2 e_a e_b) (ē_a^m δ_ab - (ē_a^m + ē_b^m)/3 + T/9) - δ_ab w_a / e_a,
  //   D_ab = μ/2 (J^(-4/3) (ē_a^(m-1) - ē_b^(m-1)) / (ē_a - ē_b) + T / (3 e_a e_b)).
  double W = 0.0;
  Vec3d w = Vec3d::Zero();
  Mat3d w2 = Mat3d::Zero();
  Mat3d D = Mat3d::Zero();
  for (int p = 0; p < t.n; ++p) {
    const double mu = t.mu[p], m = 0.5 * t.alpha[p];
    Vec3d x, power;  // ē_a^m - 1 (accurate near 1) and ē_a^m
    for (int a = 0; a < 3; ++a) {
      x(a) = std::expm1(m * s.log_ebar(a));
      power(a) = 1.0 + x(a);
    }
    const double T = 3.0 + x.sum();
    W += mu / t.alpha[p] * x.sum();
    Vec3d wp;
    for (int a = 0; a < 3; ++a) wp(a) = 0.5 * mu * (x(a) - x.sum() / 3.0) / e(a);  // (O2)
    w += wp;
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        double v = (a == b ? power(a) : 0.0) - (power(a) + power(b)) / 3.0 + T / 9.0;
        v *= 0.5 * mu * m / (e(a) * e(b));
        if (a == b) v -= wp(a) / e(a);
        w2(a, b) += v;  // (O3)
        if (a < b) {
          const double ebar_a = s.J_m23 * e(a), ebar_b = s.J_m23 * e(b);
          D(a, b) += 0.5 * mu *
                     (J_m43 * divided_power_difference(ebar_a, ebar_b, power(a) / ebar_a,
                                                       power(b) / ebar_b, m - 1.0) +
                      T / (3.0 * e(a) * e(b)));  // (O5)
        }
      }
    }
  }

  // n_a = F N_a; X_a = vec(n_a ⊗ N_a); Y_ab = vec(n_a ⊗ N_b + n_b ⊗ N_a) (O4).
  const Mat3d n = F * s.N;
  Eigen::Matrix<double, 9, 3> X;
  for (int a = 0; a < 3; ++a) {
    const Mat3d Xa = n.col(a) * s.N.col(a).transpose();
    X.col(a) = Eigen::Map<const Vec9d>(Xa.data());
  }
  PointResponse r;
  r.W = W;
  // S = 2 Σ_a w_a N_a ⊗ N_a, P = F S = Σ_a 2 w_a n_a ⊗ N_a (O4).
  const Mat3d S = s.N * (2.0 * w).asDiagonal() * s.N.transpose();
  r.P = n * (2.0 * w).asDiagonal() * s.N.transpose();

  // A = Σ_ab 4 w_ab X_a X_bᵀ + Σ_{a<b} 2 D_ab Y_ab Y_abᵀ + δ_ik S_JL (O6).
  r.A.noalias() = X * (4.0 * w2) * X.transpose();
  for (int a = 0; a < 3; ++a) {
    for (int b = a + 1; b < 3; ++b) {
      const Mat3d Yab = n.col(a) * s.N.col(b).transpose() + n.col(b) * s.N.col(a).transpose();
      const Eigen::Map<const Vec9d> y(Yab.data());
      r.A.noalias() += (2.0 * D(a, b)) * y * y.transpose();
    }
  }
  for (int j = 0; j < 3; ++j)
    for (int l = 0; l < 3; ++l)
      for (int i = 0; i < 3; ++i) r.A(i + 3 * j, i + 3 * l) += S(j, l);
  return r;
}

}  // namespace plisse
