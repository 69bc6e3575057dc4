#pragma once
/// Triangulated mid-surfaces of spheres for the shell tests: the faces of the octahedron, each
/// cut into n² triangles and projected onto the sphere (no tetrahedra; make_shell_surface adds
/// the thickness and the neighbour table).
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/shell_surface.hpp"

namespace plisse::test {

/// The sphere of radius R [mm] centred at the origin, or only its octant x, y, z >= 0
/// (`octant`), from the octahedron's faces cut into n × n triangles each, projected radially;
/// triangles oriented with the outward normal, thickness t [mm]. The octant's cut sides lie in
/// the planes x = 0, y = 0, z = 0. Surface tag "all": every triangle.
inline Mesh octahedral_sphere(double R, double t, int n, bool octant) {
  Mesh mesh;
  std::map<std::array<int, 3>, int> index;  // integer grid point -> node
  const auto node = [&](const std::array<int, 3>& key) {
    const auto [it, added] = index.emplace(key, mesh.n_nodes());
    if (added)
      mesh.nodes.push_back(R * Vec3d(double(key[0]), double(key[1]), double(key[2])).normalized());
    return it->second;
  };
  for (int face = 0; face < (octant ? 1 : 8); ++face) {
    const int sx = face & 1 ? -1 : 1, sy = face & 2 ? -1 : 1, sz = face & 4 ? -1 : 1;
    // Grid point (i, j) of the face: (sx (n - i - j), sy i, sz j). (B - A) × (C - A) points
    // outward when sx sy sz > 0; else the triangles are turned.
    const auto point = [&](int i, int j) { return node({sx * (n - i - j), sy * i, sz * j}); };
    const bool turn = sx * sy * sz < 0;
    const auto add = [&](int a, int b, int c) {
      mesh.triangles.push_back(turn ? std::array<int, 3>{a, c, b} : std::array<int, 3>{a, b, c});
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        add(point(i, j), point(i + 1, j), point(i, j + 1));
        if (i + j + 1 < n) add(point(i + 1, j), point(i + 1, j + 1), point(i, j + 1));
      }
  }
  std::vector<int>& all = mesh.surface_tags["all"];
  for (int k = 0; k < static_cast<int>(mesh.triangles.size()); ++k) all.push_back(k);
  make_shell_surface(mesh, t);
  return mesh;
}

/// A flat square of side n mm centred at the origin in the plane through it with normal Q e3, in
/// 2 n² triangles (diagonals alternating), thickness t [mm]; node (i, j), at Q (i - n/2, j - n/2,
/// 0), is node j (n + 1) + i. Surface tag "all": every triangle.
inline Mesh flat_square(const Mat3d& Q, int n, double t) {
  Mesh mesh;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh.nodes.push_back(Q * Vec3d(i - 0.5 * n, j - 0.5 * n, 0.0));
  const auto node = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if ((i + j) % 2 == 0) {
        mesh.triangles.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1)});
        mesh.triangles.push_back({node(i, j), node(i + 1, j + 1), node(i, j + 1)});
      } else {
        mesh.triangles.push_back({node(i, j), node(i + 1, j), node(i, j + 1)});
        mesh.triangles.push_back({node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});
      }
    }
  std::vector<int>& all = mesh.surface_tags["all"];
  for (int k = 0; k < static_cast<int>(mesh.triangles.size()); ++k) all.push_back(k);
  make_shell_surface(mesh, t);
  return mesh;
}

/// Moves every node of `mesh` by up to `amount` [mm] in each direction (reproducible from
/// `seed`).
inline void jitter_nodes(Mesh& mesh, double amount, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (Vec3d& x : mesh.nodes) x += amount * Vec3d(unit(rng), unit(rng), unit(rng));
}

}  // namespace plisse::test
