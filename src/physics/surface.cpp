#include "physics/surface.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <unordered_map>

#include "core/error.hpp"
#include "mesh/topology.hpp"

namespace plisse {

std::vector<SurfaceFace> outward_faces(const Mesh& mesh, const std::string& name) {
  const auto tag = mesh.surface_tags.find(name);
  PLISSE_CHECK(tag != mesh.surface_tags.end(), "no surface tag '" << name << "'");
  if (mesh.is_shell()) {
    // A shell's tag names one of its two faces (Mesh::shell_face_side): the outward normal of the
    // +1 face is the triangles' own, of the -1 face the opposite one.
    const auto side = mesh.shell_face_side.find(name);
    const bool turn = side == mesh.shell_face_side.end() || side->second < 0;
    std::vector<SurfaceFace> out(tag->second.size());
    for (std::size_t k = 0; k < tag->second.size(); ++k) {
      const auto& tri = mesh.triangles[static_cast<std::size_t>(tag->second[k])];
      out[k].nodes = {tri[0], turn ? tri[2] : tri[1], turn ? tri[1] : tri[2], -1, -1, -1};
    }
    return out;
  }
  const bool second_order = mesh.order() == 2;
  PLISSE_CHECK(!second_order || mesh.triangle_edge_nodes.size() == mesh.triangles.size(),
               "surface '" << name << "': the second-order mesh has "
                           << mesh.triangle_edge_nodes.size() << " edge-node triples for "
                           << mesh.triangles.size() << " triangles");
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
  std::vector<SurfaceFace> out;
  out.reserve(tag->second.size());
  for (int t : tag->second) {
    SurfaceFace face;
    const auto& tri = mesh.triangles[t];
    std::copy(tri.begin(), tri.end(), face.nodes.begin());
    if (second_order) {
      face.n_nodes = 6;
      std::copy(mesh.triangle_edge_nodes[t].begin(), mesh.triangle_edge_nodes[t].end(),
                face.nodes.begin() + 3);
    }
    auto key = tri;
    std::sort(key.begin(), key.end());
    const int opposite = wanted.at(key);
    PLISSE_CHECK(opposite >= 0, "triangle " << t << " of surface '" << name
                                            << "' is not a face of any tetrahedron");
    const Vec3d& x0 = mesh.nodes[tri[0]];
    const Vec3d n = (mesh.nodes[tri[1]] - x0).cross(mesh.nodes[tri[2]] - x0);
    if (n.dot(mesh.nodes[opposite] - x0) > 0) {
      // Corners (0, 1, 2) -> (0, 2, 1): the edges (01, 12, 20) become (02, 21, 10), i.e. the old
      // edge nodes (20, 12, 01).
      std::swap(face.nodes[1], face.nodes[2]);
      if (second_order) std::swap(face.nodes[3], face.nodes[5]);
    }
    out.push_back(face);
  }
  return out;
}

std::vector<std::array<int, 3>> outward_triangles(const Mesh& mesh, const std::string& name) {
  const std::vector<SurfaceFace> faces = outward_faces(mesh, name);
  std::vector<std::array<int, 3>> out;
  out.reserve(faces.size());
  for (const SurfaceFace& f : faces) out.push_back(f.corners());
  return out;
}

std::vector<double> shell_thickness(const Mesh& mesh,
                                    const std::vector<std::array<int, 3>>& triangles) {
  const auto sorted = [](std::array<int, 3> t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  std::map<std::array<int, 3>, double> thickness_of;
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e)
    thickness_of.emplace(sorted(mesh.triangles[e]), mesh.triangle_thickness.at(e));
  std::vector<double> out;
  out.reserve(triangles.size());
  for (const auto& t : triangles) {
    const auto it = thickness_of.find(sorted(t));
    PLISSE_CHECK(it != thickness_of.end(), "nodes " << t[0] << ", " << t[1] << ", " << t[2]
                                                    << " are not a triangle of the shell");
    out.push_back(it->second);
  }
  return out;
}

std::vector<SurfaceFace> faces_with_corners(const Mesh& mesh,
                                            const std::vector<std::array<int, 3>>& triangles) {
  std::vector<SurfaceFace> out(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i)
    std::copy(triangles[i].begin(), triangles[i].end(), out[i].nodes.begin());
  if (mesh.order() == 1) return out;
  // The edge node of every corner pair (min, max) of the tetrahedra.
  const auto pair_key = [](int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
           static_cast<std::uint32_t>(std::max(a, b));
  };
  std::unordered_map<std::uint64_t, int> edge_node;
  edge_node.reserve(mesh.tets.size() * 2);
  for (size_t t = 0; t < mesh.tets.size(); ++t)
    for (size_t e = 0; e < kTetEdges.size(); ++e)
      edge_node.emplace(pair_key(mesh.tets[t][kTetEdges[e][0]], mesh.tets[t][kTetEdges[e][1]]),
                        mesh.tet_edge_nodes[t][e]);
  for (SurfaceFace& face : out) {
    face.n_nodes = 6;
    for (int k = 0; k < 3; ++k) {
      const int a = face.nodes[k], b = face.nodes[(k + 1) % 3];
      const auto it = edge_node.find(pair_key(a, b));
      PLISSE_CHECK(it != edge_node.end(), "nodes "
                                              << a << " and " << b
                                              << " of a face are not an edge of any tetrahedron");
      face.nodes[3 + k] = it->second;
    }
  }
  return out;
}

std::set<int> surface_nodes(const std::vector<SurfaceFace>& faces) {
  std::set<int> nodes;
  for (const SurfaceFace& f : faces) {
    const auto list = f.node_list();
    nodes.insert(list.begin(), list.end());
  }
  return nodes;
}

}  // namespace plisse
