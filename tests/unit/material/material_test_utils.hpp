#pragma once
/// Helpers for the material unit tests: reproducible deformations, finite differences, rates.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/types.hpp"

namespace plisse::test {

/// F = I + s M with M uniform in [-1, 1]^{3x3}, s = max_strain, redrawn until det F > 0.25.
inline Mat3d random_deformation(unsigned seed, double max_strain) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (;;) {
    Mat3d F = Mat3d::Identity();
    for (int k = 0; k < 9; ++k) F.data()[k] += max_strain * u(gen);
    if (F.determinant() > 0.25) return F;
  }
}

/// A unit-Frobenius-norm direction in the space of 3x3 matrices.
inline Mat3d random_direction(unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mat3d D;
  for (int k = 0; k < 9; ++k) D.data()[k] = u(gen);
  return D / D.norm();
}

/// A proper rotation (det = +1) from a random unit quaternion.
inline Mat3d random_rotation(unsigned seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Quaterniond q(n(gen), n(gen), n(gen), n(gen));
  q.normalize();
  return q.toRotationMatrix();
}

/// dP/dF of `model` at F by central differences of its stress, step h = 1e-5 max(1, max |F_ij|).
template <class Model>
Mat9d central_difference_tangent(const Model& model, const Mat3d& F) {
  const double h = 1e-5 * std::max(1.0, F.cwiseAbs().maxCoeff());
  Mat9d A;
  for (int k = 0; k < 9; ++k) {
    Mat3d Fp = F, Fm = F;
    Fp.data()[k] += h;
    Fm.data()[k] -= h;
    const Mat3d dP = (model.evaluate(Fp).P - model.evaluate(Fm).P) / (2 * h);
    A.col(k) = Eigen::Map<const Vec9d>(dP.data());
  }
  return A;
}

/// Least-squares slope of log(err) against log(h) for h halving at each entry: the observed
/// order of convergence (2 for a central difference of a correct derivative).
inline double observed_order(const std::vector<double>& err) {
  const int n = static_cast<int>(err.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int k = 0; k < n; ++k) {
    const double x = -k * std::log(2.0), y = std::log(err[k]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

/// The test deformations: random ones with strains up to 0.5, and large stretches such as the
/// cube test's uniaxial stretch 5 (rotated), an equibiaxial stretch 3 and a volume change.
inline std::vector<Mat3d> test_deformations() {
  std::vector<Mat3d> out;
  for (unsigned seed = 1; seed <= 6; ++seed)
    out.push_back(random_deformation(seed, seed <= 3 ? 0.2 : 0.5));
  const double l = 5.0;
  out.push_back(random_rotation(7) * Vec3d(1 / std::sqrt(l), 1 / std::sqrt(l), l).asDiagonal());
  out.push_back(Vec3d(3.0, 3.0, 1.0 / 9.0).asDiagonal() * random_rotation(8));
  out.push_back(1.3 * random_deformation(9, 0.3));  // J far from 1: the isochoric split matters
  return out;
}

}  // namespace plisse::test
