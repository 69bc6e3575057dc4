#include "material/inelastic.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace plisse {
namespace {

constexpr int kSym = 6;  // xx, yy, zz, xy, yz, xz

Mat3d unpack(std::span<const double> v) {
  Mat3d S;
  S << v[0], v[3], v[5],  //
      v[3], v[1], v[4],   //
      v[5], v[4], v[2];
  return S;
}

void pack(const Mat3d& S, std::span<double> v) {
  v[0] = S(0, 0);
  v[1] = S(1, 1);
  v[2] = S(2, 2);
  v[3] = S(0, 1);
  v[4] = S(1, 2);
  v[5] = S(0, 2);
}

/// Adds c δ_ik T_LJ to A (column-major vec: (i, J) -> i + 3 J): the tangent of F ↦ c F T.
void add_right_product(double c, const Mat3d& T, Mat9d& A) {
  for (int J = 0; J < 3; ++J)
    for (int L = 0; L < 3; ++L)
      for (int i = 0; i < 3; ++i) A(i + 3 * J, i + 3 * L) += c * T(L, J);
}

}  // namespace

int Viscoelasticity::n_terms() const {
  int n = 0;
  while (n < kMaxTerms && beta(n) > 0.0) ++n;
  return n;
}

int InelasticLaw::history_size() const {
  const int n = viscoelastic.n_terms();
  return (mullins.present() ? 1 : 0) + (n > 0 ? kSym * (1 + n) : 0);
}

PointResponse evaluate_inelastic(const InelasticLaw& law, const PointResponse& elastic,
                                 const Mat3d& F, std::span<const double> converged,
                                 std::span<double> now, double dt) {
  PLISSE_CHECK(static_cast<int>(converged.size()) == law.history_size() &&
                   (now.empty() || now.size() == converged.size()),
               "inelastic point: " << converged.size() << " history values for a law of "
                                   << law.history_size());
  PointResponse out = elastic;
  std::size_t next = 0;

  // Mullins softening (MR1-MR4): the stress is scaled by η; during unloading η depends on W0, which
  // adds dη/dW0 P0 ⊗ P0 to the tangent. On the primary curve (W0 at its largest) η = 1.
  if (law.mullins.present()) {
    const MullinsSoftening& mu = law.mullins;
    const double W0 = elastic.W;
    const double Wmax = std::max(converged[0], W0);
    if (W0 < Wmax) {
      const double scale = mu.m + mu.beta * Wmax;
      const double x = (Wmax - W0) / scale;
      const double eta = 1.0 - std::erf(x) / mu.r;
      const double deta_dW0 = 2.0 / std::sqrt(std::numbers::pi) * std::exp(-x * x) / (mu.r * scale);
      const Eigen::Map<const Vec9d> P0(elastic.P.data());
      out.W = eta * W0;
      out.P = eta * elastic.P;
      out.A = eta * elastic.A + deta_dW0 * (P0 * P0.transpose());
    }
    if (!now.empty()) now[0] = Wmax;
    next = 1;
  }

  // Viscoelasticity (V1-V5) on the softened isochoric stress Se = F⁻¹ Pe.
  const int n = law.viscoelastic.n_terms();
  if (n == 0) return out;
  const Mat3d Finv = F.inverse();
  Mat3d Se = Finv * out.P;
  Se = 0.5 * (Se + Se.transpose());  // symmetric in exact arithmetic
  const Mat3d Se_old = unpack(converged.subspan(next, kSym));
  Mat3d Q_sum = Mat3d::Zero();
  double g = 0.0;  // Σ β_i exp(-dt / (2 τ_i)): the step's instantaneous stiffening
  for (int i = 0; i < n; ++i) {
    const double beta = law.viscoelastic.beta(i), tau = law.viscoelastic.tau(i);
    const double half = std::exp(-0.5 * std::max(dt, 0.0) / tau);
    const Mat3d Q_old = unpack(converged.subspan(next + kSym * (1 + i), kSym));
    const Mat3d Q = half * half * Q_old + beta * half * (Se - Se_old);  // V3
    Q_sum += Q;
    g += beta * half;
    if (!now.empty()) pack(Q, now.subspan(next + kSym * (1 + i), kSym));
  }
  if (!now.empty()) pack(Se, now.subspan(next, kSym));
  // P = Pe + F Σ Q_i (V4). With dQ_i = β_i e_i dSe and F dSe = dPe - dF Se:
  //   dP = (1 + g) dPe - g dF Se + dF Σ Q_i   (V5)
  out.P += F * Q_sum;
  out.A *= 1.0 + g;
  add_right_product(-g, Se, out.A);
  add_right_product(1.0, Q_sum, out.A);
  return out;
}

}  // namespace plisse
