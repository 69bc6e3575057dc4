#include "mesh/shell_surface.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
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
  mesh.triangle_adjacent.assign(mesh.triangles.size(), {-1, -1, -1});
  for (const auto& [edge, here] : sides) {
    const auto across = sides.find({edge.second, edge.first});
    if (across == sides.end()) continue;  // an edge of the surface
    const Side there = across->second;
    mesh.triangle_neighbours[static_cast<std::size_t>(here.triangle)][here.side] =
        mesh.triangles[static_cast<std::size_t>(there.triangle)][there.side];
    mesh.triangle_adjacent[static_cast<std::size_t>(here.triangle)][here.side] = there.triangle;
  }
  mesh.triangle_thickness.assign(mesh.triangles.size(), thickness);
  mesh.shell_thickness.assign(mesh.nodes.size(), thickness);
}

void set_shell_thickness(Mesh& mesh, const std::vector<int>& triangles, double thickness) {
  PLISSE_CHECK(mesh.is_shell() && mesh.triangle_thickness.size() == mesh.triangles.size(),
               "set_shell_thickness needs the mid-surface of a shell (make_shell_surface)");
  PLISSE_CHECK(thickness > 0.0 && std::isfinite(thickness),
               "a shell's thickness must be positive, got " << thickness);
  for (const int t : triangles) {
    PLISSE_CHECK(t >= 0 && static_cast<std::size_t>(t) < mesh.triangles.size(),
                 "triangle " << t << " out of range (" << mesh.triangles.size() << " triangles)");
    mesh.triangle_thickness[static_cast<std::size_t>(t)] = thickness;
  }
  std::vector<double> sum(mesh.nodes.size(), 0.0);
  std::vector<int> count(mesh.nodes.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const int v : mesh.triangles[t]) {
      sum[static_cast<std::size_t>(v)] += mesh.triangle_thickness[t];
      ++count[static_cast<std::size_t>(v)];
    }
  for (std::size_t v = 0; v < mesh.nodes.size(); ++v)
    if (count[v] > 0) mesh.shell_thickness[v] = sum[v] / count[v];
}

namespace {
/// Clamps `side` (KL8a): its missing node is the half turn of the opposite corner about the
/// triangle's reference normal through the side's midpoint.
void clamp_side(Mesh& mesh, const EdgeSide& side) {
  const auto& tri = mesh.triangles[static_cast<std::size_t>(side.triangle)];
  const Vec3d& x0 = mesh.nodes[tri[0]];
  const Vec3d n = (mesh.nodes[tri[1]] - x0).cross(mesh.nodes[tri[2]] - x0).normalized();
  SideMirror& m = mesh.side_mirrors[side.nodes];
  m.point = 0.5 * (mesh.nodes[side.nodes.first] + mesh.nodes[side.nodes.second]);
  m.map = 2.0 * n * n.transpose() - Mat3d::Identity();
}
}  // namespace

std::vector<EdgeSide> sides_on_edges(const Mesh& mesh, const std::vector<int>& edges) {
  std::set<std::pair<int, int>> wanted;  // undirected: the smaller node first
  for (const int k : edges) {
    const auto& edge = mesh.edges[static_cast<std::size_t>(k)];
    wanted.emplace(std::min(edge[0], edge[1]), std::max(edge[0], edge[1]));
  }
  std::vector<EdgeSide> out;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      if (mesh.triangle_neighbours[t][i] >= 0) continue;
      const int a = mesh.triangles[t][(i + 1) % 3], b = mesh.triangles[t][(i + 2) % 3];
      if (wanted.count({std::min(a, b), std::max(a, b)}))
        out.push_back({static_cast<int>(t), {a, b}});
    }
  return out;
}

void clamp_sides(Mesh& mesh, const std::vector<int>& edges) {
  for (const EdgeSide& side : sides_on_edges(mesh, edges)) clamp_side(mesh, side);
}

int clamp_to_rigid(Mesh& mesh, const std::vector<char>& rigid) {
  PLISSE_CHECK(mesh.is_shell() && rigid.size() == mesh.triangles.size() &&
                   mesh.triangle_adjacent.size() == mesh.triangles.size() &&
                   mesh.triangle_neighbours.size() == mesh.triangles.size(),
               "clamp_to_rigid needs a shell's mid-surface and a flag per triangle");
  int clamped = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = mesh.triangle_adjacent[t][static_cast<std::size_t>(i)];
      if (a < 0 || (rigid[t] != 0) == (rigid[static_cast<std::size_t>(a)] != 0)) continue;
      mesh.triangle_adjacent[t][static_cast<std::size_t>(i)] = -1;
      mesh.triangle_neighbours[t][static_cast<std::size_t>(i)] = -1;
      if (rigid[t] != 0) continue;  // the rigid side's patch is never assembled
      const auto& tri = mesh.triangles[t];
      clamp_side(mesh, {static_cast<int>(t),
                        {tri[static_cast<std::size_t>((i + 1) % 3)],
                         tri[static_cast<std::size_t>((i + 2) % 3)]}});
      ++clamped;
    }
  return clamped;
}

void mirror_sides(Mesh& mesh, const std::vector<int>& edges, int axis, double value) {
  PLISSE_CHECK(axis >= 0 && axis < 3, "mirror plane axis " << axis);
  for (const EdgeSide& side : sides_on_edges(mesh, edges)) {
    SideMirror& m = mesh.side_mirrors[side.nodes];
    m.point = Vec3d::Zero();
    m.point[axis] = value;
    m.map = Mat3d::Identity();
    m.map(axis, axis) = -1.0;
  }
}

}  // namespace plisse
