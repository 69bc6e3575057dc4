#pragma once
/// The 6-node (quadratic) triangle of a second-order boundary face: its shape functions, and the
/// position and tangent vectors of the face map at the points of the degree-4 triangle rule
/// (docs/theory/loads.md, L7).
///
/// Nodes: the corners 0, 1, 2, then the edge nodes of the edges 01, 12, 20 (mesh/mesh.hpp). The
/// face map is x(ξ, η) = Σ_a N_a(ξ, η) x_a on the reference triangle ξ, η >= 0, ξ + η <= 1, with
/// barycentric coordinates L0 = 1 - ξ - η, L1 = ξ, L2 = η.
#include <array>

#include "core/types.hpp"

namespace plisse::quadratic_triangle {

inline constexpr int kNodes = 6;

/// The shape functions at barycentric coordinates L (L7): corners L_a (2 L_a - 1), edge nodes
/// 4 L0 L1, 4 L1 L2, 4 L2 L0.
std::array<double, kNodes> shape_values(const std::array<double, 3>& L);

/// Their derivatives dN_a/dξ (row 0) and dN_a/dη (row 1) at L.
std::array<std::array<double, kNodes>, 2> shape_derivatives(const std::array<double, 3>& L);

/// Shape functions and derivatives at one point of the degree-4 rule (kTriangleRuleDegree4), and
/// its weight in the reference measure dξ dη (the rule's weight times 1/2, the reference area).
struct RulePoint {
  std::array<double, kNodes> N, dN_dxi, dN_deta;
  double weight;
};

/// The six points of the degree-4 rule, tabulated once.
const std::array<RulePoint, 6>& rule_points();

/// Position x and tangent vectors x_ξ, x_η of the face with nodes `xs` [mm] at the rule point `q`;
/// x_ξ × x_η is the area vector per unit reference area (L7).
struct FaceFrame {
  Vec3d x, x_xi, x_eta;
};
FaceFrame face_frame(const std::array<Vec3d, kNodes>& xs, const RulePoint& q);

}  // namespace plisse::quadratic_triangle
