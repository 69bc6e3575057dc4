#include "element/shell_plane_stress.hpp"

#include <array>
#include <cmath>
#include <string>

namespace plisse::shell {

namespace {

/// The directions E_a of C₂ for the components c = (C11, C22, C12) (KL11).
const std::array<Mat2d, 3>& component_directions() {
  static const std::array<Mat2d, 3> E = [] {
    std::array<Mat2d, 3> e;
    e[0] << 1, 0, 0, 0;
    e[1] << 0, 0, 0, 1;
    e[2] << 0, 1, 1, 0;
    return e;
  }();
  return E;
}

/// X̂ = X ⊕ dC33[X] in the local frame (KL10): dC33 = -C33 C₂⁻¹ : X.
Mat3d direction_of_C(const Mat2d& X, const Mat2d& C2_inverse, double C33) {
  Mat3d Xhat = Mat3d::Zero();
  Xhat.topLeftCorner<2, 2>() = X;
  Xhat(2, 2) = -C33 * C2_inverse.cwiseProduct(X).sum();
  return Xhat;
}

Vec9d vec(const Mat3d& M) { return Eigen::Map<const Vec9d>(M.data()); }

}  // namespace

Mat3d plane_stress_deformation(const Mat2d& C2, const Mat3d& frame) {
  const double det = C2.determinant();
  if (!(C2(0, 0) > 0.0) || !(det > 0.0) || !std::isfinite(det)) {
    throw InadmissibleDeformation(
        "shell: in-plane C is not positive definite (C11 = " + std::to_string(C2(0, 0)) +
        ", det = " + std::to_string(det) + ")");
  }
  // Upper Cholesky factor: U = [[u11, u12], [0, u22]], UᵀU = C₂.
  const double u11 = std::sqrt(C2(0, 0));
  const double u12 = C2(0, 1) / u11;
  const double u22 = std::sqrt(det) / u11;
  Mat3d F_local = Mat3d::Zero();
  F_local(0, 0) = u11;
  F_local(0, 1) = u12;
  F_local(1, 1) = u22;
  F_local(2, 2) = 1.0 / (u11 * u22);  // λ3 = 1/det U (KL9)
  return F_local * frame.transpose();
}

PlaneStressResponse condense_plane_stress(const Mat2d& C2, const Mat3d& frame, const Mat3d& F,
                                          const PointResponse& m) {
  const Mat2d C2_inverse = C2.inverse();
  const double C33 = 1.0 / C2.determinant();
  const Mat3d F_inverse_T = F.inverse().transpose();
  const Mat3d S = F.inverse() * m.P;  // 2nd Piola-Kirchhoff stress, global basis
  const double S33 = frame.col(2).dot(S * frame.col(2));
  const std::array<Mat2d, 3>& E = component_directions();
  std::array<Mat3d, 3> dF;  // dF_a = ½ F⁻ᵀ frame Ê_a frameᵀ: FᵀdF_a + dF_aᵀF = direction of C
  std::array<Vec9d, 3> dF_vec;
  for (int a = 0; a < 3; ++a) {
    dF[a] = 0.5 * F_inverse_T * frame * direction_of_C(E[a], C2_inverse, C33) * frame.transpose();
    dF_vec[a] = vec(dF[a]);
  }
  PlaneStressResponse r;
  r.W = m.W;
  for (int a = 0; a < 3; ++a) {
    r.dW(a) = m.P.cwiseProduct(dF[a]).sum();  // DW₂[E_a] = P : dF_a (KL10)
    const double tr_a = C2_inverse.cwiseProduct(E[a]).sum();
    for (int b = a; b < 3; ++b) {
      const double tr_b = C2_inverse.cwiseProduct(E[b]).sum();
      const double tr_ab = (C2_inverse * E[a] * C2_inverse).cwiseProduct(E[b]).sum();
      r.d2W(a, b) = dF_vec[a].dot(m.A * dF_vec[b]) -
                    S.cwiseProduct(dF[a].transpose() * dF[b]).sum() +
                    0.5 * S33 * C33 * (tr_a * tr_b + tr_ab);  // (KL11)
      r.d2W(b, a) = r.d2W(a, b);
    }
  }
  return r;
}

}  // namespace plisse::shell
