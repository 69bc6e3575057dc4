#include "mesh/second_order.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/error.hpp"
#include "mesh/topology.hpp"

namespace plisse {
namespace {

/// The edge (a, b) as one sortable number: min(a, b) in the high half, max(a, b) in the low half.
std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::min(a, b)));
  const auto hi = static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::max(a, b)));
  return (lo << 32) | hi;
}

}  // namespace

void add_edge_nodes(Mesh& mesh, const std::function<Vec3d(int a, int b)>& midpoint) {
  PLISSE_CHECK(mesh.order() == 1 && mesh.triangle_edge_nodes.empty(),
               "add_edge_nodes: the mesh is already second order");
  std::vector<std::uint64_t> edges;
  edges.reserve(6 * mesh.tets.size());
  for (const auto& tet : mesh.tets)
    for (const auto& e : kTetEdges)
      edges.push_back(
          edge_key(tet[static_cast<std::size_t>(e[0])], tet[static_cast<std::size_t>(e[1])]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

  const int first = mesh.n_nodes();
  auto node_of = [&](int a, int b) {
    const std::uint64_t key = edge_key(a, b);
    const auto it = std::lower_bound(edges.begin(), edges.end(), key);
    PLISSE_CHECK(it != edges.end() && *it == key,
                 "add_edge_nodes: edge (" << a << ", " << b << ") is no tetrahedron edge");
    return first + static_cast<int>(it - edges.begin());
  };

  mesh.nodes.reserve(mesh.nodes.size() + edges.size());
  for (const std::uint64_t key : edges)
    mesh.nodes.push_back(
        midpoint(static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffULL)));
  mesh.tet_edge_nodes.reserve(mesh.tets.size());
  for (const auto& tet : mesh.tets) {
    std::array<int, 6> nodes{};
    for (std::size_t e = 0; e < 6; ++e)
      nodes[e] = node_of(tet[static_cast<std::size_t>(kTetEdges[e][0])],
                         tet[static_cast<std::size_t>(kTetEdges[e][1])]);
    mesh.tet_edge_nodes.push_back(nodes);
  }
  mesh.triangle_edge_nodes.reserve(mesh.triangles.size());
  for (const auto& tri : mesh.triangles)
    mesh.triangle_edge_nodes.push_back(
        {node_of(tri[0], tri[1]), node_of(tri[1], tri[2]), node_of(tri[2], tri[0])});
}

void add_straight_edge_nodes(Mesh& mesh) {
  add_edge_nodes(mesh, [&mesh](int a, int b) {
    return Vec3d(
        0.5 * (mesh.nodes[static_cast<std::size_t>(a)] + mesh.nodes[static_cast<std::size_t>(b)]));
  });
}

}  // namespace plisse
