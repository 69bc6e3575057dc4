#include "element/shell_geometry.hpp"

#include <cmath>

#include "core/error.hpp"

namespace plisse::shell {

namespace {

/// Below this ratio of the smallest to the largest singular value of the fit (KL3a) the six nodes
/// are taken to lie on a conic and the isoparametric interpolation (KL3) is used instead.
constexpr double kMinFitConditioning = 1e-6;

/// Derivatives (∂/∂ξ, ∂/∂η) of the six patch functions of (KL2) at (ξ, η), one row per node.
Eigen::Matrix<double, 6, 2> natural_derivatives(double xi, double eta) {
  const double s = xi + eta;
  Eigen::Matrix<double, 6, 2> d;
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

/// The six points of a quadratic fit (KL3a) and the gradients of that fit at its own three side
/// midpoints, one 6 × 2 block of coefficients per side.
using FitPoints = std::array<Vec2d, 6>;
using FitCoefficients = Eigen::Matrix<double, 6, 2>;
using FitValues = Eigen::Matrix<double, 6, 1>;

/// The gradient (6 x 2) and the value (6) of a fit at the midpoint of each of its sides, as
/// coefficients of the six nodal positions.
struct FitAtSides {
  std::array<FitCoefficients, 3> gradient;
  std::array<FitValues, 3> value;
};

/// X_ghost = X_a + X_b - X_source: the node a missing slot stands for, the mirror image of
/// `source` through the midpoint of the side (a, b) it lies across (KL8).
struct Ghost {
  int a, b, source;
};

/// The ghost of missing slot n >= 3 (KL8, KL1b): slot 3 + i is the image of corner i through side
/// i; slot 6 + 2i + w the image of corner i + 1 + w through the side of neighbour i opposite it.
Ghost ghost_of(int n) {
  if (n < 6) {
    const int i = n - 3;
    return {(i + 1) % 3, (i + 2) % 3, i};
  }
  const int i = (n - 6) / 2, w = (n - 6) % 2;
  const int across = 3 + i, source = (i + 1 + w) % 3, other = (i + 2 - w) % 3;
  return {across, other, source};
}

/// The slots of neighbour i's own patch (KL1) in its order: its corners across (3 + i), corner
/// i + 2, corner i + 1 (counter-clockwise), then the nodes across its sides, so that its side 0
/// is side i of the triangle.
std::array<int, 6> neighbour_patch(int i) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  return {3 + i, k, j, i, outer_slot(i, 1), outer_slot(i, 0)};
}

/// Whether side i's gradient is the mean of the two elements' fits (KL3b): a node or a mirror
/// image across it.
bool has_neighbour_fit(const SlotKinds& slots, int i) { return slots[3 + i] != Slot::missing; }

/// Whether slot n enters the element: the triangle, a node or image across its sides, and the
/// nodes or images beyond a side that has a neighbour fit.
bool used_slot(const SlotKinds& slots, int n) {
  if (n < kTriangleNodes) return true;
  if (slots[n] == Slot::missing) return false;
  return n < 6 || has_neighbour_fit(slots, (n - 6) / 2);
}

/// 2-D coordinates of the 12 slots in the triangle's plane; a missing slot is its ghost (KL8),
/// an unused one left at zero.
std::array<Vec2d, kPatchNodes> plane_coordinates(const PatchPositions& X, const Mat3d& frame,
                                                 const SlotKinds& slots) {
  std::array<Vec2d, kPatchNodes> p;
  for (int n = 0; n < kPatchNodes; ++n) {
    p[n] = used_slot(slots, n) ? Vec2d(frame.leftCols<2>().transpose() * (X[n] - X[0]))
                               : Vec2d::Zero();
  }
  // Slots 3 to 5 first: the ghosts beyond a side refer to the node across it.
  for (int n = kTriangleNodes; n < kPatchNodes; ++n) {
    if (slots[n] != Slot::missing || (n >= 6 && !has_neighbour_fit(slots, (n - 6) / 2))) continue;
    const Ghost h = ghost_of(n);
    p[n] = p[h.a] + p[h.b] - p[h.source];
  }
  return p;
}

/// The gradient on side i of the isoparametric quadratic patch (KL2) of six points in the order
/// of (KL1): c^i = ∇_ξN (m_i) 𝐉_i⁻¹. Throws for a singular or folded map.
FitCoefficients isoparametric_side_coefficients(const FitPoints& p, int i) {
  const Vec2d m = side_midpoint(i);
  const FitCoefficients dN = natural_derivatives(m.x(), m.y());
  Mat2d J = Mat2d::Zero();  // J(a, b) = ∂X̃_a/∂ξ_b
  for (int n = 0; n < 6; ++n) J += p[n] * dN.row(n);
  const double det = J.determinant();
  PLISSE_CHECK(std::isfinite(det) && det > 1e-8 * J.squaredNorm(),
               "shell patch: the quadratic map of side " << i << " is singular or folded (det "
                                                         << det << ")");
  return dN * J.inverse();  // row n: (J⁻ᵀ ∇_ξ N_n)ᵀ
}

/// The gradients on the three sides of the quadratic polynomial in the plane coordinates that
/// takes the six nodal values (KL3a): exact for every quadratic field on any patch. False when
/// the six points lie (nearly) on a conic, where that polynomial is not unique.
bool fitted_side_coefficients(const FitPoints& p, FitAtSides& c) {
  const Vec2d centre = (p[0] + p[1] + p[2]) / 3.0;
  const double scale = (p[1] - p[0]).norm();
  auto scaled = [&](const Vec2d& q) { return Vec2d((q - centre) / scale); };
  Eigen::Matrix<double, 6, 6> V;  // row n: (1, x, y, x², xy, y²) at node n
  for (int n = 0; n < 6; ++n) {
    const Vec2d q = scaled(p[n]);
    V.row(n) << 1.0, q.x(), q.y(), q.x() * q.x(), q.x() * q.y(), q.y() * q.y();
  }
  // The ratio of the extreme singular values, not an LU estimate: the estimate can miss an
  // exactly singular V.
  const Eigen::Vector<double, 6> sv =
      Eigen::JacobiSVD<Eigen::Matrix<double, 6, 6>>(V).singularValues();
  if (!(sv(5) > kMinFitConditioning * sv(0))) return false;
  const Eigen::Matrix<double, 6, 6> V_inverse_T = V.partialPivLu().inverse().transpose();
  for (int i = 0; i < 3; ++i) {
    const Vec2d m = scaled(0.5 * (p[(i + 1) % 3] + p[(i + 2) % 3]));
    FitCoefficients dP;  // ∂(1, x, y, x², xy, y²)/∂X_α at the side's midpoint
    dP << 0, 0, 1, 0, 0, 1, 2 * m.x(), 0, m.y(), m.x(), 0, 2 * m.y();
    FitValues P;  // (1, x, y, x², xy, y²) there
    P << 1.0, m.x(), m.y(), m.x() * m.x(), m.x() * m.y(), m.y() * m.y();
    c.gradient[i] = V_inverse_T * dP / scale;
    c.value[i] = V_inverse_T * P;
  }
  return true;
}

/// The gradient and the value at each side's midpoint of the quadratic through the patch slots
/// `at` (KL3a), or of the isoparametric map (KL3) when they lie on a conic, scattered onto the 12
/// slots. Returns whether the fit was used.
bool patch_side_coefficients(const std::array<Vec2d, kPatchNodes>& p, const std::array<int, 6>& at,
                             std::array<SideCoefficients, 3>& gradient,
                             std::array<NodeWeights, 3>& value) {
  FitPoints q;
  for (int n = 0; n < 6; ++n) q[n] = p[at[n]];
  FitAtSides fit;
  const bool fitted = fitted_side_coefficients(q, fit);
  for (int i = 0; i < 3; ++i) {
    if (!fitted) {
      // The isoparametric map takes the natural midpoint of a side elsewhere than the side's
      // midpoint on a distorted patch: the value there is the side's linear one (KL4a).
      fit.gradient[i] = isoparametric_side_coefficients(q, i);
      fit.value[i].setZero();
      fit.value[i]((i + 1) % 3) = fit.value[i]((i + 2) % 3) = 0.5;
    }
    gradient[i].setZero();
    value[i].setZero();
    for (int n = 0; n < 6; ++n) {
      gradient[i].row(at[n]) += fit.gradient[i].row(n);
      value[i](at[n]) += fit.value[i](n);
    }
  }
  return fitted;
}

/// A missing slot's coefficients moved onto the slots its ghost is made of (KL8).
template <class Coefficients>
void fold_ghost(Coefficients& c, int slot) {
  const Ghost h = ghost_of(slot);
  c.row(h.a) += c.row(slot);
  c.row(h.b) += c.row(slot);
  c.row(h.source) -= c.row(slot);
  c.row(slot).setZero();
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

/// The coefficients of the triangle's mean gradient (KL4a): with ℓ_i ν^i = -2 A ∇L_i and
/// Simpson's rule along each side, F̄ = (1/A) Σ_i ℓ_i ν^i ⊗ [(x_j + x_k)/6 + (2/3) φ(m_i)].
SideCoefficients membrane_weights(const std::array<NodeWeights, 3>& value,
                                  const Eigen::Matrix<double, 3, 2>& L) {
  SideCoefficients m = SideCoefficients::Zero();
  for (int i = 0; i < 3; ++i) {
    NodeWeights along = (2.0 / 3.0) * value[i];
    along((i + 1) % 3) += 1.0 / 6.0;
    along((i + 2) % 3) += 1.0 / 6.0;
    m -= 2.0 * along * L.row(i);
  }
  return m;
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

ShellGeometry compute_shell_geometry(const PatchPositions& X_global, const SlotKinds& slots) {
  for (int n = 0; n < kTriangleNodes; ++n)
    PLISSE_CHECK(slots[n] == Slot::node, "shell patch: corner " << n << " is not a node");
  // Positions relative to the triangle's centroid: the element depends on differences only, and
  // the sums of the side gradients (KL3) then cancel terms of the element's size, not of its
  // distance from the origin (a patch 100 mm out in elements of 5 mm had strain round-off of
  // 1e-14, forces of 1e-14 N, which stalled Newton on a small load).
  const Vec3d origin = (X_global[0] + X_global[1] + X_global[2]) / 3.0;
  PatchPositions X;
  for (int n = 0; n < kPatchNodes; ++n) X[n] = X_global[n] - origin;
  ShellGeometry g;
  g.slots = slots;
  g.frame = triangle_frame(X, g.area);
  const std::array<Vec2d, kPatchNodes> p = plane_coordinates(X, g.frame, slots);
  const Eigen::Matrix<double, 3, 2> L = linear_gradients(p);
  std::array<SideCoefficients, 3> side;  // c^i [1/mm] (KL3b)
  std::array<NodeWeights, 3> value;      // φ at each side's midpoint (KL4a)
  g.fitted = patch_side_coefficients(p, {0, 1, 2, 3, 4, 5}, side, value);
  for (int i = 0; i < 3; ++i) {
    if (!has_neighbour_fit(slots, i)) continue;
    // The mean of this triangle's fit and its neighbour's on the side they share (KL3b).
    std::array<SideCoefficients, 3> across;
    std::array<NodeWeights, 3> across_value;
    patch_side_coefficients(p, neighbour_patch(i), across, across_value);
    side[i] = 0.5 * (side[i] + across[0]);
    value[i] = 0.5 * (value[i] + across_value[0]);
  }
  // Ghosts beyond a side first: they are made of the node across it, which a ghost of slots 3 to
  // 5 never is.
  for (int n = kPatchNodes - 1; n >= kTriangleNodes; --n) {
    if (slots[n] != Slot::missing) continue;
    for (SideCoefficients& c : side) fold_ghost(c, n);
    for (NodeWeights& c : value) fold_ghost(c, n);
  }
  for (int i = 0; i < 3; ++i) {
    if (slots[3 + i] != Slot::missing) continue;
    side[i].setZero();  // the triangle's own constant gradient on a free side (KL8)
    side[i].topRows<3>() = L;
    value[i].setZero();  // and the side's own midpoint
    value[i]((i + 1) % 3) = value[i]((i + 2) % 3) = 0.5;
  }
  g.membrane = membrane_weights(value, L);
  g.curvature = curvature_weights(side, L);
  for (int n = 0; n < kPatchNodes; ++n) {
    g.X.segment<3>(3 * n) = used_slot(slots, n) ? X[n] : Vec3d::Zero();
  }
  g.reference_metric = mean_metric(g, g.X);
  const std::array<Vec3d, 3> V = curvature_vectors(g, g.X);
  for (int c = 0; c < 3; ++c) g.reference_curvature(c) = g.frame.col(2).dot(V[c]);
  return g;
}

}  // namespace plisse::shell
