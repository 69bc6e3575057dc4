// Gravity on the shell triangle (docs/theory/loads.md, L6s) against the closed form of a
// cantilever strip under its own weight.
//
// The strip of edge_conditions_test.cpp (L = 100 mm along x, W = 10 mm, t = 1 mm, flat in z = 0,
// incompressible neo-Hookean, μ = 2 c1 = 1 MPa) is clamped at x = 0, free at x = L, and held along
// its long edges by symmetry conditions (plane strain in y), so that it bends as a beam of
// rigidity D = μ t³/3 per unit width (E = 3 μ, ν = 1/2). Its weight is the dead load q = ρ g t per
// unit area, and beam theory gives the deflection of the free end
//   w = q L⁴ / (8 D)
// (Timoshenko & Gere 1972, Mechanics of Materials, table of cantilever deflections). The load is
// small (w/L about 10⁻³, w/t about 0.1): with its free end the strip carries no membrane force, and
// the geometric nonlinearity changes w by O((w/L)²), about 10⁻⁶.
//
// The clamp carries the whole weight: the reaction along z at its nodes is ρ g L W t.
//
// The same strip with its outer half (x > L/2) a region twice as thick (Mesh::triangle_thickness,
// as a case's `regions: [{box: ..., thickness: 2}]` makes it) weighs and bends as a beam of two
// sections: q and D jump at x = a = L/2, and the unit-load method gives the free end's deflection
//   w = ∫₀ᴸ M(x) (L − x) / D(x) dx,   M(x) = ∫ₓᴸ q(s) (s − x) ds
// (Timoshenko & Gere 1972, the unit-load method): on x > a, M = q₂ (L − x)² / 2 and the integral
// is q₂ (L − a)⁴ / (8 D₂); on x < a, M = q₁ (a − x)² / 2 + q₂ ((L − x)² − (a − x)²) / 2, a cubic
// times (L − x), integrated exactly by Gauss-Legendre's 3-point rule. The error falls at first
// order (the last halving's order above 0.8) to below 2.5·10⁻³ at nx = 80.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>
#include <vector>

#include "material/registry.hpp"
#include "mesh/shell_surface.hpp"
#include "physics/body_force.hpp"
#include "physics/dirichlet.hpp"
#include "shell_fixtures.hpp"
#include "solver/mixed_model.hpp"

namespace plisse {
namespace {

using namespace shell_test::strip_constants;  // c1, L, W, t and D of the strip

constexpr double kDensity = 2.5e-13;  // ρ [tonne/mm³]: w = 9.2e-2 mm with g below
constexpr double kGravity = 9810.0;   // g [mm/s²], along -z

struct Cantilever {
  double deflection = 0.0;  ///< -u_z at the free end, the mean over its nodes [mm]
  double reaction = 0.0;    ///< the clamp's reaction along z [N]
};

/// The cantilever strip of nx cells along L (nx / 5 across, at least 2) under its own weight; with
/// `outer_thickness` > 0 the triangles beyond x = L/2 have that thickness (nx even: the step lies
/// on a line of the mesh).
Cantilever cantilever_under_its_weight(int nx, double outer_thickness = 0.0) {
  Mesh mesh = shell_test::strip_mesh(kLength, kWidth, kThickness, nx, std::max(2, nx / 5),
                                     shell_test::Cells::same_diagonal, kLength);
  if (outer_thickness > 0.0) {
    std::vector<int> outer;
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
      double x = 0.0;
      for (int v : mesh.triangles[e]) x += mesh.nodes[static_cast<std::size_t>(v)].x() / 3.0;
      if (x > 0.5 * kLength) outer.push_back(static_cast<int>(e));
    }
    set_shell_thickness(mesh, outer, outer_thickness);
  }
  ConstraintSet set;
  const SurfaceRef left{"left", {}};
  shell_test::symmetric_long_edges(mesh, kWidth, set);
  fix_surface(mesh, left, set);
  clamp_sides(mesh, mesh.edge_tags.at("left"));
  const std::vector<ConstrainedComponent> constraints = set.components();
  std::vector<std::unique_ptr<ModelTerm>> terms;
  // The acceleration, scaled by the density of every triangle, as a case's gravity load is.
  terms.push_back(
      std::make_unique<BodyForce>(mesh, "g", Vec3d(0.0, 0.0, -kGravity), Ramp{},
                                  std::vector<double>(mesh.triangles.size(), kDensity)));
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", kC1}}), 0.0, constraints,
                   std::move(terms), ElementFamily::shell);
  // Nodal loads 5e-10 to 5e-8 N: Newton's residual falls to its round-off, below 1e-13 N.
  shell_test::solve_in_one_step(model, 1e-13);
  Cantilever result;
  int count = 0;
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (std::abs(mesh.nodes[v].x() - kLength) < 1e-9) {
      result.deflection -= model.state()[DofMap::dof(v, 2)];
      ++count;
    }
  EXPECT_GT(count, 0);
  result.deflection /= count;
  result.reaction = model.node_reaction(condition_nodes(mesh, left)).z();
  return result;
}

TEST(ShellGravity, CantileverStripUnderItsWeightConvergesToTheBeamDeflection) {
  const double q = kDensity * kGravity * kThickness;  // [MPa]
  const double exact = q * std::pow(kLength, 4) / (8.0 * kRigidity);
  const double weight = kDensity * kGravity * kLength * kWidth * kThickness;  // [N]
  std::vector<double> errors;
  for (const int nx : {10, 20, 40, 80}) {
    const Cantilever c = cantilever_under_its_weight(nx);
    errors.push_back(std::abs(c.deflection - exact) / exact);
    std::printf("nx = %2d: w = %.6e mm, exact %.6e mm, relative error %.2e", nx, c.deflection,
                exact, errors.back());
    if (errors.size() > 1)
      std::printf(", order %.2f", std::log2(errors[errors.size() - 2] / errors.back()));
    std::printf("; clamp reaction / weight - 1 = %.1e\n", c.reaction / weight - 1.0);
    // The clamp holds the weight, 2.45e-6 N, up to the sum of Newton's last residual on the free
    // dofs (its round-off, about 1e-14 N a node): measured 2e-12 to 5e-11.
    EXPECT_NEAR(c.reaction / weight, 1.0, 1e-9) << "nx = " << nx;
  }
  // Second order, as the strips of edge_conditions_test.cpp (measured 2.03 to 2.08): the weight's
  // thirds are the consistent loads of linear shape functions, and a free end's elements bend
  // little (the moment vanishes there).
  EXPECT_LT(errors.back(), 3e-4);  // measured 1.58e-4
  for (std::size_t n = 0; n + 1 < errors.size(); ++n)
    EXPECT_GT(errors[n] / errors[n + 1], 3.5) << "halving " << n;
}

/// The free end's deflection of the two-section cantilever (the header's unit-load integral) [mm]:
/// q₁, q₂ the weights per unit area [MPa], D₁, D₂ the rigidities per unit width [N mm] of x < a
/// and x > a.
double two_section_deflection(double q1, double q2, double D1, double D2, double a, double L) {
  const auto integrand = [&](double x) {
    const double M =
        0.5 * q1 * (a - x) * (a - x) + 0.5 * q2 * ((L - x) * (L - x) - (a - x) * (a - x));
    return M * (L - x) / D1;
  };
  // Gauss-Legendre, 3 points on [0, a]: exact for the quartic integrand.
  const double r = std::sqrt(0.6), half = 0.5 * a;
  const double inner =
      half * (5.0 / 9.0 * integrand(half * (1.0 - r)) + 8.0 / 9.0 * integrand(half) +
              5.0 / 9.0 * integrand(half * (1.0 + r)));
  return inner + q2 * std::pow(L - a, 4) / (8.0 * D2);
}

TEST(ShellGravity, CantileverWithAThickerOuterHalfConvergesToTheTwoSectionBeam) {
  const double t2 = 2.0 * kThickness;
  const double q1 = kDensity * kGravity * kThickness, q2 = kDensity * kGravity * t2;
  const double D1 = kRigidity, D2 = kRigidity * 8.0;  // D ∝ t³
  const double a = 0.5 * kLength;
  const double exact = two_section_deflection(q1, q2, D1, D2, a, kLength);
  // The integral's check: with one section it is the uniform strip's q L⁴ / (8 D).
  EXPECT_NEAR(two_section_deflection(q1, q1, D1, D1, a, kLength),
              q1 * std::pow(kLength, 4) / (8.0 * D1), 1e-12 * exact);
  const double weight = kDensity * kGravity * kWidth * (a * kThickness + (kLength - a) * t2);
  std::vector<double> errors;
  for (const int nx : {10, 20, 40, 80}) {
    const Cantilever c = cantilever_under_its_weight(nx, t2);
    errors.push_back(std::abs(c.deflection - exact) / exact);
    std::printf("two sections, nx = %2d: w = %.6e mm, exact %.6e mm, relative error %.2e", nx,
                c.deflection, exact, errors.back());
    if (errors.size() > 1)
      std::printf(", order %.2f", std::log2(errors[errors.size() - 2] / errors.back()));
    std::printf("; clamp reaction / weight - 1 = %.1e\n", c.reaction / weight - 1.0);
    // Each triangle weighs ρ g A_e t_e with its own thickness: the clamp holds the sum.
    EXPECT_NEAR(c.reaction / weight, 1.0, 1e-9) << "nx = " << nx;
  }
  // First order, where the uniform strip is second: the curvature jumps with D at the step, and
  // the triangles beside it read their curvature from patches across it (KL1b), which spread the
  // jump over a cell. Measured: 9.5e-3, 7.4e-3, 4.3e-3, 2.3e-3 (orders 0.36, 0.78, 0.91).
  EXPECT_LT(errors.back(), 2.5e-3);
  for (std::size_t n = 0; n + 1 < errors.size(); ++n)
    EXPECT_GT(errors[n] / errors[n + 1], 1.2) << "halving " << n;
  EXPECT_GT(std::log2(errors[errors.size() - 2] / errors.back()), 0.8) << "not first order";
}

}  // namespace
}  // namespace plisse
