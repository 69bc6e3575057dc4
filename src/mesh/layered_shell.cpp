#include "mesh/layered_shell.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "mesh/boundary_tags.hpp"
#include "mesh/second_order.hpp"

namespace plisse {

std::array<bool, 3> cut_planes(Symmetry symmetry) {
  switch (symmetry) {
    case Symmetry::full:
      return {false, false, false};
    case Symmetry::half:
      return {false, false, true};
    case Symmetry::quarter:
      return {true, false, true};
    case Symmetry::octant:
      return {true, true, true};
  }
  return {false, false, false};
}

Mesh make_layered_shell(
    const SurfaceTriangulation& surface, int layers, Symmetry symmetry,
    const std::function<Vec3d(int node, int layer)>& position,
    const std::function<Vec3d(int node1, int layer1, int node2, int layer2)>& midpoint) {
  PLISSE_CHECK(layers >= 1, "make_layered_shell: layers must be >= 1");
  const int n = static_cast<int>(surface.nodes.size());
  Mesh mesh;
  mesh.nodes.reserve(static_cast<std::size_t>(n * (layers + 1)));
  for (int j = 0; j <= layers; ++j)
    for (int k = 0; k < n; ++k) mesh.nodes.push_back(position(k, j));
  mesh.tets.reserve(3 * surface.triangles.size() * static_cast<std::size_t>(layers));
  for (int j = 0; j < layers; ++j)
    for (auto tri : surface.triangles) {
      std::sort(tri.begin(), tri.end());
      const int a = tri[0], b = tri[1], c = tri[2];
      const int lo = j * n, hi = (j + 1) * n;
      mesh.tets.push_back({lo + a, lo + b, lo + c, hi + c});
      mesh.tets.push_back({lo + a, lo + b, hi + b, hi + c});
      mesh.tets.push_back({lo + a, hi + a, hi + b, hi + c});
    }
  orient_generated_tets(mesh, "layered shell");

  const auto planes = cut_planes(symmetry);
  const std::vector<std::vector<std::string>> side_tags = {
      {"inner"}, {"outer"}, {"sym_x"}, {"sym_y"}, {"sym_z"}};
  tag_boundary(mesh, side_tags, [&](const BoundaryFace& f) {
    auto layer = [&](int node) { return node / n; };
    if (layer(f.nodes[0]) == 0 && layer(f.nodes[1]) == 0 && layer(f.nodes[2]) == 0) return 0;
    if (layer(f.nodes[0]) == layers && layer(f.nodes[1]) == layers && layer(f.nodes[2]) == layers)
      return 1;
    for (int axis = 0; axis < 3; ++axis) {
      if (!planes[static_cast<std::size_t>(axis)]) continue;
      const bool on_plane = std::all_of(f.nodes.begin(), f.nodes.end(), [&](int node) {
        return mesh.nodes[static_cast<std::size_t>(node)][axis] == 0.0;
      });
      if (on_plane) return 2 + axis;
    }
    return -1;
  });
  // Symmetry tags of planes the symmetry does not cut would be empty: drop them.
  for (int axis = 0; axis < 3; ++axis)
    if (!planes[static_cast<std::size_t>(axis)])
      mesh.surface_tags.erase(side_tags[static_cast<std::size_t>(2 + axis)][0]);
  if (midpoint) {
    add_edge_nodes(mesh, [&](int a, int b) {
      Vec3d x = midpoint(a % n, a / n, b % n, b / n);
      for (int axis = 0; axis < 3; ++axis)
        if (planes[static_cast<std::size_t>(axis)] &&
            mesh.nodes[static_cast<std::size_t>(a)][axis] == 0.0 &&
            mesh.nodes[static_cast<std::size_t>(b)][axis] == 0.0) {
          PLISSE_CHECK(std::abs(x[axis]) <= 1e-9 * x.norm(),
                       "layered shell: the edge node between two nodes on a cut plane is off it");
          x[axis] = 0.0;
        }
      return x;
    });
  }
  return mesh;
}

}  // namespace plisse
