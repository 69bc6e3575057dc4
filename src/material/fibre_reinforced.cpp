#include "material/fibre_reinforced.hpp"

#include "material/neo_hookean.hpp"

namespace plisse {
namespace {

/// ψ(x), ψ'(x), ψ''(x) of one family at Ī4 = 1 + x, zero for x <= 0 (materials.md, F2).
struct FibreDerivatives {
  double psi = 0.0, d1 = 0.0, d2 = 0.0;
};

FibreDerivatives fibre_derivatives(double k1, double k2, double x) {
  if (!(x > 0.0)) return {};
  const double e = std::exp(k2 * x * x);
  FibreDerivatives d;
  d.psi = k2 > 0.0 ? k1 / (2.0 * k2) * std::expm1(k2 * x * x) : 0.5 * k1 * x * x;
  d.d1 = k1 * x * e;
  d.d2 = k1 * (1.0 + 2.0 * k2 * x * x) * e;
  return d;
}

}  // namespace

FibreReinforced::Fibres FibreReinforced::fibres() const {
  Fibres f;
  for (const Vec3d& a : {Vec3d(a1_x, a1_y, a1_z), Vec3d(a2_x, a2_y, a2_z)}) {
    if (a.squaredNorm() == 0.0) continue;
    f.a[f.n++] = a.normalized();
  }
  return f;
}

double FibreReinforced::energy_density(const Mat3d& F) const {
  const IsochoricKinematics k = compute_isochoric_kinematics(F);  // throws for det F <= 0
  double W = c1 * (k.I1bar - 3.0);
  const Fibres f = fibres();
  for (int i = 0; i < f.n; ++i)
    W += fibre_derivatives(k1, k2, k.J_m23 * (F * f.a[i]).squaredNorm() - 1.0).psi;
  return W;
}

PointResponse FibreReinforced::evaluate(const Mat3d& F) const {
  const IsochoricKinematics k = compute_isochoric_kinematics(F);  // throws for det F <= 0
  PointResponse r =
      compute_isochoric_response(k, NeoHookean{c1}.invariant_derivatives(k.I1bar, k.I2bar));
  const Fibres f = fibres();
  const double b = k.J_m23;
  const Mat3d& G = k.G;
  const Eigen::Map<const Vec9d> g(G.data());
  for (int i = 0; i < f.n; ++i) {
    const Vec3d& a = f.a[i];
    const Vec3d Fa = F * a;
    const double I4 = Fa.squaredNorm();
    const FibreDerivatives d = fibre_derivatives(k1, k2, b * I4 - 1.0);
    if (d.d1 == 0.0 && d.d2 == 0.0) continue;  // a family in compression carries nothing
    r.W += d.psi;
    // dĪ4/dF = b (H - 2/3 I4 G), H = 2 (F a) ⊗ a  (F3).
    const Mat3d H = 2.0 * Fa * a.transpose();
    const Mat3d dI4 = b * (H - 2.0 / 3.0 * I4 * G);
    r.P += d.d1 * dI4;
    // A += ψ'' dĪ4 ⊗ dĪ4 + ψ' d²Ī4 with (F4)
    //   d²Ī4/dF_ij dF_kl = b [2 δ_ik a_j a_l - 2/3 (H_ij G_kl + G_ij H_kl) + 4/9 I4 G_ij G_kl
    //                         + 2/3 I4 G_il G_kj].
    const Eigen::Map<const Vec9d> dv(dI4.data()), h(H.data());
    r.A.noalias() += d.d2 * dv * dv.transpose();
    const double w = d.d1 * b;
    r.A.noalias() += w * (-2.0 / 3.0 * (h * g.transpose() + g * h.transpose()) +
                          4.0 / 9.0 * I4 * g * g.transpose());
    for (int l = 0; l < 3; ++l)
      for (int kk = 0; kk < 3; ++kk)
        for (int j = 0; j < 3; ++j)
          for (int ii = 0; ii < 3; ++ii) {
            double v = 2.0 / 3.0 * I4 * G(ii, l) * G(kk, j);
            if (ii == kk) v += 2.0 * a(j) * a(l);
            r.A(ii + 3 * j, kk + 3 * l) += w * v;
          }
  }
  return r;
}

}  // namespace plisse
