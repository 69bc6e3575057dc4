#pragma once
/// Tetrahedral mesh with named boundary tags, or the triangulated mid-surface of a shell.
///
/// Linear tetrahedra (4 corner nodes) with optional second-order edge nodes (Gmsh's 10-node
/// tetrahedron). Boundary triangles carry named tags (Gmsh physical groups of dimension 2);
/// tetrahedra may carry named volume tags (physical groups of dimension 3).
/// A shell mesh (docs/theory/shell.md) has no tetrahedra: its `triangles` are the mid-surface's
/// elements, with the thickness and the edge neighbours of mesh/shell_surface.hpp.
/// Node numbering is 0-based and contiguous. Coordinates are in mm.
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"

namespace plisse {

/// How a shell triangle's side on a clamped or symmetry edge sees its missing neighbour
/// (docs/theory/shell.md, KL8a): as the image of the triangle's opposite corner under the fixed
/// affine map x -> point + map (x - point), in the reference and the current configuration alike.
/// `map` is orthogonal and symmetric: the reflection through a symmetry plane, or for a clamped
/// edge the half turn about the reference normal through the side's midpoint.
struct SideMirror {
  Vec3d point = Vec3d::Zero();  ///< a fixed point of the map [mm]
  Mat3d map = Mat3d::Identity();
};

struct Mesh {
  std::vector<Vec3d> nodes;                        ///< reference coordinates [mm]
  std::vector<std::array<int, 4>> tets;            ///< corner nodes, positively oriented (det > 0)
  std::vector<std::array<int, 6>> tet_edge_nodes;  ///< second order only: Gmsh edge order
                                                   ///< (01, 12, 20, 30, 32, 31); else empty
  std::vector<std::array<int, 3>> triangles;       ///< boundary triangles (corner nodes)
  std::vector<std::array<int, 3>> triangle_edge_nodes;  ///< second order only: (01, 12, 20)
  /// Surface tags: name -> indices into `triangles`. A triangle may be in several tags.
  std::map<std::string, std::vector<int>> surface_tags;
  /// Volume tags: name -> indices into `tets`.
  std::map<std::string, std::vector<int>> volume_tags;
  /// Shell meshes only (set by make_shell_surface, mesh/shell_surface.hpp), else empty. The
  /// reference thickness of every triangle [mm], the element's (uniform, or a region's own:
  /// set_shell_thickness).
  std::vector<double> triangle_thickness;
  /// Shell meshes only, else empty: the reference thickness at every node [mm], the mean of its
  /// triangles' (where regions of two thicknesses meet, in between). The elements, loads and dies
  /// read triangle_thickness.
  std::vector<double> shell_thickness;
  /// Shell meshes only: for each triangle and each side i (the side opposite corner i), the
  /// corner of the neighbouring triangle across that side that is not on it (shell.md, KL1),
  /// -1 where the side is an edge of the surface. Else empty.
  std::vector<std::array<int, 3>> triangle_neighbours;
  /// Shell meshes only: for each triangle and each side i, the index of the triangle across it,
  /// -1 where the side is an edge of the surface; with triangle_neighbours it gives the nodes
  /// across the neighbours' sides, the rest of the 12-node patch (shell.md, KL1b). Else empty.
  std::vector<std::array<int, 3>> triangle_adjacent;
  /// Shell meshes only: the tagged curves of the mid-surface (Gmsh physical groups of dimension
  /// 1, or a generator's named edges) as node pairs, and their tags: name -> indices into `edges`.
  /// A shell's boundary conditions name these (docs/meshes.md, "Shell meshes").
  std::vector<std::array<int, 2>> edges;
  std::map<std::string, std::vector<int>> edge_tags;
  /// Shell meshes only: the face of the shell that a surface tag names, +1 the face the
  /// triangles' normals point out of (a generated shell's `outer` or `top`), -1 the other
  /// (`inner`, `bottom`). A tag not listed (a Gmsh physical surface) names the -1 face: a
  /// pressure on it pushes along the normals.
  std::map<std::string, int> shell_face_side;
  /// Shell meshes only: the sides without a neighbour whose missing node is a mirror image
  /// (clamped and symmetry edges, KL8a), by the side's directed pair of nodes (corner i + 1,
  /// corner i + 2 of its triangle: unique, as a side without a neighbour belongs to one
  /// triangle); every other such side is free or hinged (KL8). Set from the case's conditions
  /// before the model is made.
  std::map<std::pair<int, int>, SideMirror> side_mirrors;

  int n_nodes() const { return static_cast<int>(nodes.size()); }
  int n_tets() const { return static_cast<int>(tets.size()); }
  int order() const { return tet_edge_nodes.empty() ? 1 : 2; }
  bool has_surface(const std::string& name) const { return surface_tags.count(name) != 0; }
  /// True for the mid-surface of a shell (make_shell_surface has run).
  bool is_shell() const { return !shell_thickness.empty(); }
};

}  // namespace plisse
