#pragma once
/// Reference geometry of one patch of the rotation-free shell triangle (EBST,
/// docs/theory/shell.md): the triangle, the nodes across its sides and across its neighbours'
/// sides, and the coefficients that turn nodal positions into the mean gradient of the membrane
/// (KL4a) and the curvature (KL6), both built from the gradients on the sides (KL3b). Computed
/// once per element from the reference positions; the kernels (element/shell.hpp) only read it.
///
/// Slot order (KL1, KL1b): 0, 1, 2 the triangle, counter-clockwise about its normal; 3 + i the
/// node of the neighbour across side i, the side opposite node i (side 0 joins 1-2, side 1 joins
/// 2-0, side 2 joins 0-1); 6 + 2i and 7 + 2i the nodes across that neighbour's sides opposite
/// corner i + 1 and corner i + 2 of the triangle. Unknowns: slot n's three translations at 3n,
/// 3n + 1, 3n + 2.
#include <array>

#include "core/types.hpp"

namespace plisse::shell {

inline constexpr int kPatchNodes = 12;
inline constexpr int kTriangleNodes = 3;
inline constexpr int kPatchDofs = 3 * kPatchNodes;
/// Generalized strains s = (ε11, ε22, ε12, κ11, κ22, κ12) (KL15).
inline constexpr int kStrains = 6;

using Vec2d = Eigen::Vector2d;
using Mat2d = Eigen::Matrix2d;
using Mat32d = Eigen::Matrix<double, 3, 2>;
using PatchVec = Eigen::Matrix<double, kPatchDofs, 1>;
using PatchMat = Eigen::Matrix<double, kPatchDofs, kPatchDofs>;
using StrainVec = Eigen::Matrix<double, kStrains, 1>;
using StrainMat = Eigen::Matrix<double, kStrains, kStrains>;
using PatchPositions = std::array<Vec3d, kPatchNodes>;
/// For each node, the coefficients of one side's gradient (KL3): φ'_α = Σ_n c(n, α) x_n.
using SideCoefficients = Eigen::Matrix<double, kPatchNodes, 2>;
/// For each node, the coefficient of one component of v (KL6): v = Σ_n k(n) x_n.
using NodeWeights = Eigen::Matrix<double, kPatchNodes, 1>;

/// What a slot of the patch holds (KL1b).
enum class Slot : unsigned char {
  node,     ///< a node of the mesh
  image,    ///< the image of a node under a side's mirror map (a clamped or symmetry edge, KL8a);
            ///< its reference position is given
  missing,  ///< no node: across a free or hinged edge (KL8), or beyond a side without neighbour
};
using SlotKinds = std::array<Slot, kPatchNodes>;

/// Slot 6 + 2i + w, w = 0, 1: across the side of neighbour i opposite corner i + 1 + w (KL1b).
constexpr int outer_slot(int side, int w) { return 6 + 2 * side + w; }

/// Every slot a node (an element inside the mesh).
inline SlotKinds all_nodes() {
  SlotKinds k;
  k.fill(Slot::node);
  return k;
}

/// Every slot a node but side `side`'s neighbour and the two nodes beyond it (an element on a
/// free edge).
inline SlotKinds without_side(int side) {
  SlotKinds k = all_nodes();
  k[3 + side] = k[outer_slot(side, 0)] = k[outer_slot(side, 1)] = Slot::missing;
  return k;
}

/// The reference geometry of a patch. Plain data; thread-safe to share between kernels.
struct ShellGeometry {
  PatchVec X;          ///< reference positions of the 12 slots relative to the triangle's
                       ///< centroid [mm] (zero for a slot the element does not use); the element
                       ///< depends on differences only
  Mat3d frame;         ///< columns e1, e2, e3 of the triangle (KL3)
  double area = 0.0;   ///< A0 [mm²]
  SlotKinds slots{};   ///< what each slot holds (KL1b)
  bool fitted = true;  ///< the triangle's own side gradients from the quadratic fit (KL3a), else
                       ///< isoparametric (KL3)
  SideCoefficients membrane;  ///< m [1/mm]: the triangle's mean gradient F̄ = Σ_n x_n m_n (KL4a)
  std::array<NodeWeights, 3> curvature;  ///< k^{αβ} for (11, 22, 12) [1/mm²] (KL6)
  Vec3d reference_metric;                ///< Ā as (11, 22, 12) [-] (KL4)
  Vec3d reference_curvature;             ///< B as (11, 22, 12) [1/mm] (KL6)
};

/// The geometry of the patch with reference positions X, slot n holding what slots[n] says (the
/// entries of a missing slot are ignored; slots 0-2 must be nodes). Throws plisse::Error for a
/// degenerate triangle or a side whose quadratic map is singular (a neighbour on the side's line,
/// or folded over onto the triangle).
ShellGeometry compute_shell_geometry(const PatchPositions& X, const SlotKinds& slots);

/// F̄ of (KL4a) (3 × 2, columns along e_1, e_2): the triangle's mean gradient at positions x.
inline Mat32d mean_gradient(const ShellGeometry& g, const PatchVec& x) {
  Mat32d d = Mat32d::Zero();
  for (int n = 0; n < kPatchNodes; ++n) d += x.segment<3>(3 * n) * g.membrane.row(n);
  return d;
}

/// ā of (KL4) as (11, 22, 12): the metric F̄ᵀF̄ of the mean gradient at positions x.
inline Vec3d mean_metric(const ShellGeometry& g, const PatchVec& x) {
  const Mat32d d = mean_gradient(g, x);
  return Vec3d(d.col(0).squaredNorm(), d.col(1).squaredNorm(), d.col(0).dot(d.col(1)));
}

/// v_αβ of (KL6) for (11, 22, 12) at positions x: b_αβ = t3 · v_αβ.
inline std::array<Vec3d, 3> curvature_vectors(const ShellGeometry& g, const PatchVec& x) {
  std::array<Vec3d, 3> v;
  for (int c = 0; c < 3; ++c) {
    v[c].setZero();
    for (int n = 0; n < kPatchNodes; ++n) v[c] += g.curvature[c](n) * x.segment<3>(3 * n);
  }
  return v;
}

/// The unnormalised normal g = (x1 - x0) × (x2 - x0) of the triangle at positions x (KL5).
inline Vec3d triangle_normal(const PatchVec& x) {
  return (x.segment<3>(3) - x.segment<3>(0)).cross(x.segment<3>(6) - x.segment<3>(0));
}

}  // namespace plisse::shell
