#include "physics/surface.hpp"

#include <algorithm>
#include <map>

#include "core/error.hpp"

namespace plisse {

std::vector<std::array<int, 3>> outward_triangles(const Mesh& mesh, const std::string& name) {
  const auto tag = mesh.surface_tags.find(name);
  FE_CHECK(tag != mesh.surface_tags.end(), "no surface tag '" << name << "'");
  // The fourth node of the tetrahedron owning each face, keyed by the sorted face.
  std::map<std::array<int, 3>, int> wanted;
  for (int t : tag->second) {
    auto key = mesh.triangles[t];
    std::sort(key.begin(), key.end());
    wanted.emplace(key, -1);
  }
  static constexpr int kFaces[4][4] = {{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}};
  for (const auto& tet : mesh.tets)
    for (const auto& f : kFaces) {
      std::array<int, 3> key = {tet[f[0]], tet[f[1]], tet[f[2]]};
      std::sort(key.begin(), key.end());
      if (auto it = wanted.find(key); it != wanted.end()) it->second = tet[f[3]];
    }
  std::vector<std::array<int, 3>> out;
  out.reserve(tag->second.size());
  for (int t : tag->second) {
    auto tri = mesh.triangles[t];
    auto key = tri;
    std::sort(key.begin(), key.end());
    const int opposite = wanted.at(key);
    FE_CHECK(opposite >= 0,
             "triangle " << t << " of surface '" << name << "' is not a face of any tetrahedron");
    const Vec3d& x0 = mesh.nodes[tri[0]];
    const Vec3d n = (mesh.nodes[tri[1]] - x0).cross(mesh.nodes[tri[2]] - x0);
    if (n.dot(mesh.nodes[opposite] - x0) > 0) std::swap(tri[1], tri[2]);
    out.push_back(tri);
  }
  return out;
}

std::set<int> surface_nodes(const std::vector<std::array<int, 3>>& triangles) {
  std::set<int> nodes;
  for (const auto& t : triangles) nodes.insert(t.begin(), t.end());
  return nodes;
}

}  // namespace plisse
