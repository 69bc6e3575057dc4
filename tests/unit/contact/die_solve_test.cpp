// A block pressed by a frictionless plane die, solved with the real load stepper: the multiplier
// updates bring the penetration below the tolerance that the penalty alone misses, and the die
// force balances the reaction of the fixed bottom (docs/theory/contact.md, D9-D10, D15).
#include <gtest/gtest.h>

#include <set>

#include "mesh/generate.hpp"
#include "physics/die_contact.hpp"
#include "physics/surface.hpp"
#include "solver/load_stepper.hpp"

namespace plisse {
namespace {

struct BlockRun {
  bool completed = false;
  std::vector<double> violation, die_force, bottom_reaction;
};

/// Unit cube (neo-Hookean, mu = 1 MPa, exactly incompressible), bottom fixed, a frictionless plane
/// die touching the top at t = 0 and moving 0.1 mm down, penalty 30 MPa/mm (= 10 mu / h).
BlockRun press_block(double tolerance) {
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.edge = 1.0;
  spec.divisions = 3;
  const Mesh mesh = generate_mesh(spec);
  std::vector<ConstrainedComponent> constraints;
  for (int v : surface_nodes(outward_faces(mesh, "bottom")))
    for (int k = 0; k < 3; ++k) constraints.push_back({v, k, 0.0, Ramp{0.0, 1.0}});
  DieContactSettings settings;
  settings.name = "punch";
  settings.penalty = 30.0;
  settings.tolerance = tolerance;
  std::vector<std::unique_ptr<ModelTerm>> terms;
  terms.push_back(std::make_unique<DieContact>(
      mesh,
      DieGeometry(DieShape::plane, Vec3d(0, 0, 1), Vec3d(0, 0, -1), Vec3d::UnitZ(), 0.0,
                  Vec3d(0, 0, -0.1), Ramp{0.0, 1.0}),
      settings, outward_triangles(mesh, "top")));
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 0.0, constraints,
                   std::move(terms));
  SteppingSettings solver;
  solver.steps = 4;
  solver.max_step = 0.25;
  solver.newton.rtol = 1e-10;
  solver.newton.atol = 1e-12;
  LoadStepper stepper(model, solver);
  BlockRun out;
  const auto& die = dynamic_cast<const DieContact&>(*model.terms().front());
  const SteppingResult result = stepper.run(
      [&](const StepInfo& info) {
        out.violation.push_back(die.violation(info.time, model.state()));
        out.die_force.push_back(die.force_on_die(info.time, model.state()).z());
        out.bottom_reaction.push_back(model.reaction(mesh.surface_tags.at("bottom")).z());
      },
      [](const std::string&) {});
  out.completed = result.completed;
  return out;
}

TEST(DieContactSolve, MultipliersBringThePenetrationBelowTheTolerance) {
  const BlockRun penalty_only = press_block(1.0);  // tolerance never binding: no updates
  const BlockRun augmented = press_block(1e-5);
  ASSERT_TRUE(penalty_only.completed);
  ASSERT_TRUE(augmented.completed);
  // The penalty alone leaves ~ contact pressure / eps = O(1e-3) mm.
  EXPECT_GT(penalty_only.violation.back(), 1e-4);
  for (size_t s = 0; s < augmented.violation.size(); ++s) {
    EXPECT_LE(augmented.violation[s], 1e-5) << "step " << s + 1;
    // Equilibrium: the body pushes the die up with the force the fixed bottom carries
    // (Newton tolerance 1e-10 relative on the residual).
    EXPECT_NEAR(augmented.die_force[s], augmented.bottom_reaction[s],
                1e-7 * std::abs(augmented.die_force[s]))
        << "step " << s + 1;
    EXPECT_GT(augmented.die_force[s], 0.0);
  }
  // Stiffer enforcement only adds force (the block is squeezed by the full 0.1 mm).
  EXPECT_GT(augmented.die_force.back(), penalty_only.die_force.back());
}

}  // namespace
}  // namespace plisse
