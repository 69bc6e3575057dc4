// The pressure twins of regions that meet (solver/pressure_twins.hpp, docs/theory/regions.md
// BL3): which corner nodes get one, for which region, and which node each element's corner then
// takes its pressure from. Small hand-built meshes, the expected numbers worked out beside them.
#include "solver/pressure_twins.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace plisse {
namespace {

// Two tetrahedra sharing the face (1, 2, 3): nodes 0..4. Region 0 keeps the shared nodes' own
// values; region 1 gets a twin at each of 1, 2, 3: nodes 5, 6, 7 in node order.
TEST(PressureTwins, TwoRegionsThroughAFace) {
  const std::vector<std::array<int, 4>> corners = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  const PressureTwins twins = make_pressure_twins(5, corners, {0, 1});
  ASSERT_EQ(twins.n_twins(), 3);
  EXPECT_EQ(twins.n_nodes, 8);
  EXPECT_EQ(twins.corner, (std::vector<int>{1, 2, 3}));
  for (int a = 0; a < 4; ++a) EXPECT_EQ(twins.carrier_of(0, a, corners[0][a]), corners[0][a]);
  EXPECT_EQ(twins.carrier_of(1, 0, 1), 5);
  EXPECT_EQ(twins.carrier_of(1, 1, 2), 6);
  EXPECT_EQ(twins.carrier_of(1, 2, 3), 7);
  EXPECT_EQ(twins.carrier_of(1, 3, 4), 4) << "node 4 is region 1's alone";
}

// The smallest region at a node keeps its value whatever the element order: the same two
// tetrahedra with the regions swapped give the twins to the first one.
TEST(PressureTwins, TheSmallestRegionKeepsTheNodesOwnValue) {
  const std::vector<std::array<int, 4>> corners = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  const PressureTwins twins = make_pressure_twins(5, corners, {2, 0});
  ASSERT_EQ(twins.n_twins(), 3);
  EXPECT_EQ(twins.carrier_of(0, 1, 1), 5);
  EXPECT_EQ(twins.carrier_of(0, 0, 0), 0);
  for (int a = 0; a < 4; ++a) EXPECT_EQ(twins.carrier_of(1, a, corners[1][a]), corners[1][a]);
}

// Three regions around node 0 (three tetrahedra sharing it, and pairwise an edge): node 0 gets
// two twins (regions 1 and 2), and each shared edge's other node one; a fourth element of region
// 0 at node 0 adds nothing. Σ_v (m_v - 1) = 2 + 1 + 1 + 1 = 5 twins.
TEST(PressureTwins, ThreeRegionsAtANodeGiveItTwoTwins) {
  const std::vector<std::array<int, 4>> corners = {
      {0, 1, 2, 7}, {0, 2, 3, 8}, {0, 3, 1, 9}, {0, 4, 5, 6}};
  const PressureTwins twins = make_pressure_twins(10, corners, {0, 1, 2, 0});
  EXPECT_EQ(twins.n_twins(), 5);
  // Node 0: regions {0, 1, 2} -> twins 10 (region 1), 11 (region 2); node 1: {0, 2} -> 12;
  // node 2: {0, 1} -> 13; node 3: {1, 2} -> 14 (region 2; region 1 keeps node 3).
  EXPECT_EQ(twins.corner, (std::vector<int>{0, 0, 1, 2, 3}));
  EXPECT_EQ(twins.carrier_of(1, 0, 0), 10);
  EXPECT_EQ(twins.carrier_of(2, 0, 0), 11);
  EXPECT_EQ(twins.carrier_of(2, 2, 1), 12);
  EXPECT_EQ(twins.carrier_of(1, 1, 2), 13);
  EXPECT_EQ(twins.carrier_of(1, 2, 3), 3);
  EXPECT_EQ(twins.carrier_of(2, 1, 3), 14);
  EXPECT_EQ(twins.carrier_of(3, 0, 0), 0);
}

// A rigid element (region -1) takes no pressure: a node it shares with one deformable region
// gets no twin, and no region at all gives no twins and no carriers.
TEST(PressureTwins, RigidElementsAndOneRegionGiveNone) {
  const std::vector<std::array<int, 4>> corners = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  PressureTwins twins = make_pressure_twins(5, corners, {0, -1});
  EXPECT_EQ(twins.n_twins(), 0);
  EXPECT_TRUE(twins.carrier.empty());
  EXPECT_EQ(twins.n_nodes, 5);
  twins = make_pressure_twins(5, corners, {3, 3});
  EXPECT_EQ(twins.n_twins(), 0);
  twins = make_pressure_twins(5, corners, {});
  EXPECT_EQ(twins.n_twins(), 0);
  EXPECT_EQ(twins.carrier_of(1, 2, 3), 3);
}

}  // namespace
}  // namespace plisse
