#pragma once
/// Material-independent parts of the MINI kernel: point kinematics, the quadrature sums of the
/// residual and tangent blocks in (x_e, b), the local bubble Newton step and the static
/// condensation. Equation labels refer to docs/theory/mixed_up.md.
///
/// The template kernel in element/mini.hpp only evaluates the material at the points; everything
/// here is fixed-size (no heap) and free of shared state, hence thread-safe.
#include <array>

#include "core/types.hpp"
#include "element/mini_layout.hpp"
#include "element/tet_geometry.hpp"
#include "material/point_response.hpp"

namespace plisse::mini {

/// Element unknowns rearranged once per evaluation.
struct NodalState {
  Mat3d grad_u_linear;  ///< Σ_a u_a ⊗ Grad N_a  (the P1 part of Grad u_h, constant)  [-]
  Eigen::Vector4d p;    ///< nodal pressures [MPa]
};
NodalState gather_nodal_state(const TetGeometry& g, const ElemVec& x_e);

/// Kinematics at one quadrature point (eq. U3).
struct PointKinematics {
  Mat3d F;           ///< I + Grad u_h
  Mat3d cof;         ///< cof F = J F^{-T}, columns f1×f2, f2×f0, f0×f1 of F = [f0 f1 f2]
  double J;          ///< det F
  double J_minus_1;  ///< det F - 1 from the invariants of H = Grad u_h (no cancellation near 1)
  double p;          ///< p_h [MPa]
};
PointKinematics compute_point_kinematics(const TetGeometry& g, const NodalState& s,
                                         const BubbleVec& bubble, int q);

/// The uncondensed element system in (x_e, b): residuals and the tangent blocks (eqs. R1-R3,
/// K1-K6). K_bx = K_xbᵀ (the tangent is a Hessian), so only K_xb is stored.
struct MiniLocalSystem {
  ElemVec r_x;             ///< (R1), (R3) [N], [mm^3]
  BubbleVec r_b;           ///< (R2) [N]
  ElemBubbleMat K_xb;      ///< (K2), (K5)
  Mat3d K_bb;              ///< (K3) [N/mm]
  ElemMat K_xx;            ///< (K1), (K4), (K6); only filled when asked for
  double force_scale = 0;  ///< f_e of eq. (B2) [N]
};

/// Quadrature sums of one element evaluation: add every point, then read the blocks.
class MiniIntegrals {
 public:
  /// `with_K_xx`: also sum what K_xx needs (not needed for a residual-only evaluation).
  MiniIntegrals(const TetGeometry& g, bool with_K_xx);
  /// Adds quadrature point q with kinematics k and isochoric material response m.
  void add_point(int q, const PointKinematics& k, const PointResponse& m);
  /// r_b, K_bb and force_scale: all the bubble Newton step needs.
  void bubble_block(MiniLocalSystem& sys) const;
  /// r_x and K_xb, and K_xx if constructed `with_K_xx`. `inverse_bulk_modulus` = 1/κ [1/MPa].
  void coupled_blocks(const NodalState& s, double inverse_bulk_modulus, MiniLocalSystem& sys) const;

 private:
  const TetGeometry& g_;
  bool with_K_xx_;
  Mat3d P_sum_ = Mat3d::Zero();        // Σ w (P - p cof F)
  BubbleVec r_b_ = BubbleVec::Zero();  // Σ w (P - p cof F) g
  Eigen::Matrix<double, 9, 3> AG_sum_ = Eigen::Matrix<double, 9, 3>::Zero();   // Σ w A·g
  Mat3d K_bb_ = Mat3d::Zero();                                                 // Σ w g·A·g
  Mat3d pF_cross_g_sum_ = Mat3d::Zero();                                       // Σ w p F [g]_×
  Eigen::Matrix<double, 3, 4> cof_g_N_ = Eigen::Matrix<double, 3, 4>::Zero();  // Σ w N_a cof g
  Eigen::Vector4d J_minus_1_N_ = Eigen::Vector4d::Zero();                      // Σ w N_a (J - 1)
  double force_scale_ = 0;      // Σ w |P - p cof F| |g|
  Mat9d A_sum_;                 // Σ w A          (K_xx only)
  Mat3d pF_sum_;                // Σ w p F        (K_xx only)
  std::array<Mat3d, 4> cof_N_;  // Σ w N_a cof F  (K_xx only)
};

/// One Newton step of the local bubble problem r_b(x, b) = 0 at fixed x (eqs. B1-B2).
struct BubbleStep {
  bool ok = false;                      ///< false: K_bb singular or not finite
  bool converged = false;               ///< |r_b| <= kBubbleTolerance f_e before the step
  BubbleVec delta = BubbleVec::Zero();  ///< Δb = -K_bb⁻¹ r_b [mm]
  Mat3d K_bb_inverse = Mat3d::Zero();
};

/// Relative tolerance of the bubble solve, |r_b| <= ε (h_e |K_bb| + Σ w |P - p cof F| |g|) (B2).
inline constexpr double kBubbleTolerance = 1e-10;
/// Most element evaluations of one bubble solve before it is reported as failed.
inline constexpr int kMaxBubbleIterations = 30;
/// Bubble iterations taken as Newton gives them; after these a step that raises |r_b| is halved.
inline constexpr int kUndampedBubbleIterations = 5;
/// Most successive halvings of a bubble Newton step that leads to det F <= 0.
inline constexpr int kMaxBubbleHalvings = 4;

BubbleStep compute_bubble_step(const MiniLocalSystem& sys, double element_size);

/// Static condensation (B3)-(B4):  r_e = r_x + K_xb Δb,  K_e = K_xx - K_xb K_bb⁻¹ K_xbᵀ.
/// K_e == nullptr: residual only.
void condense_bubble(const MiniLocalSystem& sys, const BubbleStep& step, ElemVec& r_e,
                     ElemMat* K_e);

}  // namespace plisse::mini
