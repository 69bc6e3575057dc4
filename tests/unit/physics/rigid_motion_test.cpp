// Requirement: free_rigid_motions finds exactly the rigid motions that a body's constrained
// components and supports leave free, and names them. The expected sets are worked out by hand
// for a unit cube: a symmetry plane x = 0 (u_x = 0 on it) leaves the translations along y and z
// and the turn about x; two planes leave the translation along their common line; a pinned corner
// leaves the turns about the axes through it; a fixed line the turn about that line. Each free
// motion is checked to move no held component, and each held one to be outside the set found.
#include "physics/rigid_motion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "mesh/box_mesh.hpp"
#include "mesh/shell_surface.hpp"

namespace plisse {
namespace {

const Mesh& unit_cube() {
  static const Mesh mesh = make_box_mesh({1.0, 1.0, 1.0}, {2, 2, 2});
  return mesh;
}

/// u_k = 0 at every node whose coordinate `axis` equals `value`.
void hold_plane(const Mesh& mesh, int axis, double value, int component,
                std::vector<ConstrainedComponent>& constraints) {
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (mesh.nodes[static_cast<std::size_t>(v)][axis] == value)
      constraints.push_back({v, component, 0.0, {}});
}

std::vector<std::string> names(const FreePiece& piece) {
  std::vector<std::string> out;
  for (const RigidMotion& m : piece.motions) out.push_back(m.describe());
  return out;
}

/// Every free motion leaves every held component at rest (to round-off).
void expect_moves_nothing_held(const Mesh& mesh, const FreePiece& piece,
                               const std::vector<ConstrainedComponent>& constraints) {
  for (const RigidMotion& m : piece.motions)
    for (const ConstrainedComponent& c : constraints)
      EXPECT_NEAR(m.at(mesh.nodes[static_cast<std::size_t>(c.node)])[c.component], 0.0, 1e-12)
          << m.describe() << " moves node " << c.node;
}

TEST(FreeRigidMotions, AFreeBodyMovesInAllSixWays) {
  const auto free = free_rigid_motions(unit_cube(), {}, {});
  ASSERT_EQ(free.size(), 1u);
  EXPECT_EQ(free[0].n_pieces, 1);
  EXPECT_EQ(free[0].n_elements, 48);
  EXPECT_EQ(names(free[0]), (std::vector<std::string>{"translation along x", "translation along y",
                                                      "translation along z",
                                                      "rotation about x through [0.5, 0.5, 0.5]",
                                                      "rotation about y through [0.5, 0.5, 0.5]",
                                                      "rotation about z through [0.5, 0.5, 0.5]"}));
}

TEST(FreeRigidMotions, ASymmetryPlaneHoldsOnlyTheMotionsAcrossIt) {
  std::vector<ConstrainedComponent> held;
  hold_plane(unit_cube(), 0, 0.0, 0, held);
  const auto free = free_rigid_motions(unit_cube(), held, {});
  ASSERT_EQ(free.size(), 1u);
  EXPECT_EQ(names(free[0]), (std::vector<std::string>{"translation along y", "translation along z",
                                                      "rotation about x through [0.5, 0.5, 0.5]"}));
  expect_moves_nothing_held(unit_cube(), free[0], held);
}

TEST(FreeRigidMotions, AQuarterModelSlidesAlongItsPlanesCommonLine) {
  std::vector<ConstrainedComponent> held;
  hold_plane(unit_cube(), 0, 0.0, 0, held);
  hold_plane(unit_cube(), 1, 0.0, 1, held);
  const auto free = free_rigid_motions(unit_cube(), held, {});
  ASSERT_EQ(free.size(), 1u);
  EXPECT_EQ(names(free[0]), (std::vector<std::string>{"translation along z"}));
  // Every node moves alike: the first one of the piece is named.
  EXPECT_EQ(free[0].nodes, (std::vector<int>{0}));
}

TEST(FreeRigidMotions, AnOctantIsHeld) {
  std::vector<ConstrainedComponent> held;
  for (int k = 0; k < 3; ++k) hold_plane(unit_cube(), k, 0.0, k, held);
  EXPECT_TRUE(free_rigid_motions(unit_cube(), held, {}).empty());
}

TEST(FreeRigidMotions, APinnedCornerLeavesTheTurnsAboutIt) {
  std::vector<ConstrainedComponent> held;
  for (int k = 0; k < 3; ++k) held.push_back({0, k, 0.0, {}});  // node 0 is the corner 000
  ASSERT_EQ(unit_cube().nodes[0], Vec3d::Zero());
  const auto free = free_rigid_motions(unit_cube(), held, {});
  ASSERT_EQ(free.size(), 1u);
  // Each axis through the corner, named by its point nearest the centre (0.5, 0.5, 0.5).
  EXPECT_EQ(names(free[0]), (std::vector<std::string>{"rotation about x through [0.5, 0, 0]",
                                                      "rotation about y through [0, 0.5, 0]",
                                                      "rotation about z through [0, 0, 0.5]"}));
  expect_moves_nothing_held(unit_cube(), free[0], held);
  // The node each turn moves farthest is a corner off its axis: sqrt(2) from it.
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec3d& x = unit_cube().nodes[static_cast<std::size_t>(free[0].nodes[k])];
    const Vec3d off_axis = x - x[static_cast<Eigen::Index>(k)] * Vec3d::Unit(static_cast<int>(k));
    EXPECT_NEAR(off_axis.norm(), std::sqrt(2.0), 1e-12) << k;
  }
}

TEST(FreeRigidMotions, NodesHeldOnOneLineLeaveTheTurnAboutIt) {
  // Every component of the nodes on the edge y = 0, z = 0.
  std::vector<ConstrainedComponent> held;
  const Mesh& mesh = unit_cube();
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (mesh.nodes[static_cast<std::size_t>(v)].y() == 0.0 &&
        mesh.nodes[static_cast<std::size_t>(v)].z() == 0.0)
      for (int k = 0; k < 3; ++k) held.push_back({v, k, 0.0, {}});
  const auto free = free_rigid_motions(mesh, held, {});
  ASSERT_EQ(free.size(), 1u);
  EXPECT_EQ(names(free[0]), (std::vector<std::string>{"rotation about x through [0.5, 0, 0]"}));
}

TEST(FreeRigidMotions, ADieTouchingOneFaceHoldsOnlyAlongItsNormal) {
  // A frictionless plane die under the face z = 0: each node held along z only.
  const Mesh& mesh = unit_cube();
  std::vector<RigidHold> holds;
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (mesh.nodes[static_cast<std::size_t>(v)].z() == 0.0)
      holds.push_back({{v}, mesh.nodes[static_cast<std::size_t>(v)], Vec3d::UnitZ(), false});
  auto free = free_rigid_motions(mesh, {}, holds);
  ASSERT_EQ(free.size(), 1u);
  EXPECT_EQ(names(free[0]), (std::vector<std::string>{"translation along x", "translation along y",
                                                      "rotation about z through [0.5, 0.5, 0.5]"}));
  // A cap on the top face whose turn about z is prescribed holds that turn too.
  std::vector<int> top;
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (mesh.nodes[static_cast<std::size_t>(v)].z() == 1.0) top.push_back(v);
  holds.push_back({top, Vec3d(0.5, 0.5, 1.0), Vec3d::UnitZ(), true});
  free = free_rigid_motions(mesh, {}, holds);
  ASSERT_EQ(free.size(), 1u);
  EXPECT_EQ(names(free[0]),
            (std::vector<std::string>{"translation along x", "translation along y"}));
  // A slanted direction is named by its components.
  holds.push_back({{0}, Vec3d::Zero(), Vec3d(0.6, 0.8, 0.0), false});
  free = free_rigid_motions(mesh, {}, holds);
  ASSERT_EQ(free.size(), 1u);
  ASSERT_EQ(free[0].motions.size(), 1u);
  EXPECT_EQ(free[0].motions[0].rotation, Vec3d::Zero());
  EXPECT_NEAR(std::abs(free[0].motions[0].translation.normalized().dot(Vec3d(0.8, -0.6, 0.0))), 1.0,
              1e-12);
}

/// Two unit cubes side by side, not sharing a node: [0, 1]^3 and [2, 3] x [0, 1]^2.
Mesh two_cubes() {
  Mesh mesh = make_box_mesh({1.0, 1.0, 1.0}, {1, 1, 1});
  const Mesh second = make_box_mesh({1.0, 1.0, 1.0}, {1, 1, 1});
  const int offset = mesh.n_nodes();
  for (const Vec3d& x : second.nodes) mesh.nodes.push_back(x + Vec3d(2.0, 0.0, 0.0));
  for (auto t : second.tets) {
    for (int& v : t) v += offset;
    mesh.tets.push_back(t);
  }
  return mesh;
}

TEST(FreeRigidMotions, APieceHeldByNothingIsFoundAndACapJoiningItHoldsIt) {
  const Mesh mesh = two_cubes();
  std::vector<ConstrainedComponent> held;
  for (int v = 0; v < 8; ++v)  // the first cube's nodes
    for (int k = 0; k < 3; ++k) held.push_back({v, k, 0.0, {}});
  auto free = free_rigid_motions(mesh, held, {});
  ASSERT_EQ(free.size(), 1u);
  EXPECT_EQ(free[0].n_pieces, 2);
  EXPECT_EQ(free[0].n_elements, 6);
  EXPECT_NEAR((free[0].centre - Vec3d(2.5, 0.5, 0.5)).norm(), 0.0, 1e-12);
  EXPECT_EQ(free[0].motions.size(), 6u);
  // A cap free in all six ways that ties a node of each cube makes them one piece.
  free = free_rigid_motions(mesh, held, {{{0, 8}, Vec3d::Zero(), Vec3d::Zero(), false}});
  EXPECT_TRUE(free.empty());
}

TEST(FreeRigidMotions, AShellsClampedEdgeHoldsTheTurnAboutIt) {
  // A sheet whose edge x = 0 has every position held: free to turn about it (a hinge) until the
  // edge's slope is held as well (Mesh::side_mirrors of a clamped edge).
  Mesh mesh = make_rectangle_surface(2.0, 1.0, 0.0, {4, 2});
  make_shell_surface(mesh, 0.01);
  std::vector<ConstrainedComponent> held;
  hold_plane(mesh, 0, 0.0, 0, held);
  hold_plane(mesh, 0, 0.0, 1, held);
  hold_plane(mesh, 0, 0.0, 2, held);
  auto free = free_rigid_motions(mesh, held, {});
  ASSERT_EQ(free.size(), 1u);
  EXPECT_EQ(names(free[0]), (std::vector<std::string>{"rotation about y through [0, 0.5, 0]"}));
  clamp_sides(mesh, mesh.edge_tags.at("left"));
  EXPECT_TRUE(free_rigid_motions(mesh, held, {}).empty());
}

TEST(FreeRigidMotions, AShellsSymmetryEdgeLeavesTheTurnAboutItsNormal) {
  // The sheet's edge x = 0 on a mirror plane: u_x = 0 there and the slope mirrored. Free: the
  // translations along y and z and the turn about x, as for a solid's symmetry plane.
  Mesh mesh = make_rectangle_surface(2.0, 1.0, 0.0, {4, 2});
  make_shell_surface(mesh, 0.01);
  std::vector<ConstrainedComponent> held;
  hold_plane(mesh, 0, 0.0, 0, held);
  mirror_sides(mesh, mesh.edge_tags.at("left"), 0, 0.0);
  const auto free = free_rigid_motions(mesh, held, {});
  ASSERT_EQ(free.size(), 1u);
  EXPECT_EQ(names(free[0]), (std::vector<std::string>{"translation along y", "translation along z",
                                                      "rotation about x through [1, 0.5, 0]"}));
}

}  // namespace
}  // namespace plisse
