#pragma once
/// The current thickness of a membrane's wall at every node: the distance to one face of the wall
/// plus the distance to the other, both measured in the deformed configuration
/// (docs/output.md, "Wall thickness").
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// The two surface tags that bound a wall.
using WallFaces = std::pair<std::string, std::string>;

/// The two surface tags that bound the wall of `mesh`: `inner` and `outer` (generated spheres,
/// airbags and tubes, and file meshes tagged so), else `bottom` and `top` (the generated sheet),
/// else nullopt (a cube, or a file mesh without such tags).
std::optional<WallFaces> wall_faces(const Mesh& mesh);

/// At each node, d(x, A) + d(x, B) [mm]: x = X + u its deformed position, A and B the deformed
/// faces (on a second-order mesh each 6-node face split through its edge nodes,
/// sampling_triangles). On a face this is the distance to the other face; inside the wall, the sum
/// of the two. Exact for a flat wall of uniform thickness. On a curved wall whose nodes lie on
/// common normals (the generated shells), exact at the nodes of the convex face, whose distance to
/// the concave face's chords is to a node; elsewhere the chords of the convex face bend towards
/// the node and the distance is short by a factor of at least cos(h / R), h the edge of the
/// face's triangles and R its radius of curvature: 0.1 % at h = R / 20.
///
/// The nearest point of a face is found by a walk over its triangles from the one nearest to the
/// node in the reference configuration (found once, by a bucket search) to the nearest of the
/// triangles around its corners, until it stays: a few steps, as far as the through-thickness
/// fibres slide along the faces.
class WallThickness {
 public:
  /// Borrows `mesh`. Throws Error if a tag of `faces` is missing or empty.
  WallThickness(const Mesh& mesh, const WallFaces& faces);

  /// The thickness at every node for the displacement `displacement` (one vector a node).
  std::vector<double> operator()(const std::vector<Vec3d>& displacement) const;

 private:
  /// One face: its triangles, the triangles at each node (compressed rows), and per node of the
  /// mesh the face's triangle nearest to it in the reference configuration.
  struct Face {
    std::vector<std::array<int, 3>> triangles;
    std::vector<int> start, at_node;
    std::vector<int> nearest;
  };
  Face face(const std::string& tag) const;
  /// Distance from node v at `x` to the face `f`.
  double distance(const Face& f, const std::vector<Vec3d>& x, std::size_t v) const;

  const Mesh& mesh_;
  std::array<Face, 2> faces_;
};

}  // namespace plisse
