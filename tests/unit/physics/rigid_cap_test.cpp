// Rigid cap (docs/theory/caps.md, G4-G7): the tangent is the derivative of the residual and
// symmetric, with every motion free or some prescribed; components a boundary condition already
// prescribes are not tied; the couplings cover every tangent entry.
#include "physics/rigid_cap.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/box_mesh.hpp"
#include "mesh/topology.hpp"
#include "support/term_testing.hpp"

namespace plisse {
namespace {

using test::DenseSink;
using test::random_state;
using test::term_residual;

struct CapSetup {
  Mesh mesh;
  std::unique_ptr<RigidCap> cap;
  int n = 0;  ///< full-state size
};

CapSetup make_cap(bool all_free, const std::vector<ConstrainedComponent>& constraints = {}) {
  CapSetup s;
  s.mesh = make_box_mesh({2.0, 2.0, 1.0}, {2, 2, 1}, 2);
  Cap settings;
  settings.name = "cap";
  settings.surface = {"top", {}};
  settings.point = Vec3d(1.0, 0.8, 1.1);
  settings.force = Vec3d(0.3, -0.2, 0.1);
  settings.moment = Vec3d(-0.4, 0.25, 0.6);
  settings.ramp = {0.0, 2.0};
  if (!all_free) {
    settings.displacement = {std::nullopt, 0.2, std::nullopt};
    settings.rotation = {0.3, std::nullopt, -0.1};
    settings.force.y() = 0.0;
    settings.moment.x() = settings.moment.z() = 0.0;
  }
  s.cap = std::make_unique<RigidCap>(settings, s.mesh, constraints);
  s.cap->set_first_global_dof(kValuesPerNode * s.mesh.n_nodes());
  s.n = kValuesPerNode * s.mesh.n_nodes() + s.cap->n_global_unknowns();
  return s;
}

void expect_tangent_is_derivative(CapSetup& s) {
  auto x = random_state(s.n, 17, 0.2);
  for (int k = kValuesPerNode * s.mesh.n_nodes(); k < s.n; ++k) x[k] *= 5.0;  // λ, θ of O(1)
  DenseSink sink(s.n);
  std::vector<double> r(s.n, 0.0);
  s.cap->assemble(1.0, x, r, &sink);
  const double h = 1e-6, scale = sink.K.cwiseAbs().maxCoeff();
  const double max_error = test::max_tangent_error(*s.cap, 1.0, x, sink.K, h);
  EXPECT_LT(max_error, 1e-8 * scale);
  EXPECT_LT((sink.K - sink.K.transpose()).cwiseAbs().maxCoeff(), 1e-14 * scale);
  // Every non-zero entry is among the declared couplings or in the nodal block.
  std::vector<std::pair<int, int>> pairs;
  s.cap->add_couplings(pairs);
  const std::set<std::pair<int, int>> declared(pairs.begin(), pairs.end());
  const int nodal = kValuesPerNode * s.mesh.n_nodes();
  for (int i = 0; i < s.n; ++i)
    for (int j = 0; j < s.n; ++j)
      if (sink.K(i, j) != 0.0 && (i >= nodal || j >= nodal)) {
        EXPECT_TRUE(declared.count({i, j})) << "entry " << i << ", " << j;
      }
}

TEST(RigidCap, TangentIsTheSymmetricDerivativeWithEveryMotionFree) {
  CapSetup s = make_cap(true);
  EXPECT_EQ(s.cap->n_global_unknowns(), s.cap->n_ties() + 6);
  expect_tangent_is_derivative(s);
}

TEST(RigidCap, TangentIsTheSymmetricDerivativeWithSomeMotionsPrescribed) {
  CapSetup s = make_cap(false);
  EXPECT_EQ(s.cap->n_global_unknowns(), s.cap->n_ties() + 3);
  expect_tangent_is_derivative(s);
  // Prescribed motions follow the ramp: half-way at t = 1.
  const std::vector<double> x(s.n, 0.0);
  const auto q = s.cap->motion(1.0, x);
  EXPECT_DOUBLE_EQ(q[1], 0.1);
  EXPECT_DOUBLE_EQ(q[3], 0.15);
  EXPECT_DOUBLE_EQ(q[5], -0.05);
}

// A Newton iterate that turns the cap past 2 pi (a step beyond a limit load) ends the step with a
// reason that names the cap and the divergence; 6 rad is still within the rotation's range.
TEST(RigidCap, ANewtonIterateTurningTheCapPastTwoPiNamesTheCap) {
  CapSetup s = make_cap(true);
  std::vector<double> x(s.n, 0.0), r(s.n, 0.0);
  x[s.n - 3] = 6.0;  // θ_x, the first of the last three free motions
  EXPECT_NO_THROW(s.cap->assemble(1.0, x, r, nullptr));
  x[s.n - 3] = 59.0;
  try {
    s.cap->assemble(1.0, x, r, nullptr);
    ADD_FAILURE() << "a turn of 59 rad was assembled";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "the Newton iterations diverged: they turned cap 'cap' by 59 rad, more than the "
              "2 pi a rotation vector describes");
  }
}

TEST(RigidCap, ComponentsPrescribedByABoundaryConditionAreNotTied) {
  const Mesh mesh = make_box_mesh({2.0, 2.0, 1.0}, {2, 2, 1}, 2);
  const std::set<int> nodes = triangle_nodes(mesh, mesh.surface_tags.at("top"));
  const int first = *nodes.begin();
  const CapSetup s = make_cap(true, {{first, 2, 0.0, {}}});
  EXPECT_EQ(s.cap->n_ties(), 3 * static_cast<int>(nodes.size()) - 1);
  EXPECT_EQ(s.cap->negative_directions(), s.cap->n_ties());
  Cap settings;
  settings.surface = {"top", {}};
  std::vector<ConstrainedComponent> all;
  for (int v : nodes)
    for (int i = 0; i < 3; ++i) all.push_back({v, i, 0.0, {}});
  EXPECT_THROW(RigidCap(settings, mesh, all), InputError);
}

}  // namespace
}  // namespace plisse
