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

/// The cantilever strip of nx cells along L (nx / 5 across, at least 2) under its own weight.
Cantilever cantilever_under_its_weight(int nx) {
  Mesh mesh = shell_test::strip_mesh(kLength, kWidth, kThickness, nx, std::max(2, nx / 5),
                                     shell_test::Cells::same_diagonal, kLength);
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

}  // namespace
}  // namespace plisse
