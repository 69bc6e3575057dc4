// Node-to-facet gap: the gap, normal and barycentric coordinates on a facet with a closed form,
// the gradient and Hessian against central differences on random facets, the gradient as
// (n, -Na n, -Nb n, -Nc n), invariance under translation, the sign flip when the corners are
// reordered, and the rejection of degenerate facets (docs/theory/surface-contact.md, N9-N13).
#include "physics/node_facet_gap.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <sstream>

#include "core/error.hpp"

namespace plisse {
namespace {

using Vec12d = NodeFacetGap::Vec12d;

NodeFacetGap evaluate(const Vec12d& x, bool with_hessian) {
  return node_facet_gap(x.segment<3>(0), x.segment<3>(3), x.segment<3>(6), x.segment<3>(9),
                        with_hessian);
}

std::string scientific(double v) {
  std::ostringstream s;
  s << std::scientific << v;
  return s.str();
}

TEST(NodeFacetGap, ClosedFormOnARightTriangle) {
  const Vec3d xa(0, 0, 0), xb(2, 0, 0), xc(0, 2, 0);
  const NodeFacetGap above = node_facet_gap(Vec3d(0.5, 0.5, 0.3), xa, xb, xc, true);
  EXPECT_NEAR(above.g, 0.3, 1e-15);
  EXPECT_TRUE(above.n.isApprox(Vec3d(0, 0, 1), 1e-15));
  EXPECT_TRUE(above.xi.isApprox(Vec3d(0.5, 0.25, 0.25), 1e-15));
  Vec12d expected;
  expected << 0, 0, 1, 0, 0, -0.5, 0, 0, -0.25, 0, 0, -0.25;
  EXPECT_LT((above.gradient - expected).cwiseAbs().maxCoeff(), 1e-15);
  // The node below the facet penetrates; outside the triangle xi leaves [0, 1] but sums to 1.
  const NodeFacetGap below = node_facet_gap(Vec3d(3, -1, -0.2), xa, xb, xc, false);
  EXPECT_NEAR(below.g, -0.2, 1e-15);
  EXPECT_TRUE(below.xi.isApprox(Vec3d(0.0, 1.5, -0.5), 1e-15));
  EXPECT_EQ(below.hessian.cwiseAbs().maxCoeff(), 0.0);  // not asked for
}

TEST(NodeFacetGap, DerivativesAreCentralDifferencesOfTheGap) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> corner(-1.0, 1.0), inplane(-0.2, 1.2), offset(-0.3, 0.3);
  const double h = 1e-6;
  double worst_gradient = 0.0, worst_hessian = 0.0, worst_symmetry = 0.0, worst_identity = 0.0;
  int configurations = 0;
  while (configurations < 20) {
    const Vec3d xa(corner(rng), corner(rng), corner(rng));
    const Vec3d xb(corner(rng), corner(rng), corner(rng));
    const Vec3d xc(corner(rng), corner(rng), corner(rng));
    const Vec3d a = (xb - xa).cross(xc - xa);
    if (a.norm() < 0.2) continue;  // keep the facets well shaped: no ill-conditioned differences
    ++configurations;
    // A node near the facet, above or below it, its projection inside or a little outside.
    const Vec3d xs =
        xa + inplane(rng) * (xb - xa) + inplane(rng) * (xc - xa) + offset(rng) * a.normalized();
    Vec12d x;
    x << xs, xa, xb, xc;
    const NodeFacetGap r = evaluate(x, true);

    // N10: the gradient is (n, -Na n, -Nb n, -Nc n), Na + Nb + Nc = 1, and xs - g n = sum N_i x_i.
    Vec12d identity;
    identity << r.n, -r.xi[0] * r.n, -r.xi[1] * r.n, -r.xi[2] * r.n;
    worst_identity = std::max(worst_identity, (r.gradient - identity).cwiseAbs().maxCoeff());
    EXPECT_NEAR(r.xi.sum(), 1.0, 1e-14);
    EXPECT_LT((xs - r.g * r.n - (r.xi[0] * xa + r.xi[1] * xb + r.xi[2] * xc)).norm(), 1e-14);
    EXPECT_NEAR(r.n.norm(), 1.0, 1e-15);

    // Central differences of g (gradient) and of the gradient (Hessian).
    Vec12d fd_gradient;
    NodeFacetGap::Mat12d fd_hessian;
    for (int j = 0; j < 12; ++j) {
      Vec12d xp = x, xm = x;
      xp[j] += h;
      xm[j] -= h;
      const NodeFacetGap rp = evaluate(xp, false), rm = evaluate(xm, false);
      fd_gradient[j] = (rp.g - rm.g) / (2 * h);
      fd_hessian.col(j) = (rp.gradient - rm.gradient) / (2 * h);
    }
    const double g_scale = r.gradient.cwiseAbs().maxCoeff();
    const double h_scale = r.hessian.cwiseAbs().maxCoeff();
    worst_gradient =
        std::max(worst_gradient, (fd_gradient - r.gradient).cwiseAbs().maxCoeff() / g_scale);
    worst_hessian =
        std::max(worst_hessian, (fd_hessian - r.hessian).cwiseAbs().maxCoeff() / h_scale);
    worst_symmetry = std::max(worst_symmetry,
                              (r.hessian - r.hessian.transpose()).cwiseAbs().maxCoeff() / h_scale);
    // The gap is linear in the node: d2g/dxs2 = 0.
    EXPECT_EQ(r.hessian.block(0, 0, 3, 3).cwiseAbs().maxCoeff(), 0.0);
  }
  RecordProperty("fd_relative_error_gradient", scientific(worst_gradient));
  RecordProperty("fd_relative_error_hessian", scientific(worst_hessian));
  RecordProperty("hessian_asymmetry", scientific(worst_symmetry));
  RecordProperty("gradient_identity_error", scientific(worst_identity));
  // Central differences: h^2 |third derivative| + round-off / h ~ 1e-10 relative.
  EXPECT_LT(worst_gradient, 1e-8);
  EXPECT_LT(worst_hessian, 1e-7);
  EXPECT_LT(worst_symmetry, 1e-14);
  EXPECT_LT(worst_identity, 1e-13);
}

TEST(NodeFacetGap, InvariantUnderTranslationAndFlippedBySwappingCorners) {
  const Vec3d xs(0.3, 0.8, -0.1), xa(-0.4, 0.1, 0.2), xb(0.9, -0.3, 0.5), xc(0.2, 1.1, -0.6);
  const NodeFacetGap r = node_facet_gap(xs, xa, xb, xc, true);
  const Vec3d d(3.0, -1.5, 2.25);
  const NodeFacetGap moved = node_facet_gap(xs + d, xa + d, xb + d, xc + d, true);
  EXPECT_NEAR(moved.g, r.g, 1e-14);
  EXPECT_TRUE(moved.n.isApprox(r.n, 1e-14));
  EXPECT_TRUE(moved.xi.isApprox(r.xi, 1e-13));
  EXPECT_LT((moved.hessian - r.hessian).cwiseAbs().maxCoeff(),
            1e-13 * r.hessian.cwiseAbs().maxCoeff());

  const NodeFacetGap swapped = node_facet_gap(xs, xa, xc, xb, false);
  EXPECT_DOUBLE_EQ(swapped.g, -r.g);
  EXPECT_TRUE(swapped.n.isApprox(-r.n, 1e-15));
  EXPECT_TRUE(swapped.xi.isApprox(Vec3d(r.xi[0], r.xi[2], r.xi[1]), 1e-14));
}

TEST(NodeFacetGap, RejectsDegenerateFacets) {
  const Vec3d xs(0.1, 0.2, 0.3);
  // Collinear corners, coincident corners, a corner that is not a number.
  EXPECT_THROW(node_facet_gap(xs, Vec3d(0, 0, 0), Vec3d(1, 1, 1), Vec3d(2, 2, 2), false), Error);
  EXPECT_THROW(node_facet_gap(xs, Vec3d(1, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), true), Error);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(node_facet_gap(xs, Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, nan, 0), false), Error);
}

}  // namespace
}  // namespace plisse
