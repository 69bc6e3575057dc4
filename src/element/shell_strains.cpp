#include "element/shell_strains.hpp"

#include <cmath>

#include "material/inadmissible_deformation.hpp"

namespace plisse::shell {

namespace {

/// G_n = ∂g/∂x_n = [x_{n+2} - x_{n+1}]× for the triangle's nodes n = 0, 1, 2 (KL18).
Mat3d normal_derivative_unnormalised(const PatchVec& x, int n) {
  const int n1 = (n + 1) % 3;
  const int n2 = (n + 2) % 3;
  return cross_matrix(x.segment<3>(3 * n2) - x.segment<3>(3 * n1));
}

/// σ_nm of (KL18): the sign of ∂²g[u at n, w at m] = σ u × w.
double bilinear_sign(int n, int m) {
  if (m == (n + 1) % 3) return 1.0;
  if (n == (m + 1) % 3) return -1.0;
  return 0.0;
}

/// V · ∂²t3/∂x_n∂x_m for the triangle's nodes n, m (KL18).
Mat3d normal_hessian_block(const ShellKinematics& k, const Vec3d& V, int n, int m) {
  const Vec3d& t = k.normal;
  const double l = k.normal_length;
  const Mat3d P = Mat3d::Identity() - t * t.transpose();
  const Mat3d Gn = normal_derivative_unnormalised(k.x, n);
  const Mat3d Gm = normal_derivative_unnormalised(k.x, m);
  const Mat3d& Tn = k.d_normal[n];
  const Mat3d& Tm = k.d_normal[m];
  Mat3d block = -bilinear_sign(n, m) * cross_matrix(P * V);
  block -= (Gn.transpose() * t) * (Tm.transpose() * V).transpose();
  block -= V.dot(t) * Gn.transpose() * Tm;
  block -= (Tn.transpose() * V) * (Gm.transpose() * t).transpose();
  return block / l;
}

/// The scalar coefficients of ∂²(Σ_c w_c ε_c)/∂x_n∂x_m (KL17); the block is that times I.
Eigen::Matrix<double, kPatchNodes, kPatchNodes> membrane_hessian(const ShellGeometry& g,
                                                                 const StrainVec& w) {
  const NodeWeights c1 = g.membrane.col(0);
  const NodeWeights c2 = g.membrane.col(1);
  return w(0) * c1 * c1.transpose() + w(1) * c2 * c2.transpose() +
         0.5 * w(2) * (c1 * c2.transpose() + c2 * c1.transpose());
}

}  // namespace

ShellKinematics compute_shell_kinematics(const ShellGeometry& g, const PatchVec& x) {
  ShellKinematics k;
  k.x = x;
  k.mean_gradient = mean_gradient(g, x);
  const Mat32d& d = k.mean_gradient;
  const Vec3d metric(d.col(0).squaredNorm(), d.col(1).squaredNorm(),
                     d.col(0).dot(d.col(1)));  // ā (KL4)
  k.v = curvature_vectors(g, x);
  const Vec3d normal = triangle_normal(x);
  k.normal_length = normal.norm();
  if (!(k.normal_length > 0.0) || !std::isfinite(k.normal_length)) {
    throw InadmissibleDeformation("shell: the triangle has collapsed (zero area)");
  }
  k.normal = normal / k.normal_length;
  const Mat3d P = Mat3d::Identity() - k.normal * k.normal.transpose();
  for (int n = 0; n < kTriangleNodes; ++n) {
    k.d_normal[n] = P * normal_derivative_unnormalised(x, n) / k.normal_length;
  }
  k.strains.head<3>() = 0.5 * (metric - g.reference_metric);
  for (int c = 0; c < 3; ++c) {
    k.strains(3 + c) = g.reference_curvature(c) - k.normal.dot(k.v[c]);  // κ = B - b (KL7)
  }
  return k;
}

StrainGradient compute_strain_gradient(const ShellGeometry& g, const ShellKinematics& k) {
  StrainGradient D = StrainGradient::Zero();
  for (int n = 0; n < kPatchNodes; ++n) {
    const double c1 = g.membrane(n, 0);
    const double c2 = g.membrane(n, 1);
    const Vec3d& d1 = k.mean_gradient.col(0);
    const Vec3d& d2 = k.mean_gradient.col(1);
    D.block<1, 3>(0, 3 * n) = c1 * d1.transpose();
    D.block<1, 3>(1, 3 * n) = c2 * d2.transpose();
    D.block<1, 3>(2, 3 * n) = 0.5 * (c1 * d2 + c2 * d1).transpose();
    for (int c = 0; c < 3; ++c) {
      Vec3d db = g.curvature[c](n) * k.normal;
      if (n < kTriangleNodes) db += k.d_normal[n].transpose() * k.v[c];
      D.block<1, 3>(3 + c, 3 * n) = -db.transpose();  // ∂κ = -∂b (KL18)
    }
  }
  return D;
}

void add_strain_hessians(const ShellGeometry& g, const ShellKinematics& k, const StrainVec& w,
                         PatchMat& K) {
  const Eigen::Matrix<double, kPatchNodes, kPatchNodes> h = membrane_hessian(g, w);
  // The curvature part: κ = B - b, so the weights of b are -w (KL18).
  Vec3d V = Vec3d::Zero();
  NodeWeights kw = NodeWeights::Zero();
  for (int c = 0; c < 3; ++c) {
    V -= w(3 + c) * k.v[c];
    kw -= w(3 + c) * g.curvature[c];
  }
  for (int n = 0; n < kPatchNodes; ++n) {
    for (int m = 0; m < kPatchNodes; ++m) {
      if (n >= kTriangleNodes && m >= kTriangleNodes) {
        // Only the membrane part, a multiple of I: the off-diagonal entries stay as they are.
        for (int i = 0; i < 3; ++i) K(3 * n + i, 3 * m + i) += h(n, m);
        continue;
      }
      Mat3d block = h(n, m) * Mat3d::Identity();
      if (n < kTriangleNodes) block += kw(m) * k.d_normal[n].transpose();
      if (m < kTriangleNodes) block += kw(n) * k.d_normal[m];
      if (n < kTriangleNodes && m < kTriangleNodes) block += normal_hessian_block(k, V, n, m);
      K.block<3, 3>(3 * n, 3 * m) += block;
    }
  }
}

}  // namespace plisse::shell
