#pragma once
/// The Taylor-Hood (P2/P1) mixed displacement-pressure tetrahedron, total Lagrangian
/// (docs/theory/taylor_hood.md): 10-node isoparametric displacements, continuous linear pressure
/// on the corners, the same mixed functional as the MINI element without a bubble,
///
///   Π_e(u, p) = ∫_Ωe [ W(F) - p_h (J - 1) - p_h² / (2κ) ] dV                           (H6)
///
/// W the isochoric energy of the material, p positive in compression, σ = σ_iso - p I, 1/κ = 0
/// exact incompressibility. Residual (H7) and consistent tangent (H8) are the first and second
/// derivatives of Π_e. The kernels are templates on the material (any type with
/// `PointResponse evaluate(const Mat3d& F) const`); no heap allocation, inputs const, outputs
/// owned by the caller: thread-safe.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "element/element_fields.hpp"
#include "element/kinematics.hpp"
#include "element/taylor_hood_geometry.hpp"
#include "material/energy_density.hpp"
#include "material/inadmissible_deformation.hpp"
#include "material/point_response.hpp"

namespace plisse::taylor_hood {

/// Outcome of one element evaluation.
struct ElementStatus {
  bool ok = true;    ///< false when det F <= 0 at a quadrature point or the material rejects F;
                     ///< r_e and K_e are then zero, and the solver cuts the load step
  double min_J = 1;  ///< smallest det F over the quadrature points
};

/// Kinematics at one quadrature point.
struct PointKinematics {
  NodeGradients grad_N;  ///< Grad N_a [1/mm]
  Mat3d F;               ///< I + Σ_a u_a ⊗ Grad N_a
  Mat3d cof;             ///< cof F = J F⁻ᵀ
  double J_minus_1;      ///< det F - 1 without cancellation (as in the MINI kernel)
  double J;              ///< det F
  double p;              ///< p_h = Σ_a L_a p_a [MPa]
};

/// Displacements as a 3 x 10 matrix (one column per node) and the corner pressures of x_e.
inline Eigen::Matrix<double, 3, kNodes> nodal_displacements(const ElemVec& x_e) {
  return Eigen::Map<const Eigen::Matrix<double, 3, kNodes>>(x_e.data());
}

/// Kinematics at quadrature point q for displacements `u` (3 x 10) and corner pressures `p`.
inline PointKinematics point_kinematics(const Geometry& g,
                                        const Eigen::Matrix<double, 3, kNodes>& u,
                                        const Eigen::Vector4d& p, int q) {
  PointKinematics k;
  k.grad_N = gradients(g, q);
  const Mat3d H = u * k.grad_N.transpose();
  k.F = Mat3d::Identity() + H;
  k.cof = cofactor(k.F);
  k.J_minus_1 = det_minus_one(H);
  k.J = 1.0 + k.J_minus_1;
  const std::array<double, 4>& L = kQuadrature.points[q];
  k.p = L[0] * p(0) + L[1] * p(1) + L[2] * p(2) + L[3] * p(3);
  return k;
}

/// Residual r_e (H7) and, when K_e is not null, the consistent tangent K_e = dr_e/dx_e (H8) of one
/// element at the element unknowns x_e.
///   inverse_bulk_modulus: 1/κ [1/MPa], 0 for exact incompressibility.
///   r_e [N for u rows, mm³ for p rows], K_e: outputs, overwritten.
/// status.ok is false when det F <= 0 at a point or the material rejects F; r_e and K_e are then
/// zero.
template <class Material>
ElementStatus assemble(const Geometry& g, const ElemVec& x_e, const Material& mat,
                       double inverse_bulk_modulus, ElemVec& r_e, ElemMat* K_e) {
  const Eigen::Matrix<double, 3, kNodes> u = nodal_displacements(x_e);
  const Eigen::Vector4d p = x_e.segment<kDofP>(kDofU);
  ElementStatus status;
  status.min_J = std::numeric_limits<double>::infinity();
  r_e.setZero();
  if (K_e != nullptr) K_e->setZero();
  Eigen::Matrix<double, 3, kNodes> r_u = Eigen::Matrix<double, 3, kNodes>::Zero();
  for (int q = 0; q < kQuadPoints; ++q) {
    const PointKinematics k = point_kinematics(g, u, p, q);
    status.min_J = std::min(status.min_J, k.J);
    PointResponse m;
    bool admissible = k.J > 0.0 && std::isfinite(k.J);
    if (admissible) {
      try {
        m = evaluate_at_point(mat, q, k.F);
      } catch (const InadmissibleDeformation&) {
        admissible = false;
      }
    }
    if (!admissible) {
      status.ok = false;
      r_e.setZero();
      if (K_e != nullptr) K_e->setZero();
      return status;
    }
    const double w = g.weight[q];
    const std::array<double, 4>& L = kQuadrature.points[q];
    const Mat3d P_total = m.P - k.p * k.cof;  // ∂/∂F [W - p (J - 1)]
    r_u.noalias() += (w * P_total) * k.grad_N;
    const double pressure_equation = k.J_minus_1 + inverse_bulk_modulus * k.p;
    for (int a = 0; a < kCorners; ++a) r_e(dof_p(a)) -= w * L[a] * pressure_equation;
    if (K_e == nullptr) continue;
    ElemMat& K = *K_e;
    const Mat3d wpF = (w * k.p) * k.F;
    const Mat9d wA = w * m.A;
    for (int b = 0; b < kNodes; ++b) {
      const Vec3d Gb = k.grad_N.col(b);
      // (A·G_b)(iJ, k) = Σ_L A(iJ, k + 3L) G_b,L
      const Eigen::Matrix<double, 9, 3> AG =
          Gb(0) * wA.leftCols<3>() + Gb(1) * wA.middleCols<3>(3) + Gb(2) * wA.rightCols<3>();
      for (int a = 0; a <= b; ++a) {
        const Vec3d Ga = k.grad_N.col(a);
        K.block<3, 3>(dof_u(a, 0), dof_u(b, 0)) +=
            Ga(0) * AG.topRows<3>() + Ga(1) * AG.middleRows<3>(3) + Ga(2) * AG.bottomRows<3>() -
            epsilon_dot(wpF * Ga.cross(Gb));
      }
      const Vec3d cof_G = -w * (k.cof * Gb);
      for (int c = 0; c < kCorners; ++c) K.block<3, 1>(dof_u(b, 0), dof_p(c)) += L[c] * cof_G;
    }
    for (int a = 0; a < kCorners; ++a)
      for (int c = 0; c <= a; ++c) K(dof_p(c), dof_p(a)) -= w * inverse_bulk_modulus * L[a] * L[c];
  }
  r_e.head<kDofU>() = Eigen::Map<const Eigen::Matrix<double, kDofU, 1>>(r_u.data());
  if (K_e != nullptr) {
    // Only the upper triangle was summed: the tangent is a Hessian, symmetric.
    ElemMat& K = *K_e;
    for (int j = 0; j < kDof; ++j)
      for (int i = j + 1; i < kDof; ++i) K(i, j) = K(j, i);
  }
  return status;
}

/// Volume averages of Cauchy stress, J, von Mises stress and pressure over the element.
///   σ = J⁻¹ P Fᵀ - p I   (mixed_up.md, Y1, as for the MINI element)
/// Precondition: det F > 0 at every quadrature point (checked, throws plisse::Error).
template <class Material>
ElementFields compute_element_fields(const Geometry& g, const ElemVec& x_e, const Material& mat) {
  const Eigen::Matrix<double, 3, kNodes> u = nodal_displacements(x_e);
  const Eigen::Vector4d p = x_e.segment<kDofP>(kDofU);
  ElementFields fields;
  fields.cauchy.setZero();
  fields.J = 0.0;
  fields.pressure = 0.0;
  for (int q = 0; q < kQuadPoints; ++q) {
    const PointKinematics k = point_kinematics(g, u, p, q);
    PLISSE_CHECK(k.J > 0.0, "element fields: det F = " << k.J << " <= 0 at quadrature point " << q);
    const double w = g.weight[q] / g.volume;
    fields.cauchy +=
        w * (evaluate_at_point(mat, q, k.F).P * k.F.transpose() / k.J - k.p * Mat3d::Identity());
    fields.J += w * k.J;
    fields.pressure += w * k.p;
  }
  fields.von_mises = von_mises_stress(fields.cauchy);
  return fields;
}

/// Stored energy ∫ W dV + 1/(2κ) ∫ p_h² dV of the element [mJ] (the MINI element's SE1), for any
/// model of the registry (W from compute_energy_density). Throws plisse::Error when det F <= 0 at a
/// point.
template <class Material>
double compute_strain_energy(const Geometry& g, const ElemVec& x_e, const Material& mat,
                             double inverse_bulk_modulus) {
  const Eigen::Matrix<double, 3, kNodes> u = nodal_displacements(x_e);
  const Eigen::Vector4d p = x_e.segment<kDofP>(kDofU);
  double energy = 0.0;
  for (int q = 0; q < kQuadPoints; ++q) {
    const PointKinematics k = point_kinematics(g, u, p, q);
    PLISSE_CHECK(k.J > 0.0, "strain energy: det F = " << k.J << " <= 0 at quadrature point " << q);
    energy +=
        g.weight[q] * (compute_energy_density(mat, k.F) + 0.5 * inverse_bulk_modulus * k.p * k.p);
  }
  return energy;
}

/// The mixed functional Π_e (H6) at x_e [mJ]; its gradient is the residual (H7). For tests.
/// NaN when det F <= 0 at a point.
template <class Material>
double compute_element_energy(const Geometry& g, const ElemVec& x_e, const Material& mat,
                              double inverse_bulk_modulus) {
  const Eigen::Matrix<double, 3, kNodes> u = nodal_displacements(x_e);
  const Eigen::Vector4d p = x_e.segment<kDofP>(kDofU);
  double energy = 0.0;
  for (int q = 0; q < kQuadPoints; ++q) {
    const PointKinematics k = point_kinematics(g, u, p, q);
    if (!(k.J > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    energy += g.weight[q] * (evaluate_at_point(mat, q, k.F).W - k.p * k.J_minus_1 -
                             0.5 * inverse_bulk_modulus * k.p * k.p);
  }
  return energy;
}

/// ∫ F dV over the element at x_e [mm^3] (its reference volume is g.volume).
inline Mat3d deformation_integral(const Geometry& g, const ElemVec& x_e) {
  const Eigen::Matrix<double, 3, kNodes> u = nodal_displacements(x_e);
  Mat3d sum = Mat3d::Zero();
  for (int q = 0; q < kQuadPoints; ++q)
    sum += g.weight[q] * (Mat3d::Identity() + u * gradients(g, q).transpose());
  return sum;
}

}  // namespace plisse::taylor_hood
