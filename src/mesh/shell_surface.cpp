#include "mesh/shell_surface.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/error.hpp"

namespace plisse {

void make_shell_surface(Mesh& mesh, double thickness) {
  PLISSE_CHECK(mesh.tets.empty(), "a shell mesh has no tetrahedra, this one has " << mesh.n_tets());
  PLISSE_CHECK(!mesh.triangles.empty(), "a shell mesh needs triangles, this one has none");
  PLISSE_CHECK(std::isfinite(thickness) && thickness > 0.0,
               "shell thickness " << thickness << " mm, must be > 0");
  const int n_triangles = static_cast<int>(mesh.triangles.size());
  // Each directed side (a, b) of a triangle, with the triangle and the corner opposite it.
  struct Side {
    int triangle;
    int side;
  };
  std::map<std::pair<int, int>, Side> sides;
  for (int t = 0; t < n_triangles; ++t) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
    for (int v : tri)
      PLISSE_CHECK(v >= 0 && v < mesh.n_nodes(),
                   "shell triangle " << t << " names node " << v << " of " << mesh.n_nodes());
    PLISSE_CHECK(tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0],
                 "shell triangle " << t << " repeats a node");
    for (int i = 0; i < 3; ++i) {
      // Side i joins corners i + 1 and i + 2 (KL1).
      const int a = tri[(i + 1) % 3], b = tri[(i + 2) % 3];
      PLISSE_CHECK(sides.emplace(std::make_pair(a, b), Side{t, i}).second,
                   "shell triangles " << sides.at({a, b}).triangle << " and " << t
                                      << " both run from node " << a << " to node " << b
                                      << ": an edge of more than two triangles, or two "
                                         "triangles oriented inconsistently");
    }
  }
  mesh.triangle_neighbours.assign(mesh.triangles.size(), {-1, -1, -1});
  for (const auto& [edge, here] : sides) {
    const auto across = sides.find({edge.second, edge.first});
    if (across == sides.end()) continue;  // an edge of the surface
    const Side there = across->second;
    mesh.triangle_neighbours[static_cast<std::size_t>(here.triangle)][here.side] =
        mesh.triangles[static_cast<std::size_t>(there.triangle)][there.side];
  }
  mesh.shell_thickness.assign(mesh.nodes.size(), thickness);
}

}  // namespace plisse
