#include "element/shell_plane_stress.hpp"

#include <algorithm>
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

/// Throws InadmissibleDeformation unless C₂ is positive definite; returns det C₂.
double positive_definite_determinant(const Mat2d& C2) {
  const double det = C2.determinant();
  if (!(C2(0, 0) > 0.0) || !(det > 0.0) || !std::isfinite(det)) {
    throw InadmissibleDeformation(
        "shell: in-plane C is not positive definite (C11 = " + std::to_string(C2(0, 0)) +
        ", det = " + std::to_string(det) + ")");
  }
  return det;
}

}  // namespace

Mat3d plane_stress_deformation(const Mat2d& C2, const Mat3d& frame, double C33) {
  const double det = positive_definite_determinant(C2);
  if (!(C33 > 0.0) || !std::isfinite(C33)) {
    throw InadmissibleDeformation("shell: thickness stretch squared C33 = " + std::to_string(C33) +
                                  " is not positive");
  }
  // Upper Cholesky factor: U = [[u11, u12], [0, u22]], UᵀU = C₂.
  const double u11 = std::sqrt(C2(0, 0));
  Mat3d F_local = Mat3d::Zero();
  F_local(0, 0) = u11;
  F_local(0, 1) = C2(0, 1) / u11;
  F_local(1, 1) = std::sqrt(det) / u11;
  F_local(2, 2) = std::sqrt(C33);
  return F_local * frame.transpose();
}

Mat3d plane_stress_deformation(const Mat2d& C2, const Mat3d& frame) {
  const double det = C2.determinant();
  // λ3 = 1/det U (KL9); a C₂ that is not positive definite is refused by the general form.
  return plane_stress_deformation(C2, frame, det > 0.0 ? 1.0 / det : 0.0);
}

ThickPointResponse thick_point_response(const Mat2d& C2, const Mat3d& frame, double C33,
                                        const Mat3d& F, const PointResponse& m,
                                        double bulk_modulus) {
  const Mat2d C2_inverse = C2.inverse();
  const Mat3d F_inverse_T = F.inverse().transpose();
  const Mat3d S = F.inverse() * m.P;  // 2nd Piola-Kirchhoff stress of the isochoric model
  // The four directions of C in the local frame: E11, E22, E12 + E21 (one unknown C12), e3 ⊗ e3.
  const std::array<Mat2d, 3>& E = component_directions();
  std::array<Mat3d, 4> direction;
  for (int a = 0; a < 3; ++a) direction[a] = direction_of_C(E[a], C2_inverse, 0.0);
  direction[3] = Mat3d::Zero();
  direction[3](2, 2) = 1.0;
  // C⁻¹ : Ê_a, and (C⁻¹ Ê_a C⁻¹) : Ê_b; C⁻¹ = C₂⁻¹ ⊕ 1/C33 is block diagonal.
  std::array<double, 4> trace;
  Eigen::Matrix4d trace_product = Eigen::Matrix4d::Zero();
  for (int a = 0; a < 3; ++a) {
    trace[a] = C2_inverse.cwiseProduct(E[a]).sum();
    for (int b = 0; b < 3; ++b)
      trace_product(a, b) = (C2_inverse * E[a] * C2_inverse).cwiseProduct(E[b]).sum();
  }
  trace[3] = 1.0 / C33;
  trace_product(3, 3) = 1.0 / (C33 * C33);
  std::array<Mat3d, 4> dF;  // dF_a = ½ F⁻ᵀ frame Ê_a frameᵀ: FᵀdF_a + dF_aᵀF = frame Ê_a frameᵀ
  std::array<Vec9d, 4> dF_vec;
  for (int a = 0; a < 4; ++a) {
    dF[a] = 0.5 * F_inverse_T * frame * direction[a] * frame.transpose();
    dF_vec[a] = vec(dF[a]);
  }
  // U(J) = κ/2 (J - 1)² with J = √det C: ∂J = ½ J C⁻¹ : Ê,
  // ∂²J = ¼ J (C⁻¹ : Ê_a)(C⁻¹ : Ê_b) - ½ J (C⁻¹ Ê_a C⁻¹) : Ê_b (KL12).
  ThickPointResponse w;
  w.J = std::sqrt(C2.determinant() * C33);
  const double J_minus_1 = w.J - 1.0;
  w.W = m.W + 0.5 * bulk_modulus * J_minus_1 * J_minus_1;
  for (int a = 0; a < 4; ++a) {
    const double dJ_a = 0.5 * w.J * trace[a];
    w.dW(a) = m.P.cwiseProduct(dF[a]).sum() + bulk_modulus * J_minus_1 * dJ_a;
    for (int b = a; b < 4; ++b) {
      const double dJ_b = 0.5 * w.J * trace[b];
      const double d2J = 0.25 * w.J * trace[a] * trace[b] - 0.5 * w.J * trace_product(a, b);
      w.d2W(a, b) = dF_vec[a].dot(m.A * dF_vec[b]) -
                    S.cwiseProduct(dF[a].transpose() * dF[b]).sum() +
                    bulk_modulus * (dJ_a * dJ_b + J_minus_1 * d2J);
      w.d2W(b, a) = w.d2W(a, b);
    }
  }
  return w;
}

PlaneStressResponse condense_thickness(const ThickPointResponse& w, double C33, double step) {
  // At C33 + step the normal stress is zero to second order in the step: the energy, gradient
  // and Hessian there, to that order, are those of the Schur complement of ∂²Ŵ/∂C33² (KL12).
  const double h33 = w.d2W(3, 3);
  PlaneStressResponse r;
  r.W = w.W - 0.5 * w.dW(3) * w.dW(3) / h33;
  r.dW = w.dW.head<3>() + w.d2W.block<3, 1>(0, 3) * step;
  r.d2W = w.d2W.topLeftCorner<3, 3>() - w.d2W.block<3, 1>(0, 3) * w.d2W.block<1, 3>(3, 0) / h33;
  r.C33 = C33 + step;
  r.J = w.J * std::sqrt(r.C33 / C33);
  return r;
}

double next_thickness_iterate(double C33, double step) {
  return std::clamp(C33 + step, 0.25 * C33, 4.0 * C33);
}

PlaneStressResponse condense_plane_stress(const Mat2d& C2, const Mat3d& frame, const Mat3d& F,
                                          const PointResponse& m, bool with_hessian) {
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
  r.C33 = C33;
  for (int a = 0; a < 3; ++a) {
    r.dW(a) = m.P.cwiseProduct(dF[a]).sum();  // DW₂[E_a] = P : dF_a (KL10)
    if (!with_hessian) continue;
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

PlaneStressInvariants plane_stress_invariants(const Mat2d& C2) {
  const double det = positive_definite_determinant(C2);
  const double trace = C2.trace();
  return {det, trace, trace + 1.0 / det, det + trace / det};
}

PlaneStressResponse condense_invariants(const Mat2d& C2, const PlaneStressInvariants& invariants,
                                        const InvariantDerivatives& d, bool with_hessian) {
  const double trace = invariants.trace;
  const double inv = 1.0 / invariants.det;
  // Derivatives in c = (C11, C22, C12), C12 one unknown for both off-diagonal entries (KL11a).
  const Vec3d dtrace(1.0, 1.0, 0.0);
  const Vec3d ddet(C2(1, 1), C2(0, 0), -2.0 * C2(0, 1));
  const Vec3d dI1 = dtrace - inv * inv * ddet;
  const Vec3d dI2 = ddet + inv * dtrace - trace * inv * inv * ddet;
  PlaneStressResponse r;
  r.W = d.W;
  r.C33 = inv;
  r.dW = d.W_1 * dI1 + d.W_2 * dI2;
  if (!with_hessian) return r;
  Mat3d d2det = Mat3d::Zero();
  d2det(0, 1) = d2det(1, 0) = 1.0;
  d2det(2, 2) = -2.0;
  const Mat3d ddet_ddet = ddet * ddet.transpose();
  const Mat3d d2I1 = 2.0 * inv * inv * inv * ddet_ddet - inv * inv * d2det;
  const Mat3d d2I2 = d2det - inv * inv * (dtrace * ddet.transpose() + ddet * dtrace.transpose()) +
                     2.0 * trace * inv * inv * inv * ddet_ddet - trace * inv * inv * d2det;
  r.d2W = d.W_1 * d2I1 + d.W_2 * d2I2 + d.W_11 * dI1 * dI1.transpose() +
          d.W_12 * (dI1 * dI2.transpose() + dI2 * dI1.transpose()) + d.W_22 * dI2 * dI2.transpose();
  return r;
}

}  // namespace plisse::shell
