#pragma once
/// Thin-walled shells with an exact number of tetrahedra through the wall, built by stacking
/// layers of prisms on a surface triangulation (spherical-shell and airbag generators).
#include <array>
#include <functional>
#include <vector>

#include "core/types.hpp"
#include "mesh/generate.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// A triangulated surface: nodes and corner triples (orientation irrelevant).
struct SurfaceTriangulation {
  std::vector<Vec3d> nodes;
  std::vector<std::array<int, 3>> triangles;
};

/// Stacks `layers` layers of prisms on `surface`: node k of layer j (0 <= j <= layers) is
/// `position(k, j)` and gets index j n + k (n = surface nodes). Each prism (a, b, c) between
/// layers j and j+1, with a < b < c, is cut into the three tetrahedra
///   (a_j, b_j, c_j, c_{j+1}), (a_j, b_j, b_{j+1}, c_{j+1}), (a_j, a_{j+1}, b_{j+1}, c_{j+1}),
/// i.e. each quadrilateral side is cut by the diagonal from its smallest-index vertex. The rule
/// depends on the quadrilateral's vertices only, so prisms sharing a side cut it alike
/// (conforming mesh). Tetrahedra are then made positive.
/// Tags: `inner` (layer 0), `outer` (layer `layers`), and for each plane kept by `symmetry`
/// (sym_x: x = 0, sym_y: y = 0, sym_z: z = 0) the side faces whose nodes all have that
/// coordinate exactly 0. Precondition: positions on cut planes have the coordinate exactly 0.
///
/// Second order when `midpoint` is given: the edge between node k1 of layer j1 and node k2 of
/// layer j2 gets one edge node at `midpoint(k1, j1, k2, j2)` (add_edge_nodes; called once per
/// edge, for the edge's smaller mesh index first), so that curved walls can put it on the true
/// surface. An edge node whose two ends lie on a cut plane gets that coordinate exactly 0 (the
/// callback need only be within round-off of it), like the corners.
Mesh make_layered_shell(
    const SurfaceTriangulation& surface, int layers, Symmetry symmetry,
    const std::function<Vec3d(int node, int layer)>& position,
    const std::function<Vec3d(int node1, int layer1, int node2, int layer2)>& midpoint = {});

/// Which coordinate planes a symmetry cuts: {x = 0, y = 0, z = 0}.
std::array<bool, 3> cut_planes(Symmetry symmetry);

}  // namespace plisse
