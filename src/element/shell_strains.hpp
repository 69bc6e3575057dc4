#pragma once
/// The generalized strains of the shell triangle, s = (ε11, ε22, ε12, κ11, κ22, κ12), and their
/// first and second derivatives with respect to the 18 nodal positions of the patch
/// (docs/theory/shell.md, KL4-KL7, KL17-KL18). Geometry only: no material. No heap; thread-safe.
#include <array>

#include "element/shell_geometry.hpp"

namespace plisse::shell {

using StrainGradient = Eigen::Matrix<double, kStrains, kPatchDofs>;

/// Everything the derivatives need at one state of the patch, computed once.
struct ShellKinematics {
  PatchVec x;                     ///< current positions [mm]
  Mat32d mean_gradient;           ///< F̄ (KL4a)
  std::array<Vec3d, 3> v;         ///< v_αβ for (11, 22, 12) (KL6) [1/mm]
  Vec3d normal;                   ///< t3 (KL5)
  double normal_length = 0.0;     ///< |g| = |(x1 - x0) × (x2 - x0)| [mm²]
  std::array<Mat3d, 3> d_normal;  ///< T_n = ∂t3/∂x_n, n = 0, 1, 2 (KL18)
  StrainVec strains;              ///< s: ε [-], κ [1/mm] (KL4, KL7)
};

/// The kinematics at current positions x. Throws InadmissibleDeformation when the triangle has
/// collapsed (|g| = 0).
ShellKinematics compute_shell_kinematics(const ShellGeometry& g, const PatchVec& x);

/// ∂s/∂x (KL17, KL18).
StrainGradient compute_strain_gradient(const ShellGeometry& g, const ShellKinematics& k);

/// K += Σ_k w_k ∂²s_k/∂x∂x (KL17, KL18): the second-derivative part of the tangent (KL16).
void add_strain_hessians(const ShellGeometry& g, const ShellKinematics& k, const StrainVec& w,
                         PatchMat& K);

}  // namespace plisse::shell
