// The pieces of a distributed run that can be checked in one process: the node partition
// (solver/partition.hpp) and the equation numbering by a node order (solver/dof_map.hpp).
#include "solver/partition.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <algorithm>
#include <vector>

#include "solver/dof_map.hpp"

namespace plisse {
namespace {

/// The graph of an nx x ny grid of vertices (4-neighbours plus self loops), CSR.
struct Graph {
  std::vector<int> start{0}, adjacency;
};
Graph grid(int nx, int ny) {
  Graph g;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int v = j * nx + i;
      g.adjacency.push_back(v);  // self loops are ignored by the partitioner
      if (i > 0) g.adjacency.push_back(v - 1);
      if (i + 1 < nx) g.adjacency.push_back(v + 1);
      if (j > 0) g.adjacency.push_back(v - nx);
      if (j + 1 < ny) g.adjacency.push_back(v + nx);
      g.start.push_back(static_cast<int>(g.adjacency.size()));
    }
  return g;
}

TEST(PartitionGraph, BalancedPartsWithAShortCut) {
  const int nx = 40, ny = 40, n = nx * ny;
  const Graph g = grid(nx, ny);
  for (int parts : {2, 3, 4}) {
    const std::vector<int> part =
        partition_graph(g.start, g.adjacency, std::vector<int>(n, 1), parts, PETSC_COMM_SELF);
    ASSERT_EQ(part.size(), static_cast<std::size_t>(n));
    std::vector<int> size(parts, 0);
    for (int p : part) {
      ASSERT_GE(p, 0);
      ASSERT_LT(p, parts);
      ++size[p];
    }
    // Balance within 5 % of the mean (PT-Scotch's default imbalance is 1 %).
    for (int s : size) EXPECT_NEAR(s, double(n) / parts, 0.05 * n / parts) << parts << " parts";
    // Cut edges: a straight cut across the 40 x 40 grid costs 40 edges per cut; a good
    // partitioner stays within twice the cuts of straight lines.
    int cut = 0;
    for (int v = 0; v < n; ++v)
      for (int k = g.start[v]; k < g.start[v + 1]; ++k) cut += part[g.adjacency[k]] != part[v];
    EXPECT_LE(cut / 2, 2 * 40 * (parts - 1)) << parts << " parts";
  }
}

TEST(PartitionGraph, WeightsAreBalancedNotVertexCounts) {
  // Left half of the grid weighs 3 per vertex, right half 1: the part boundaries move left.
  const int nx = 40, ny = 20, n = nx * ny;
  const Graph g = grid(nx, ny);
  std::vector<int> weight(n);
  for (int v = 0; v < n; ++v) weight[v] = v % nx < nx / 2 ? 3 : 1;
  const std::vector<int> part = partition_graph(g.start, g.adjacency, weight, 2, PETSC_COMM_SELF);
  double w[2] = {0, 0};
  for (int v = 0; v < n; ++v) w[part[v]] += weight[v];
  EXPECT_NEAR(w[0], w[1], 0.05 * (w[0] + w[1]));
}

TEST(PartitionGraph, OnePartNeedsNoPartitioner) {
  const Graph g = grid(3, 3);
  EXPECT_EQ(partition_graph(g.start, g.adjacency, std::vector<int>(9, 1), 1, PETSC_COMM_SELF),
            std::vector<int>(9, 0));
}

TEST(DofMapNodeOrder, NumbersNodesInTheGivenOrderThenTheGlobalUnknowns) {
  // 3 nodes, node 1 has ux constrained; order 2, 0, 1; one global unknown.
  std::vector<ConstrainedComponent> constrained(1);
  constrained[0].node = 1;
  constrained[0].component = 0;
  const DofMap dofs(3, 1, constrained, {2, 0, 1});
  const auto eq = [&](int node, int comp) { return dofs.equation(DofMap::dof(node, comp)); };
  for (int k = 0; k < 4; ++k) EXPECT_EQ(eq(2, k), k);      // node 2 first
  for (int k = 0; k < 4; ++k) EXPECT_EQ(eq(0, k), 4 + k);  // then node 0
  EXPECT_EQ(eq(1, 0), -1);                                 // constrained
  EXPECT_EQ(eq(1, 1), 8);
  EXPECT_EQ(eq(1, 3), 10);
  EXPECT_EQ(dofs.equation(dofs.global_dof(0)), 11);  // global unknowns last
  EXPECT_EQ(dofs.n_free(), 12);
  EXPECT_EQ(dofs.n_free_pressure(), 3);
  // The identity order is the default numbering.
  const DofMap plain(3, 1, constrained), identity(3, 1, constrained, {0, 1, 2});
  EXPECT_EQ(plain.equations(), identity.equations());
}

TEST(DofMapNodeOrder, RefusesAnOrderThatIsNotAPermutation) {
  EXPECT_THROW(DofMap(3, 0, {}, {0, 1}), Error);
  EXPECT_THROW(DofMap(3, 0, {}, {0, 1, 1}), Error);
  EXPECT_THROW(DofMap(3, 0, {}, {0, 1, 3}), Error);
}

}  // namespace
}  // namespace plisse
