#include "element/taylor_hood_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace plisse::taylor_hood {
namespace {

/// dL_a/dξ for ξ = (L1, L2, L3).
Vec3d barycentric_derivative(int a) {
  Vec3d d = Vec3d::Zero();
  if (a == 0)
    d.setConstant(-1.0);
  else
    d(a - 1) = 1.0;
  return d;
}

double jacobian_determinant(const std::array<Vec3d, kNodes>& X, const NodeGradients& dN,
                            Mat3d& jacobian) {
  jacobian.setZero();
  for (int a = 0; a < kNodes; ++a) jacobian.noalias() += X[a] * dN.col(a).transpose();
  return jacobian.determinant();
}

}  // namespace

std::array<double, kNodes> shape_values(const std::array<double, 4>& L) {
  std::array<double, kNodes> N;
  for (int a = 0; a < kCorners; ++a) N[a] = L[a] * (2.0 * L[a] - 1.0);
  for (int k = 0; k < 6; ++k) N[4 + k] = 4.0 * L[kTetEdges[k][0]] * L[kTetEdges[k][1]];
  return N;
}

NodeGradients shape_derivatives(const std::array<double, 4>& L) {
  NodeGradients dN;
  for (int a = 0; a < kCorners; ++a) dN.col(a) = (4.0 * L[a] - 1.0) * barycentric_derivative(a);
  for (int k = 0; k < 6; ++k) {
    const int i = kTetEdges[k][0], j = kTetEdges[k][1];
    dN.col(4 + k) = 4.0 * (L[j] * barycentric_derivative(i) + L[i] * barycentric_derivative(j));
  }
  return dN;
}

const std::array<NodeGradients, kQuadPoints>& reference_derivatives() {
  static const std::array<NodeGradients, kQuadPoints> table = [] {
    std::array<NodeGradients, kQuadPoints> t;
    for (int q = 0; q < kQuadPoints; ++q) t[q] = shape_derivatives(kQuadrature.points[q]);
    return t;
  }();
  return table;
}

Geometry compute_geometry(const std::array<Vec3d, kNodes>& X) {
  Geometry g;
  for (int a = 0; a < kCorners; ++a)
    for (int b = a + 1; b < kCorners; ++b) g.size = std::max(g.size, (X[a] - X[b]).norm());
  const double h3 = g.size * g.size * g.size;
  const auto check = [&](double det, const char* where) {
    PLISSE_CHECK(std::isfinite(det) && det > 1e-12 * h3,
                 "10-node tetrahedron with corners ("
                     << X[0].transpose() << "), (" << X[1].transpose() << "), (" << X[2].transpose()
                     << "), (" << X[3].transpose() << ") has det(dX/dξ) = " << det << " <= 0 at "
                     << where << " (inverted, degenerate or too strongly curved element)");
  };
  Mat3d jacobian;
  // The Jacobian of a curved element is a quadratic polynomial: positive at the points and the
  // corners is the check a mesh generator makes too. Degenerate to working precision counts as
  // zero (as for the linear tetrahedron, 1e-12 h³).
  for (int a = 0; a < kCorners; ++a) {
    std::array<double, 4> corner = {0.0, 0.0, 0.0, 0.0};
    corner[a] = 1.0;
    const double det = jacobian_determinant(X, shape_derivatives(corner), jacobian);
    check(det, "a corner");
  }
  for (int q = 0; q < kQuadPoints; ++q) {
    const double det = jacobian_determinant(X, reference_derivatives()[q], jacobian);
    check(det, "a quadrature point");
    g.jacobian_inverse_t[q] = jacobian.inverse().transpose();
    g.weight[q] = kQuadrature.weights[q] * det / 6.0;
    g.volume += g.weight[q];
  }
  return g;
}

}  // namespace plisse::taylor_hood
