#include "element/mini_integrals.hpp"

#include <cmath>

#include "element/kinematics.hpp"

namespace plisse::mini {
namespace {

/// [v]_× w = v × w.
Mat3d cross_matrix(const Vec3d& v) { return -epsilon_dot(v); }

/// T_ik = Σ_J G_J M(i + 3J, k): contraction of a 9x3 block (vec-F rows) with a gradient.
Mat3d contract_rows(const Eigen::Matrix<double, 9, 3>& M, const Vec3d& G) {
  return G(0) * M.topRows<3>() + G(1) * M.middleRows<3>(3) + G(2) * M.bottomRows<3>();
}

/// (A·G)(iJ, k) = Σ_L A(iJ, k + 3L) G_L: contraction of a 9x9 tangent with a gradient on the right.
Eigen::Matrix<double, 9, 3> contract_columns(const Mat9d& A, const Vec3d& G) {
  return G(0) * A.leftCols<3>() + G(1) * A.middleCols<3>(3) + G(2) * A.rightCols<3>();
}

}  // namespace

NodalState gather_nodal_state(const TetGeometry& g, const ElemVec& x_e) {
  NodalState s;
  s.grad_u_linear.setZero();
  for (int a = 0; a < kNodes; ++a)
    s.grad_u_linear.noalias() += x_e.segment<3>(dof_u(a, 0)) * g.grad_N[a].transpose();
  s.p = x_e.segment<kDofP>(kDofU);
  return s;
}

PointKinematics compute_point_kinematics(const TetGeometry& g, const NodalState& s,
                                         const BubbleVec& bubble, int q) {
  PointKinematics k;
  const Mat3d H = s.grad_u_linear + bubble * g.grad_bubble[q].transpose();  // (U3)
  k.F = Mat3d::Identity() + H;
  k.cof = cofactor(k.F);
  k.J_minus_1 = det_minus_one(H);  // (U4)
  k.J = 1.0 + k.J_minus_1;
  const std::array<double, 4>& N = kQuadrature.points[q];
  k.p = N[0] * s.p(0) + N[1] * s.p(1) + N[2] * s.p(2) + N[3] * s.p(3);
  return k;
}

MiniIntegrals::MiniIntegrals(const TetGeometry& g, bool with_K_xx) : g_(g), with_K_xx_(with_K_xx) {
  if (with_K_xx_) {
    A_sum_.setZero();
    pF_sum_.setZero();
    for (Mat3d& c : cof_N_) c.setZero();
  }
}

void MiniIntegrals::add_point(int q, const PointKinematics& k, const PointResponse& m) {
  const double w = g_.weight[q];
  const Vec3d& gb = g_.grad_bubble[q];
  const std::array<double, 4>& N = kQuadrature.points[q];
  const Mat3d P_total = m.P - k.p * k.cof;  // P - p cof F = ∂/∂F [W - p (J - 1)]
  P_sum_ += w * P_total;                    // (R1)
  r_b_.noalias() += w * (P_total * gb);     // (R2)
  force_scale_ += w * P_total.norm() * gb.norm();
  const Eigen::Matrix<double, 9, 3> AG = contract_columns(m.A, gb);
  AG_sum_ += w * AG;                                                  // (K2), material part
  K_bb_ += w * contract_rows(AG, gb);                                 // (K3)
  pF_cross_g_sum_.noalias() += (w * k.p) * (k.F * cross_matrix(gb));  // (K2), pressure part
  const Vec3d cof_g = k.cof * gb;
  for (int a = 0; a < kNodes; ++a) {
    cof_g_N_.col(a) += (w * N[a]) * cof_g;        // (K5)
    J_minus_1_N_(a) += (w * N[a]) * k.J_minus_1;  // (R3)
  }
  if (with_K_xx_) {
    A_sum_ += w * m.A;                                                 // (K1), material part
    pF_sum_ += (w * k.p) * k.F;                                        // (K1), pressure part
    for (int a = 0; a < kNodes; ++a) cof_N_[a] += (w * N[a]) * k.cof;  // (K4)
  }
}

void MiniIntegrals::bubble_block(MiniLocalSystem& sys) const {
  sys.r_b = r_b_;
  sys.K_bb = K_bb_;
  sys.force_scale = force_scale_;
}

void MiniIntegrals::coupled_blocks(const NodalState& s, double inverse_bulk_modulus,
                                   MiniLocalSystem& sys) const {
  const double V = g_.volume;
  const double p_sum = s.p.sum();
  for (int a = 0; a < kNodes; ++a) {
    const Vec3d& Ga = g_.grad_N[a];
    sys.r_x.segment<3>(dof_u(a, 0)) = P_sum_ * Ga;  // (R1)
    // (R3); the 1/κ part uses the exact P1 mass matrix V (1 + δ_ab) / 20 (the rule has degree >= 2)
    sys.r_x(dof_p(a)) = -(J_minus_1_N_(a) + inverse_bulk_modulus * V / 20.0 * (s.p(a) + p_sum));
    // (K2): G_a·A·g - E(Σ w p F (G_a × g)) = G_a·A·g + E(Σ w p F [g]_× G_a)
    sys.K_xb.block<3, 3>(dof_u(a, 0), 0) =
        contract_rows(AG_sum_, Ga) + epsilon_dot(pF_cross_g_sum_ * Ga);
    sys.K_xb.row(dof_p(a)) = -cof_g_N_.col(a).transpose();  // (K5)
  }
  if (!with_K_xx_) return;
  for (int b = 0; b < kNodes; ++b) {
    const Vec3d& Gb = g_.grad_N[b];
    const Eigen::Matrix<double, 9, 3> AG = contract_columns(A_sum_, Gb);
    for (int a = 0; a < kNodes; ++a) {
      const Vec3d& Ga = g_.grad_N[a];
      sys.K_xx.block<3, 3>(dof_u(a, 0), dof_u(b, 0)) =
          contract_rows(AG, Ga) - epsilon_dot(pF_sum_ * Ga.cross(Gb));  // (K1)
      const Vec3d coupling = -(cof_N_[b] * Ga);                         // (K4)
      sys.K_xx.block<3, 1>(dof_u(a, 0), dof_p(b)) = coupling;
      sys.K_xx.block<1, 3>(dof_p(b), dof_u(a, 0)) = coupling.transpose();
      sys.K_xx(dof_p(a), dof_p(b)) =
          -inverse_bulk_modulus * V / 20.0 * (a == b ? 2.0 : 1.0);  // (K6)
    }
  }
}

BubbleStep compute_bubble_step(const MiniLocalSystem& sys, double element_size) {
  BubbleStep step;
  const double K_norm = sys.K_bb.norm();
  const double det = sys.K_bb.determinant();
  // K_bb is the integrated acoustic tensor of W (K3): positive definite for a rank-one convex
  // material. Reject it when singular to working precision.
  if (!std::isfinite(det) || !(std::abs(det) > 1e-13 * K_norm * K_norm * K_norm) ||
      !sys.r_b.allFinite())
    return step;
  step.ok = true;
  step.K_bb_inverse = sys.K_bb.inverse();
  step.delta = -(step.K_bb_inverse * sys.r_b);  // (B1)
  step.converged =
      sys.r_b.norm() <= kBubbleTolerance * (element_size * K_norm + sys.force_scale);  // (B2)
  return step;
}

void condense_bubble(const MiniLocalSystem& sys, const BubbleStep& step, ElemVec& r_e,
                     ElemMat* K_e) {
  r_e = sys.r_x;
  r_e.noalias() += sys.K_xb * step.delta;  // (B3)
  if (K_e == nullptr) return;
  const ElemBubbleMat K_xb_Kinv = sys.K_xb * step.K_bb_inverse;
  *K_e = sys.K_xx;
  // Coefficient-based product: Eigen's blocked GEMM path is slower at 16x3x16.
  K_e->noalias() -= K_xb_Kinv.lazyProduct(sys.K_xb.transpose());  // (B4)
}

}  // namespace plisse::mini
