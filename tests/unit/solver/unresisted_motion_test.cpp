// Requirement: unresisted_rigid_motion finds a rigid motion that the assembled tangent does not
// resist, and none where every one is resisted. A neo-Hookean cube held across the planes x = 0
// and y = 0 (u_x = 0, u_y = 0 there) slides freely along z, and only so: the tangent's null space
// over the free unknowns is that translation (worked out by hand: the planes hold the other two
// translations and the three turns). Held across z = 0 as well, nothing is free. The model's
// state is the same after the search.
#include "solver/unresisted_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "material/registry.hpp"
#include "mesh/box_mesh.hpp"
#include "solver/petsc_session.hpp"

namespace plisse {
namespace {

std::vector<ConstrainedComponent> planes(const Mesh& mesh, int n_axes) {
  std::vector<ConstrainedComponent> held;
  for (int k = 0; k < n_axes; ++k)
    for (int v = 0; v < mesh.n_nodes(); ++v)
      if (mesh.nodes[static_cast<std::size_t>(v)][k] == 0.0) held.push_back({v, k, 0.0, {}});
  return held;
}

TEST(UnresistedRigidMotion, AQuarterCubeSlidesAlongZAndAnOctantNowhere) {
  const Mesh mesh = make_box_mesh(Vec3d(1.0, 1.0, 1.0), {2, 2, 2});
  {
    MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 0.0, planes(mesh, 2));
    const std::vector<double> before = model.state();
    const std::string found = unresisted_rigid_motion(model);
    EXPECT_NE(found.find("the body of 48 tetrahedra (centred near [0.5, 0.5, 0.5]) can still "
                         "move as a rigid body by translation along z"),
              std::string::npos)
        << found;
    EXPECT_EQ(model.state(), before);
  }
  {
    MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 0.0, planes(mesh, 3));
    EXPECT_EQ(unresisted_rigid_motion(model), "");
  }
}

TEST(UnresistedRigidMotion, AStretchedOctantResistsEveryMotion) {
  // Pre-stressed: stretched 1.2 along z and 1/sqrt(1.2) across (isochoric), held across the
  // three planes.
  const Mesh mesh = make_box_mesh(Vec3d(1.0, 1.0, 1.0), {2, 2, 2});
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 0.0, planes(mesh, 3));
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d& X = mesh.nodes[static_cast<std::size_t>(v)];
    model.state()[static_cast<std::size_t>(node_dof(v, 2))] = 0.2 * X.z();
    model.state()[static_cast<std::size_t>(node_dof(v, 0))] = (1.0 / std::sqrt(1.2) - 1.0) * X.x();
    model.state()[static_cast<std::size_t>(node_dof(v, 1))] = (1.0 / std::sqrt(1.2) - 1.0) * X.y();
  }
  EXPECT_EQ(unresisted_rigid_motion(model), "");
}

}  // namespace
}  // namespace plisse
