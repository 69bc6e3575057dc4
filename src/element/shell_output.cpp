#include "element/shell_output.hpp"

#include <cmath>

namespace plisse::shell {

namespace {

/// [F̄ n]: the mean gradient of the triangle at positions x (KL4a) and a third column n.
Mat3d gradient_with_normal(const ShellGeometry& g, const PatchVec& x, const Vec3d& n) {
  Mat3d M;
  M << mean_gradient(g, x), n;
  return M;
}

}  // namespace

Mat3d mid_surface_deformation(const ShellGeometry& g, const PatchVec& u, double J) {
  const Mat3d reference = gradient_with_normal(g, g.X, g.frame.col(2));
  const PatchVec x = g.X + u;
  const Vec3d normal = triangle_normal(x);
  const double length = normal.norm();
  Mat3d current = gradient_with_normal(g, x, normal / length);
  const double in_plane = current.determinant();  // (φ̄'_1 × φ̄'_2) · t3
  if (!(length > 0.0) || !(in_plane > 0.0) || !std::isfinite(in_plane)) {
    throw InadmissibleDeformation("shell: the triangle has collapsed or turned over");
  }
  current.col(2) *= J * reference.determinant() / in_plane;  // det F = J (KL19)
  return current * reference.inverse();
}

Mat3d current_frame(const Mat3d& F, const ShellGeometry& g, const Vec3d& t3) {
  const Vec3d image = F * g.frame.col(0);
  Mat3d Q;
  Q.col(0) = (image - image.dot(t3) * t3).normalized();
  Q.col(2) = t3;
  Q.col(1) = t3.cross(Q.col(0));
  return Q;
}

Mat3d plane_stress_cauchy(const Mat2d& C2, const Mat2d& S2, const Mat3d& current_frame, double J) {
  Mat2d U = Mat2d::Zero();  // upper Cholesky factor, UᵀU = C₂
  U(0, 0) = std::sqrt(C2(0, 0));
  U(0, 1) = C2(0, 1) / U(0, 0);
  U(1, 1) = std::sqrt(C2.determinant()) / U(0, 0);
  const Mat2d tau = U * S2 * U.transpose();  // Kirchhoff stress, J σ
  const Eigen::Matrix<double, 3, 2> Q = current_frame.leftCols<2>();
  return Q * tau * Q.transpose() / J;
}

ShellOutputs zero_shell_outputs() {
  ShellOutputs zero;
  zero.thickness = 0.0;
  zero.membrane_force.setZero();
  zero.bending_moment.setZero();
  zero.curvature_change.setZero();
  for (int f = 0; f < kShellFaces; ++f) {
    zero.face_cauchy[f].setZero();
    zero.face_stretches[f].setZero();
  }
  return zero;
}

int nearest_section_point(const ShellSection& section, double zeta) {
  int nearest = 0;
  for (int g = 1; g < section.n_points; ++g) {
    if (std::abs(section.zeta[g] - zeta) < std::abs(section.zeta[nearest] - zeta)) nearest = g;
  }
  return nearest;
}

}  // namespace plisse::shell
