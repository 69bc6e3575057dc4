#pragma once
/// Reference-configuration geometry of one MINI tetrahedron, computed once per element
/// (the analogue of libCEED's q_data): shape-function gradients, bubble gradients and weights
/// at the quadrature points.
#include <array>

#include "core/types.hpp"
#include "element/quadrature.hpp"

namespace plisse::mini {

/// The quadrature rule of the MINI kernel: the symmetric 4-point rule of degree 2 (positive
/// weights). Why this is enough (docs/theory/mixed_up.md, Q1-Q5): any fully symmetric rule gives
/// ∫ Grad N_b dV = 0 exactly (homogeneous states keep b = 0, the patch test is exact) and a
/// pressure-bubble coupling Σ_q w_q N_a Grad N_b = -β_Q V Grad N_a with β_Q ≠ 0, so the element
/// stays inf-sup stable; the P1 blocks are exact in the linearised regime. A rule exact for the
/// coupling (degree 4) costs 14 points instead of 4.
inline constexpr const TetQuadrature<4>& kQuadrature = kTetQuadratureDegree2;
inline constexpr int kQuadPoints = TetQuadrature<4>::n_points;

/// Geometry of one tetrahedron in the reference configuration. Plain data, owned by the caller
/// (one per element, computed by compute_tet_geometry); read-only in the kernels.
struct TetGeometry {
  double volume = 0.0;            ///< V [mm^3], > 0
  double size = 0.0;              ///< h_e: longest edge [mm]; length scale of tolerances and tests
  std::array<Vec3d, 4> grad_N{};  ///< Grad N_a = Grad L_a [1/mm], constant; Σ_a Grad N_a = 0
  std::array<Vec3d, kQuadPoints> grad_bubble{};  ///< Grad N_b at the quadrature points [1/mm]
  std::array<double, kQuadPoints> weight{};      ///< w_q V [mm^3]; Σ_q = V
};

/// Geometry of the tetrahedron with corners X[0..3] [mm] (reference configuration).
/// Grad L_a are the rows of the inverse of the Jacobian [X1-X0, X2-X0, X3-X0] (a = 1..3) and
/// Grad L_0 = -(Grad L_1 + Grad L_2 + Grad L_3).
/// Throws plisse::Error if the tetrahedron is inverted or degenerate (6 V <= 1e-12 h_e³, i.e.
/// volume <= 0 to working precision) or its coordinates are not finite.
TetGeometry compute_tet_geometry(const std::array<Vec3d, 4>& X);

}  // namespace plisse::mini
