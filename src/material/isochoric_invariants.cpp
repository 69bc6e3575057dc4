#include "material/isochoric_invariants.hpp"

#include <sstream>

#include "material/inadmissible_deformation.hpp"

namespace plisse {

IsochoricKinematics compute_isochoric_kinematics(const Mat3d& F) {
  IsochoricKinematics k;
  k.F = F;
  // cof F by columns of cross products; J = F.col(0) . cof.col(0); F^{-T} = cof F / J (M3).
  Mat3d cof;
  cof.col(0) = F.col(1).cross(F.col(2));
  cof.col(1) = F.col(2).cross(F.col(0));
  cof.col(2) = F.col(0).cross(F.col(1));
  k.J = F.col(0).dot(cof.col(0));
  if (!(k.J > 0.0)) {  // also catches NaN
    std::ostringstream msg;
    msg << "inadmissible deformation: det F = " << k.J
        << " is not > 0 (inverted or degenerate element)";
    throw InadmissibleDeformation(msg.str());
  }
  k.G = cof * (1.0 / k.J);
  k.C.noalias() = F.transpose() * F;
  k.I1 = k.C.trace();
  k.I2 = 0.5 * (k.I1 * k.I1 - k.C.squaredNorm());  // (M1); C symmetric, so tr C^2 = C:C
  const double cbrt_J = std::cbrt(k.J);
  k.J_m23 = 1.0 / (cbrt_J * cbrt_J);  // cbrt is exact at J = 1 and cheaper than pow
  k.I1bar = k.J_m23 * k.I1;           // (M2)
  k.I2bar = k.J_m23 * k.J_m23 * k.I2;
  return k;
}

PointResponse compute_isochoric_response(const IsochoricKinematics& kin,
                                         const InvariantDerivatives& d) {
  const double a = kin.J_m23;  // J^{-2/3}
  const double b = a * a;      // J^{-4/3}
  const double I1 = kin.I1, I2 = kin.I2;
  const bool has_I2 = d.W_2 != 0.0 || d.W_12 != 0.0 || d.W_22 != 0.0;

  // Every first derivative is a combination of the three tensors F, G = F^{-T} and F C; the
  // coefficients in that basis are (M5), (M6):
  //   dĪ1/dF = a (2 F - 2/3 I1 G),   dĪ2/dF = b (2 I1 F - 4/3 I2 G - 2 F C).
  const Vec3d d1(2.0 * a, -2.0 / 3.0 * a * I1, 0.0);
  const Vec3d d2(2.0 * b * I1, -4.0 / 3.0 * b * I2, -2.0 * b);
  Mat3d FC;
  if (has_I2) {
    FC.noalias() = kin.F * kin.C;
  } else {
    FC.setZero();
  }

  PointResponse r;
  r.W = d.W;
  const Vec3d p = d.W_1 * d1 + d.W_2 * d2;  // (M7)
  r.P = p(0) * kin.F + p(1) * kin.G + p(2) * FC;

  // Rank-one part of A (M12): U M U^T with U = [vec F, vec G, vec FC] (9 x 3) and M symmetric 3 x 3
  // collecting the outer products of (M11) and the dyadic terms of (M9), (M10).
  Eigen::Matrix3d M = d.W_11 * d1 * d1.transpose();
  M(0, 1) = M(1, 0) = M(0, 1) - 4.0 / 3.0 * d.W_1 * a;  // -4/3 a W_1 (F⊗G + G⊗F)
  M(1, 1) += 4.0 / 9.0 * d.W_1 * a * I1;                // +4/9 a W_1 I1 G⊗G
  if (has_I2) {
    const Eigen::Matrix3d d12 = d1 * d2.transpose();
    M += d.W_12 * (d12 + d12.transpose()) + d.W_22 * d2 * d2.transpose();
    // W_2 b [4 F⊗F - 4/3 (H⊗G + G⊗H) + 16/9 I2 G⊗G] with H = dI2/dF = 2 I1 F - 2 F C = (2 I1, 0,
    // -2).
    const double w = d.W_2 * b;
    M(0, 0) += 4.0 * w;
    M(0, 1) -= 4.0 / 3.0 * w * 2.0 * I1;
    M(1, 0) -= 4.0 / 3.0 * w * 2.0 * I1;
    M(1, 2) += 4.0 / 3.0 * w * 2.0;
    M(2, 1) += 4.0 / 3.0 * w * 2.0;
    M(1, 1) += 16.0 / 9.0 * w * I2;
  }
  Eigen::Matrix<double, 9, 3> U;
  U.col(0) = Eigen::Map<const Vec9d>(kin.F.data());
  U.col(1) = Eigen::Map<const Vec9d>(kin.G.data());
  U.col(2) = Eigen::Map<const Vec9d>(FC.data());
  const Eigen::Matrix<double, 9, 3> UM = U * M;

  // Non-dyadic parts (M12), with vec index i + 3 j for (i, j) and k + 3 l for (k, l):
  //   c_I δ_ik δ_jl + c_G G_il G_kj + c_F (F_il F_kj + δ_ik C_jl + B_ik δ_jl).
  // One pass over the upper triangle, mirrored (A is symmetric): writing each entry once was faster
  // in a quick timing than separate Eigen passes (1.4x with the Ī2 terms, equal without).
  const double c_I = 2.0 * d.W_1 * a + (has_I2 ? 2.0 * d.W_2 * b * I1 : 0.0);
  const double c_G = 2.0 / 3.0 * d.W_1 * a * I1 + (has_I2 ? 4.0 / 3.0 * d.W_2 * b * I2 : 0.0);
  const double c_F = has_I2 ? -2.0 * d.W_2 * b : 0.0;
  Mat3d B;
  if (has_I2) {
    B.noalias() = kin.F * kin.F.transpose();
  } else {
    B.setZero();
  }
  const Mat3d& F = kin.F;
  const Mat3d& G = kin.G;
  const Mat3d& C = kin.C;
  for (int l = 0; l < 3; ++l) {
    for (int k = 0; k < 3; ++k) {
      const int col = k + 3 * l;
      for (int row = 0; row <= col; ++row) {
        const int i = row % 3, j = row / 3;
        double v = UM(row, 0) * U(col, 0) + UM(row, 1) * U(col, 1) + UM(row, 2) * U(col, 2) +
                   c_G * G(i, l) * G(k, j) +
                   c_F * (F(i, l) * F(k, j) + (i == k ? C(j, l) : 0.0) + (j == l ? B(i, k) : 0.0));
        if (row == col) v += c_I;
        r.A(row, col) = v;
        r.A(col, row) = v;
      }
    }
  }
  return r;
}

}  // namespace plisse
