#include "analysis/wall_thickness.hpp"

#include <algorithm>
#include <limits>

#include "analysis/surface_columns.hpp"
#include "analysis/wrinkle_rings.hpp"
#include "core/error.hpp"

namespace plisse {

std::optional<WallFaces> wall_faces(const Mesh& mesh) {
  for (const WallFaces& faces : {WallFaces{"inner", "outer"}, WallFaces{"bottom", "top"}})
    if (mesh.has_surface(faces.first) && mesh.has_surface(faces.second)) return faces;
  return std::nullopt;
}

WallThickness::WallThickness(const Mesh& mesh, const WallFaces& faces)
    : mesh_(mesh), faces_{face(faces.first), face(faces.second)} {}

WallThickness::Face WallThickness::face(const std::string& tag) const {
  Face f;
  f.triangles = sampling_triangles(mesh_, tag);  // checks the tag
  PLISSE_CHECK(!f.triangles.empty(),
               "wall thickness: the surface '" << tag << "' has no triangles");
  const std::size_t n = mesh_.nodes.size();
  f.start.assign(n + 1, 0);
  for (const auto& t : f.triangles)
    for (int a : t) ++f.start[static_cast<std::size_t>(a) + 1];
  for (std::size_t v = 0; v < n; ++v) f.start[v + 1] += f.start[v];
  f.at_node.resize(static_cast<std::size_t>(f.start[n]));
  std::vector<int> fill(f.start.begin(), f.start.end() - 1);
  for (std::size_t t = 0; t < f.triangles.size(); ++t)
    for (int a : f.triangles[t])
      f.at_node[static_cast<std::size_t>(fill[static_cast<std::size_t>(a)]++)] =
          static_cast<int>(t);
  f.nearest = nearest_triangles(mesh_.nodes, f.triangles, mesh_.nodes);
  return f;
}

double WallThickness::distance(const Face& f, const std::vector<Vec3d>& x, std::size_t v) const {
  const auto triangle_distance = [&](int t) {
    const auto& corners = f.triangles[static_cast<std::size_t>(t)];
    return point_triangle_distance(x[v], x[static_cast<std::size_t>(corners[0])],
                                   x[static_cast<std::size_t>(corners[1])],
                                   x[static_cast<std::size_t>(corners[2])]);
  };
  // A walk over the face: from the triangle nearest in the reference configuration to the
  // nearest of the triangles around its corners, until it stays. On a smooth face and a point
  // within the wall the distance has one minimum, so the walk ends at the nearest triangle.
  int at = f.nearest[v];
  double best = triangle_distance(at);
  for (int step = 0; step < 64; ++step) {
    const int from = at;
    for (int corner : f.triangles[static_cast<std::size_t>(from)])
      for (int q = f.start[static_cast<std::size_t>(corner)];
           q < f.start[static_cast<std::size_t>(corner) + 1]; ++q) {
        const int t = f.at_node[static_cast<std::size_t>(q)];
        const double d = triangle_distance(t);
        if (d < best) {
          best = d;
          at = t;
        }
      }
    if (at == from) break;
  }
  return best;
}

std::vector<double> WallThickness::operator()(const std::vector<Vec3d>& displacement) const {
  PLISSE_CHECK(displacement.size() == mesh_.nodes.size(),
               "wall thickness: " << displacement.size() << " displacements for " << mesh_.n_nodes()
                                  << " nodes");
  std::vector<Vec3d> x(mesh_.nodes.size());
  for (std::size_t v = 0; v < x.size(); ++v) x[v] = mesh_.nodes[v] + displacement[v];
  std::vector<double> thickness(x.size(), 0.0);
  for (const Face& f : faces_)
    for (std::size_t v = 0; v < x.size(); ++v) {
      thickness[v] += distance(f, x, v);
    }
  return thickness;
}

}  // namespace plisse
