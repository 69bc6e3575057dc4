#include "mesh/topology.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "core/error.hpp"

namespace plisse {

double tet_signed_volume(const Mesh& mesh, int t) {
  const auto& n = mesh.tets[static_cast<std::size_t>(t)];
  return six_signed_volume(mesh.nodes[n[0]], mesh.nodes[n[1]], mesh.nodes[n[2]], mesh.nodes[n[3]]) /
         6.0;
}

void flip_tet(Mesh& mesh, int t) {
  const auto i = static_cast<std::size_t>(t);
  std::swap(mesh.tets[i][1], mesh.tets[i][2]);
  if (!mesh.tet_edge_nodes.empty()) {
    // Corners (0, 1, 2, 3) -> (0, 2, 1, 3): edges (01, 12, 20, 30, 32, 31) become
    // (02, 21, 10, 30, 31, 32), i.e. old edges (2, 1, 0, 3, 5, 4).
    auto& e = mesh.tet_edge_nodes[i];
    std::swap(e[0], e[2]);
    std::swap(e[4], e[5]);
  }
}

std::vector<BoundaryFace> compute_boundary_faces(const Mesh& mesh) {
  struct Entry {
    std::array<int, 3> key;
    int tet;
    int local_face;
  };
  std::vector<Entry> all;
  all.reserve(4 * mesh.tets.size());
  for (int t = 0; t < mesh.n_tets(); ++t) {
    const auto& n = mesh.tets[static_cast<std::size_t>(t)];
    for (int k = 0; k < 4; ++k) {
      const auto& f = kTetFaces[static_cast<std::size_t>(k)];
      all.push_back({sorted_face({n[f[0]], n[f[1]], n[f[2]]}), t, k});
    }
  }
  std::sort(all.begin(), all.end(), [](const Entry& a, const Entry& b) {
    return a.key != b.key ? a.key < b.key : a.tet < b.tet;
  });
  std::vector<BoundaryFace> faces;
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i + 1;
    while (j < all.size() && all[j].key == all[i].key) ++j;
    if (j - i == 1) {
      const auto& n = mesh.tets[static_cast<std::size_t>(all[i].tet)];
      const auto& f = kTetFaces[static_cast<std::size_t>(all[i].local_face)];
      faces.push_back({{n[f[0]], n[f[1]], n[f[2]]}, all[i].tet, all[i].local_face});
    }
    i = j;
  }
  return faces;
}

namespace {
/// The corners of elements `elements` of `corners` and, on a second-order mesh, their nodes of
/// `edge_nodes` (`what` names the element in the error for a missing list).
template <class Corners, class EdgeNodes>
std::set<int> nodes_of(const Mesh& mesh, const std::vector<int>& elements, const Corners& corners,
                       const EdgeNodes& edge_nodes, const char* what) {
  std::set<int> nodes;
  for (int e : elements) {
    for (int v : corners[static_cast<std::size_t>(e)]) nodes.insert(v);
    if (mesh.order() == 2) {
      PLISSE_CHECK(static_cast<std::size_t>(e) < edge_nodes.size(),
                   what << " " << e << " of the second-order mesh has no edge nodes");
      for (int v : edge_nodes[static_cast<std::size_t>(e)]) nodes.insert(v);
    }
  }
  return nodes;
}
}  // namespace

std::set<int> triangle_nodes(const Mesh& mesh, const std::vector<int>& triangles) {
  return nodes_of(mesh, triangles, mesh.triangles, mesh.triangle_edge_nodes, "triangle");
}

std::set<int> edge_nodes(const Mesh& mesh, const std::vector<int>& edges) {
  std::set<int> out;
  for (const int k : edges) {
    PLISSE_CHECK(k >= 0 && k < static_cast<int>(mesh.edges.size()),
                 "edge " << k << " of " << mesh.edges.size());
    out.insert(mesh.edges[static_cast<std::size_t>(k)].begin(),
               mesh.edges[static_cast<std::size_t>(k)].end());
  }
  return out;
}

std::set<int> tet_nodes(const Mesh& mesh, const std::vector<int>& tets) {
  return nodes_of(mesh, tets, mesh.tets, mesh.tet_edge_nodes, "tetrahedron");
}

int nearest_node(const Mesh& mesh, const Vec3d& point) {
  int best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (const double d = (mesh.nodes[v] - point).squaredNorm(); d < best_distance) {
      best_distance = d;
      best = v;
    }
  return best;
}

double longest_edge_at(const Mesh& mesh, int v) {
  double longest = 0.0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& tet = mesh.tets[t];
    bool touches = std::find(tet.begin(), tet.end(), v) != tet.end();
    if (!touches && t < mesh.tet_edge_nodes.size()) {
      const auto& edges = mesh.tet_edge_nodes[t];
      touches = std::find(edges.begin(), edges.end(), v) != edges.end();
    }
    if (!touches) continue;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        longest = std::max(longest, (mesh.nodes[tet[a]] - mesh.nodes[tet[b]]).norm());
  }
  if (!mesh.is_shell()) return longest;
  for (const auto& tri : mesh.triangles) {
    if (std::find(tri.begin(), tri.end(), v) == tri.end()) continue;
    for (int a = 0; a < 3; ++a)
      longest = std::max(longest, (mesh.nodes[tri[a]] - mesh.nodes[tri[(a + 1) % 3]]).norm());
  }
  return longest;
}

}  // namespace plisse
