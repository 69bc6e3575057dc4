#include "physics/quadratic_triangle.hpp"

#include "physics/triangle_quadrature.hpp"

namespace plisse::quadratic_triangle {

std::array<double, kNodes> shape_values(const std::array<double, 3>& L) {
  // (loads.md, L7)
  return {L[0] * (2.0 * L[0] - 1.0), L[1] * (2.0 * L[1] - 1.0), L[2] * (2.0 * L[2] - 1.0),
          4.0 * L[0] * L[1],         4.0 * L[1] * L[2],         4.0 * L[2] * L[0]};
}

std::array<std::array<double, kNodes>, 2> shape_derivatives(const std::array<double, 3>& L) {
  // dL0/dξ = dL0/dη = -1, dL1/dξ = 1, dL2/dη = 1.
  const double d0 = 4.0 * L[0] - 1.0, d1 = 4.0 * L[1] - 1.0, d2 = 4.0 * L[2] - 1.0;
  return {{{-d0, d1, 0.0, 4.0 * (L[0] - L[1]), 4.0 * L[2], -4.0 * L[2]},
           {-d0, 0.0, d2, -4.0 * L[1], 4.0 * L[1], 4.0 * (L[0] - L[2])}}};
}

const std::array<RulePoint, 6>& rule_points() {
  static const std::array<RulePoint, 6> table = [] {
    std::array<RulePoint, 6> out{};
    for (std::size_t q = 0; q < out.size(); ++q) {
      const TrianglePoint& p = kTriangleRuleDegree4[q];
      const auto d = shape_derivatives(p.L);
      out[q] = {shape_values(p.L), d[0], d[1], 0.5 * p.weight};
    }
    return out;
  }();
  return table;
}

FaceFrame face_frame(const std::array<Vec3d, kNodes>& xs, const RulePoint& q) {
  FaceFrame f{Vec3d::Zero(), Vec3d::Zero(), Vec3d::Zero()};
  for (int a = 0; a < kNodes; ++a) {
    f.x += q.N[a] * xs[a];
    f.x_xi += q.dN_dxi[a] * xs[a];
    f.x_eta += q.dN_deta[a] * xs[a];
  }
  return f;
}

}  // namespace plisse::quadratic_triangle
