#pragma once
/// The signed gap of a node to the plane of a flat triangular facet, with its exact first and
/// second derivatives with respect to the 12 coordinates of the node and the facet's corners: the
/// geometry kernel of node-to-surface contact (docs/theory/surface-contact.md, N9-N13).
///
/// With x = (xs, xa, xb, xc) in R^12, e1 = xb - xa, e2 = xc - xa, w = xs - xa, a = e1 x e2,
/// m = |a|, n = a/m, q = a . w:
///   (N9) g = n . (xs - xa) = q/m, positive on the side n points to.
///   (N10) dg/dx = (n, -Na n, -Nb n, -Nc n), with (Na, Nb, Nc) the barycentric coordinates of the
///        projection p = xs - g n of the node on the plane (Nb, Nc solve the 2x2 normal equations
///        of e1, e2 for p - xa; Na = 1 - Nb - Nc).
///   (N11) In y = (e1, e2, w) in R^9 (y = T x, T constant), the triple product q has
///        dq/de1 = e2 x w, dq/de2 = w x e1, dq/dw = a, and the Hessian with zero diagonal blocks
///        and d2q/de1de2 = -[w]x, d2q/de1dw = [e2]x, d2q/de2dw = -[e1]x ([v]x u = v x u).
///   (N12) m has dm/de1 = e2 x n, dm/de2 = n x e1, dm/dw = 0 and the Hessian
///        (1/m) J^T (I - n n^T) J + sum_k n_k d2a_k, with J = da/d(e1, e2) = [-[e2]x, [e1]x] and
///        sum_k n_k d2a_k = [[0, -[n]x], [[n]x, 0]] in the (e1, e2) blocks.
///   (N13) g = q/m: grad g = grad q/m - q grad m/m^2,
///        H_g = H_q/m - (grad q grad m^T + grad m grad q^T)/m^2 + 2 q grad m grad m^T/m^3
///              - q H_m/m^2,
///        and in x: grad_x g = T^T grad_y g, H_x = T^T H_y T.
/// dg/dxs = n and d2g/dxs2 = 0: the gap is linear in the node's position.
#include "core/types.hpp"

namespace plisse {

/// Gap of a node to the plane of a facet and its first and second derivatives with respect to
/// the 12 coordinates (xs, xa, xb, xc), in that order.
struct NodeFacetGap {
  using Vec12d = Eigen::Matrix<double, 12, 1>;
  using Mat12d = Eigen::Matrix<double, 12, 12>;

  double g = 0.0;                    ///< n . (xs - xa) [mm] (N9)
  Vec3d n = Vec3d::Zero();           ///< unit normal (xb - xa) x (xc - xa) / |...|
  Vec3d xi = Vec3d::Zero();          ///< barycentric coordinates (Na, Nb, Nc) of xs - g n, sum 1
  Vec12d gradient = Vec12d::Zero();  ///< dg/dx = (n, -Na n, -Nb n, -Nc n) (N10)
  Mat12d hessian = Mat12d::Zero();   ///< d2g/dx2 [1/mm], symmetric (N11-N13); zero if not asked
};

/// Gap, normal, barycentric coordinates and gradient of the node xs to the plane of the facet
/// (xa, xb, xc), and the Hessian when `with_hessian`. Throws plisse::Error for a degenerate facet
/// (|(xb - xa) x (xc - xa)| <= 1e-300 or not finite).
NodeFacetGap node_facet_gap(const Vec3d& xs, const Vec3d& xa, const Vec3d& xb, const Vec3d& xc,
                            bool with_hessian);

}  // namespace plisse
