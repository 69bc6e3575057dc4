#pragma once
/// The follower-pressure contribution of one boundary face, a linear (3-node) or a quadratic
/// (6-node) triangle: its nodal residual and its load stiffness (docs/theory/loads.md, L2-L3 and
/// L8-L9). The pressure load and the cavity wall both call it, so the two terms add exactly the
/// same numbers for the same pressure and face.
#include <array>
#include <span>

#include "core/types.hpp"

namespace plisse {

/// A 9 x 9 row-major view (rows and columns 3 a + i: corner a, component i) into an element block
/// that may be larger (the cavity borders it with its pressure row and column).
using FollowerPressureBlock =
    Eigen::Ref<Eigen::Matrix<double, 9, 9, Eigen::RowMajor>, 0, Eigen::OuterStride<>>;
/// The same for a 6-node face: 18 x 18, rows and columns 3 a + i for node a = 0..5.
using FollowerPressureBlock6 =
    Eigen::Ref<Eigen::Matrix<double, 18, 18, Eigen::RowMajor>, 0, Eigen::OuterStride<>>;

/// Adds the follower-pressure residual of the triangle with deformed corners `xs` [mm] under the
/// pressure `p` [MPa]: residual[dofs[3 a + i]] += p c_i / 6 for every corner a and component i,
/// with c = (x1 - x0) x (x2 - x0) (loads.md, L2; residual = internal minus external force).
/// `dofs` holds at least 9 indices into `residual`, corner-major. Returns c [mm^2].
Vec3d add_follower_pressure_residual(double p, const std::array<Vec3d, 3>& xs,
                                     std::span<const int> dofs, std::span<double> residual);

/// Writes the load stiffness K_ab = (p/6) dc/dx_b of the same triangle into `k` (loads.md, L3):
/// dc/dx0 = [x2 - x1]x, dc/dx1 = [x0 - x2]x, dc/dx2 = [x1 - x0]x. Overwrites all 81 entries.
void follower_pressure_stiffness(double p, const std::array<Vec3d, 3>& xs, FollowerPressureBlock k);

/// Adds the follower-pressure residual of the 6-node face with deformed nodes `xs` [mm] (corners,
/// then the edge nodes of 01, 12, 20) under the pressure `p` [MPa]: residual[dofs[3 a + i]] +=
/// p g_a,i with g_a = ∫ N_a (x_ξ × x_η) dξ dη (loads.md, L8), integrated exactly by the degree-4
/// rule. `dofs` holds at least 18 indices into `residual`, node-major. Returns g_a [mm^2], the
/// residual per unit pressure (the cavity's column, cavities.md, C13).
std::array<Vec3d, 6> add_follower_pressure_residual(double p, const std::array<Vec3d, 6>& xs,
                                                    std::span<const int> dofs,
                                                    std::span<double> residual);

/// Writes the load stiffness K_ab = p dg_a/dx_b of the same 6-node face into `k` (loads.md, L9).
/// Overwrites all 324 entries.
void follower_pressure_stiffness(double p, const std::array<Vec3d, 6>& xs,
                                 FollowerPressureBlock6 k);

}  // namespace plisse
