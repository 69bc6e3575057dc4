#pragma once
/// The volume enclosed by a cavity's wall and the closure rule it relies on
/// (docs/theory/cavities.md, C1-C3 and C12-C13).
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"
#include "physics/surface.hpp"

namespace plisse {

/// Deformed position x = X + u of `node` from the full state (u at node_dof(node, 0..2)).
Vec3d deformed_position(const Mesh& mesh, std::span<const double> state, int node);

/// Signed volume [mm^3] of the cone from the origin over the 6-node face with nodes `xs` [mm]
/// (corners, then the edge nodes of 01, 12, 20): (1/3) ∫ x · (x_ξ × x_η) dξ dη (cavities.md, C12),
/// exact (the integrand has degree 4). For straight edges of a flat face it is x0 · (x1 × x2) / 6.
double quadratic_cone_volume(const std::array<Vec3d, 6>& xs);

/// Its gradient with respect to the six nodal positions [mm^2] (cavities.md, C13).
std::array<Vec3d, 6> quadratic_cone_volume_gradient(const std::array<Vec3d, 6>& xs);

/// Volume [mm^3] enclosed by `faces` in the state `state` (full-state layout of model_term.hpp;
/// only the nodal displacements are read), together with the symmetry planes x = 0, y = 0, z = 0
/// that close its boundary: minus the sum of the faces' cone volumes,
///   V = -(1/6) sum x0 . (x1 x x2)   for linear faces (cavities.md, C1), C12 for 6-node faces.
/// `faces` are oriented with the BODY's outward normal (outward_faces), which points into the
/// cavity, so the volume of the cavity on the far side of the body's wall is positive. Exact for
/// the deformed faces when the surface is closed up to those planes (first_open_edge) and its
/// boundary nodes stay on them.
double cavity_volume(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                     std::span<const double> state);

/// A corner edge of `faces` that does not belong to exactly two of them: its corners in the order
/// of the (first) face that runs it, its edge node on a 6-node face, how many faces hold it, and
/// the plane x_k = 0 it lies in (k, or -1: none; its end nodes, and its edge node on a 6-node
/// face, with |X_k| <= tolerance in the reference configuration).
struct OpenEdge {
  int a = -1, b = -1;  ///< corners, in the direction of the face
  int middle = -1;     ///< edge node, -1 on a linear face
  int faces = 1;       ///< 1 on a boundary; more where the surface is not a manifold
  int plane = -1;      ///< k of the plane x_k = 0 the edge lies in (the first), -1: none
};

/// The open edges of `faces`, in the order of their sorted corner pairs, with the tolerance
/// relative_tolerance times the largest extent of the surface. Empty for a closed surface.
std::vector<OpenEdge> open_edges(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                                 double relative_tolerance = 1e-8);

/// The first corner edge (node pair) of `faces` that breaks the closure rule (cavities.md, C2):
/// an edge must belong to exactly two faces, or to one face and lie in one of the planes x = 0,
/// y = 0, z = 0 (its end nodes, and its edge node on a 6-node face, with |coordinate| <=
/// relative_tolerance times the largest extent of the surface, in the reference configuration).
/// nullopt when the rule holds.
std::optional<std::array<int, 2>> first_open_edge(const Mesh& mesh,
                                                  const std::vector<SurfaceFace>& faces,
                                                  double relative_tolerance = 1e-8);

/// The symmetry planes that close `faces` by the rule of first_open_edge, as bits (1: x = 0,
/// 2: y = 0, 4: z = 0; an edge in two planes counts for the first), or nullopt when an edge breaks
/// the rule. 0: the surface is closed by itself.
std::optional<int> closing_planes(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                                  double relative_tolerance = 1e-8);

/// How many copies of the modelled part make the whole body when it is mirrored in the planes
/// `planes` (closing_planes' bits): 2 to the number of planes.
int full_body_factor(int planes);

}  // namespace plisse
