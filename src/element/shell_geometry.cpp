#include "element/shell_geometry.hpp"

#include <cmath>

#include "core/error.hpp"

namespace plisse::shell {

namespace {

/// Below this ratio of the smallest to the largest singular value of the fit (KL3a) the six nodes
/// are taken to lie on a conic and the isoparametric interpolation (KL3) is used instead.
constexpr double kMinFitConditioning = 1e-6;

/// Derivatives (∂/∂ξ, ∂/∂η) of the six patch functions of (KL2) at (ξ, η), one row per node.
SideCoefficients natural_derivatives(double xi, double eta) {
  const double s = xi + eta;
  SideCoefficients d;
  d.row(0) << -(1.0 - eta), -(1.0 - xi);
  d.row(1) << 1.0 - eta, 1.0 - xi - 2.0 * eta;
  d.row(2) << 1.0 - 2.0 * xi - eta, 1.0 - xi;
  d.row(3) << s - 0.5, s - 0.5;
  d.row(4) << xi - 0.5, 0.0;
  d.row(5) << 0.0, eta - 0.5;
  return d;
}

/// The midpoint of side i in the natural coordinates of the triangle (KL2).
Vec2d side_midpoint(int i) {
  static const std::array<Vec2d, 3> m = {Vec2d(0.5, 0.5), Vec2d(0.0, 0.5), Vec2d(0.5, 0.0)};
  return m[i];
}

/// The reference frame of the triangle (KL3) and its area; throws for a degenerate triangle.
Mat3d triangle_frame(const PatchPositions& X, double& area) {
  const Vec3d g = (X[1] - X[0]).cross(X[2] - X[0]);
  const double edge = (X[1] - X[0]).norm();
  area = 0.5 * g.norm();
  PLISSE_CHECK(std::isfinite(area) && area > 1e-12 * edge * edge && edge > 0.0,
               "shell patch: degenerate triangle (area " << area << " mm²)");
  Mat3d frame;
  frame.col(0) = (X[1] - X[0]) / edge;
  frame.col(2) = g.normalized();
  frame.col(1) = frame.col(2).cross(frame.col(0));
  return frame;
}

/// 2-D coordinates of the six nodes in the triangle's plane; a missing neighbour is the mirror
/// image of the opposite node through its side's midpoint (KL8).
std::array<Vec2d, kPatchNodes> plane_coordinates(const PatchPositions& X, const Mat3d& frame,
                                                 const NeighbourFlags& has_neighbour) {
  std::array<Vec2d, kPatchNodes> p;
  for (int n = 0; n < kPatchNodes; ++n) {
    p[n] = frame.leftCols<2>().transpose() * (X[n] - X[0]);
  }
  for (int i = 0; i < 3; ++i) {
    if (!has_neighbour[i]) p[3 + i] = p[(i + 1) % 3] + p[(i + 2) % 3] - p[i];
  }
  return p;
}

/// The gradient on side i of the isoparametric quadratic patch (KL2): c^i = ∇_ξN (m_i) 𝐉_i⁻¹.
/// Throws for a singular or folded map.
SideCoefficients isoparametric_side_coefficients(const std::array<Vec2d, kPatchNodes>& p, int i) {
  const Vec2d m = side_midpoint(i);
  const SideCoefficients dN = natural_derivatives(m.x(), m.y());
  Mat2d J = Mat2d::Zero();  // J(a, b) = ∂X̃_a/∂ξ_b
  for (int n = 0; n < kPatchNodes; ++n) J += p[n] * dN.row(n);
  const double det = J.determinant();
  PLISSE_CHECK(std::isfinite(det) && det > 1e-8 * J.squaredNorm(),
               "shell patch: the quadratic map of side " << i << " is singular or folded (det "
                                                         << det << ")");
  return dN * J.inverse();  // row n: (J⁻ᵀ ∇_ξ N_n)ᵀ
}

/// The gradients on the three sides of the quadratic polynomial in the plane coordinates that
/// takes the six nodal values (KL3a): exact for every quadratic field on any patch. False when
/// the six points lie (nearly) on a conic, where that polynomial is not unique.
bool fitted_side_coefficients(const std::array<Vec2d, kPatchNodes>& p,
                              std::array<SideCoefficients, 3>& c) {
  const Vec2d centre = (p[0] + p[1] + p[2]) / 3.0;
  const double scale = (p[1] - p[0]).norm();
  auto scaled = [&](const Vec2d& q) { return Vec2d((q - centre) / scale); };
  Eigen::Matrix<double, kPatchNodes, kPatchNodes> V;  // row n: (1, x, y, x², xy, y²) at node n
  for (int n = 0; n < kPatchNodes; ++n) {
    const Vec2d q = scaled(p[n]);
    V.row(n) << 1.0, q.x(), q.y(), q.x() * q.x(), q.x() * q.y(), q.y() * q.y();
  }
  // The ratio of the extreme singular values, not an LU estimate: the estimate can miss an
  // exactly singular V.
  const Eigen::Vector<double, kPatchNodes> sv =
      Eigen::JacobiSVD<Eigen::Matrix<double, kPatchNodes, kPatchNodes>>(V).singularValues();
  if (!(sv(kPatchNodes - 1) > kMinFitConditioning * sv(0))) return false;
  const Eigen::Matrix<double, kPatchNodes, kPatchNodes> V_inverse_T =
      V.partialPivLu().inverse().transpose();
  for (int i = 0; i < 3; ++i) {
    const Vec2d m = scaled(0.5 * (p[(i + 1) % 3] + p[(i + 2) % 3]));
    SideCoefficients dP;  // ∂(1, x, y, x², xy, y²)/∂X_α at the side's midpoint
    dP << 0, 0, 1, 0, 0, 1, 2 * m.x(), 0, m.y(), m.x(), 0, 2 * m.y();
    c[i] = V_inverse_T * dP / scale;
  }
  return true;
}

/// A missing neighbour's coefficients moved onto the nodes its mirror image is made of (KL8).
void fold_mirror_node(SideCoefficients& c, int missing_side) {
  const int ghost = 3 + missing_side;
  c.row((missing_side + 1) % 3) += c.row(ghost);
  c.row((missing_side + 2) % 3) += c.row(ghost);
  c.row(missing_side) -= c.row(ghost);
  c.row(ghost).setZero();
}

/// Gradients of the linear shape functions of the triangle, one row per node (KL6).
Eigen::Matrix<double, 3, 2> linear_gradients(const std::array<Vec2d, kPatchNodes>& p) {
  const double two_area =
      (p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x();
  Eigen::Matrix<double, 3, 2> L;
  for (int i = 0; i < 3; ++i) {
    const Vec2d& pj = p[(i + 1) % 3];
    const Vec2d& pk = p[(i + 2) % 3];
    L.row(i) << (pj.y() - pk.y()) / two_area, (pk.x() - pj.x()) / two_area;
  }
  return L;
}

/// k^{αβ} of (KL6) for (11, 22, 12).
std::array<NodeWeights, 3> curvature_weights(const std::array<SideCoefficients, 3>& c,
                                             const Eigen::Matrix<double, 3, 2>& L) {
  std::array<NodeWeights, 3> k;
  for (auto& w : k) w.setZero();
  for (int i = 0; i < 3; ++i) {
    k[0] -= 2.0 * L(i, 0) * c[i].col(0);
    k[1] -= 2.0 * L(i, 1) * c[i].col(1);
    k[2] -= L(i, 0) * c[i].col(1) + L(i, 1) * c[i].col(0);
  }
  return k;
}

}  // namespace

ShellGeometry compute_shell_geometry(const PatchPositions& X_global,
                                     const NeighbourFlags& has_neighbour) {
  // Positions relative to the triangle's centroid: the element depends on differences only, and
  // the sums of the side gradients (KL3) then cancel terms of the element's size, not of its
  // distance from the origin (a patch 100 mm out in elements of 5 mm had strain round-off of
  // 1e-14, forces of 1e-14 N, which stalled Newton on a small load).
  const Vec3d origin = (X_global[0] + X_global[1] + X_global[2]) / 3.0;
  PatchPositions X;
  for (int n = 0; n < kPatchNodes; ++n) X[n] = X_global[n] - origin;
  ShellGeometry g;
  g.has_neighbour = has_neighbour;
  g.frame = triangle_frame(X, g.area);
  const std::array<Vec2d, kPatchNodes> p = plane_coordinates(X, g.frame, has_neighbour);
  const Eigen::Matrix<double, 3, 2> L = linear_gradients(p);
  g.fitted = fitted_side_coefficients(p, g.side);
  if (!g.fitted) {
    for (int i = 0; i < 3; ++i) g.side[i] = isoparametric_side_coefficients(p, i);
  }
  for (int i = 0; i < 3; ++i) {
    if (has_neighbour[i]) continue;
    for (SideCoefficients& c : g.side) fold_mirror_node(c, i);
    g.side[i].setZero();  // the triangle's own constant gradient on a free side (KL8)
    g.side[i].topRows<3>() = L;
  }
  g.curvature = curvature_weights(g.side, L);
  for (int n = 0; n < kPatchNodes; ++n) {
    const bool used = n < kTriangleNodes || has_neighbour[n - kTriangleNodes];
    g.X.segment<3>(3 * n) = used ? X[n] : Vec3d::Zero();
  }
  g.reference_metric = mean_metric(g, g.X);
  const std::array<Vec3d, 3> V = curvature_vectors(g, g.X);
  for (int c = 0; c < 3; ++c) g.reference_curvature(c) = g.frame.col(2).dot(V[c]);
  return g;
}

}  // namespace plisse::shell
