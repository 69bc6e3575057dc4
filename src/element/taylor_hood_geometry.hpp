#pragma once
/// The 10-node isoparametric tetrahedron of the Taylor-Hood (P2/P1) element: shape functions,
/// unknown layout, quadrature and the reference geometry of one element, computed once
/// (docs/theory/taylor_hood.md, H1-H4).
///
/// Nodes: the 4 corners, then the 6 edge nodes in Gmsh's order (01, 12, 20, 30, 32, 31), as in
/// mesh/mesh.hpp. Element unknowns seen by the global solver (x_e, 34 values):
///   [u0x, u0y, u0z, ..., u9x, u9y, u9z, p0, p1, p2, p3]
/// the displacements [mm] of the 10 nodes and the pressures [MPa] of the 4 corners (P1 pressure,
/// positive in compression).
#include <Eigen/Dense>
#include <array>

#include "core/types.hpp"
#include "element/quadrature.hpp"
#include "mesh/topology.hpp"

namespace plisse::taylor_hood {

inline constexpr int kNodes = 10, kCorners = 4, kDofU = 30, kDofP = 4, kDof = 34;

using ElemVec = Eigen::Matrix<double, kDof, 1>;
using ElemMat = Eigen::Matrix<double, kDof, kDof>;
/// Shape-function gradients of the 10 nodes, one column per node.
using NodeGradients = Eigen::Matrix<double, 3, kNodes>;

/// Index in x_e of displacement component i (0..2) of node a (0..9).
constexpr int dof_u(int a, int i) { return 3 * a + i; }
/// Index in x_e of the pressure of corner a (0..3).
constexpr int dof_p(int a) { return kDofU + a; }

/// The corners (i, j) of edge node 4 + k are kTetEdges[k] (mesh/topology.hpp), Gmsh's order.

/// The quadrature rule: the symmetric 14-point rule of degree 5 with positive weights. It
/// integrates the stiffness of a straight-sided element in the linearised regime (degree 2) and
/// the pressure mass matrix (degree 2) exactly, and the pressure-displacement coupling of a
/// straight element (degree 3 at most under finite strain: L_a times det F, a cubic) too
/// (taylor_hood.md, H5).
inline constexpr const TetQuadrature<14>& kQuadrature = kTetQuadratureDegree5;
inline constexpr int kQuadPoints = TetQuadrature<14>::n_points;

/// Values N_a(L) of the 10 quadratic shape functions at barycentric coordinates L (H1):
/// corners L_a (2 L_a - 1), edge nodes 4 L_i L_j.
std::array<double, kNodes> shape_values(const std::array<double, 4>& L);
/// Their derivatives with respect to the natural coordinates ξ = (L1, L2, L3) (L0 = 1 - Σ ξ),
/// one column per node.
NodeGradients shape_derivatives(const std::array<double, 4>& L);

/// Reference geometry of one 10-node tetrahedron at the quadrature points. Plain data, owned by
/// the caller; read-only in the kernels.
struct Geometry {
  double volume = 0.0;  ///< V = Σ_q weight_q [mm^3], > 0
  double size = 0.0;    ///< h_e: longest corner-to-corner edge [mm]
  /// Jacobian inverses, transposed, per point: Grad N_a = jacobian_inverse_t[q] dN_a/dξ (H2).
  std::array<Mat3d, kQuadPoints> jacobian_inverse_t{};
  std::array<double, kQuadPoints> weight{};  ///< w_q det(dX/dξ) / 6 [mm^3]
};

/// Geometry of the tetrahedron with nodes X[0..9] [mm] (corners, then Gmsh's edge order).
/// Throws plisse::Error when det(dX/dξ) is not positive at a quadrature point or at a corner
/// (an inverted, degenerate or too strongly curved element) or a coordinate is not finite.
Geometry compute_geometry(const std::array<Vec3d, kNodes>& X);

/// The reference derivatives dN_a/dξ of the 10 nodes at every quadrature point (a table built
/// once).
const std::array<NodeGradients, kQuadPoints>& reference_derivatives();

/// Grad N of the 10 nodes at quadrature point q [1/mm] (H2).
inline NodeGradients gradients(const Geometry& g, int q) {
  return g.jacobian_inverse_t[q] * reference_derivatives()[q];
}

}  // namespace plisse::taylor_hood
