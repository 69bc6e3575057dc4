#pragma once
/// Degrees of freedom, element vectors and status of the MINI (P1+/P1) tetrahedron.
///
/// Element unknowns seen by the global solver (x_e, 16 values):
///   [u0x, u0y, u0z, u1x, ..., u3z, p0, p1, p2, p3]
/// nodal displacements u_a [mm] and nodal pressures p_a [MPa] (positive in compression).
/// The bubble displacement b [mm] (3 values) is internal to the element and condensed.
#include <Eigen/Dense>

#include "core/types.hpp"
#include "element/element_fields.hpp"

namespace plisse::mini {

inline constexpr int kNodes = 4, kDofU = 12, kDofP = 4, kDof = 16, kDofBubble = 3;

using ElemVec = Eigen::Matrix<double, kDof, 1>;
using ElemMat = Eigen::Matrix<double, kDof, kDof>;
using BubbleVec = Eigen::Matrix<double, kDofBubble, 1>;
/// Coupling block between element unknowns x_e and the bubble.
using ElemBubbleMat = Eigen::Matrix<double, kDof, kDofBubble>;
/// db/dx_e: the converged bubble's derivative with respect to the element unknowns (B6).
using BubbleSensitivity = Eigen::Matrix<double, kDofBubble, kDof>;

/// An element's bubble from its last evaluation, with its sensitivity there: the warm start of the
/// next evaluation, b(x_e) ≈ b + db/dx (x_e - x_at) (B6). The bubble is the element's state
/// (kDofBubble doubles at data(), what a checkpoint keeps); the sensitivity and x_at are a cache,
/// all zero meaning "no prediction".
struct BubbleWarmStart {
  BubbleVec b = BubbleVec::Zero();
  BubbleSensitivity db_dx = BubbleSensitivity::Zero();
  ElemVec x_at = ElemVec::Zero();

  double* data() { return b.data(); }
  const double* data() const { return b.data(); }
  BubbleVec predict(const ElemVec& x_e) const { return b + db_dx * (x_e - x_at); }
};

/// Index in x_e of displacement component i (0..2) of node a (0..3).
constexpr int dof_u(int a, int i) { return 3 * a + i; }
/// Index in x_e of the pressure of node a (0..3).
constexpr int dof_p(int a) { return kDofU + a; }

/// Outcome of one element evaluation.
struct ElementStatus {
  bool ok = true;    ///< false when J <= 0 at a quadrature point or the bubble solve failed; then
                     ///< r_e / K_e are zero and not meaningful, and the solver cuts the load step
  double min_J = 1;  ///< smallest J = det F over the quadrature points (last evaluation)
  int bubble_iterations = 0;  ///< element evaluations made by the local bubble Newton solve
};

/// Volume averages over one tetrahedron (for output).
using ElementFields = plisse::ElementFields;

}  // namespace plisse::mini
