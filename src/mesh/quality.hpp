#pragma once
/// Mesh admissibility and quality report.
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace plisse {

struct MeshReport {
  std::vector<std::string> errors;    ///< the mesh cannot be used (each names the element/tag)
  std::vector<std::string> warnings;  ///< usable but suspicious
  double min_volume = 0.0;            ///< smallest (signed) tetrahedron volume [mm^3]
  double max_aspect_ratio = 0.0;  ///< largest (longest edge / inradius) / (2 sqrt 6); 1 if regular
  int n_unused_nodes = 0;         ///< nodes used by no tetrahedron (corner or edge node)
  int n_boundary_faces = 0;       ///< faces of exactly one tetrahedron
  /// Shell meshes: the smallest angle of a triangle and the largest turn between the normals of
  /// two triangles sharing a side [degrees].
  double min_angle_deg = 0.0;
  double max_turn_deg = 0.0;
  bool ok() const { return errors.empty(); }
};

/// Aspect ratio above which check_mesh warns (a regular tetrahedron has 1; thin-wall meshes with
/// a few layers through the thickness typically stay below 20).
inline constexpr double kAspectRatioWarning = 100.0;

/// Shell meshes: a triangle angle below this warns [degrees] (the side gradients of the shell
/// triangle lose accuracy as the triangle flattens).
inline constexpr double kShellAngleWarning = 10.0;
/// Shell meshes: a turn between neighbouring triangles above this warns [degrees]. The shell
/// triangle reads the curvature from the nodes across its sides (docs/theory/shell.md, KL6),
/// which is accurate while a side's turn h/R is small; at 45 degrees the element is as long as
/// the radius of curvature, and a sharper turn is a crease the element smooths over.
inline constexpr double kShellTurnWarning = 45.0;

/// The largest coordinate a mesh may have [mm]: the volume of a body of that size (1e90 mm^3)
/// and the products of the tangent stay far from the overflow of double precision (1.8e308).
inline constexpr double kMaxCoordinate = 1e30;

/// Checks, in this order (each problem is one message naming the element, node, edge or tag;
/// at most 10 messages per kind, then a count):
/// - errors: node indices out of range; coordinates that are not finite or beyond
///   kMaxCoordinate; inverted tetrahedra (volume < 0) and degenerate ones
///   (|volume| <= 1e-12 (longest edge)^3), with index and volume; second-order edge nodes that
///   differ between tetrahedra sharing an edge; tags listing indices out of range;
///   `required_tags` missing or empty (surface or volume tags); triangles that are no face of
///   any tetrahedron; non-manifold boundary edges (edges of the tetrahedral boundary shared by
///   other than two boundary faces, e.g. two tetrahedra touching along one edge only);
/// - warnings: nodes used by no tetrahedron; triangles that are interior faces (between two
///   tetrahedra); aspect ratio above kAspectRatioWarning.
///
/// A shell mesh (mesh.is_shell()) is checked as a surface: errors for node indices out of range,
/// non-finite coordinates or beyond kMaxCoordinate, degenerate triangles (area <= 1e-12 (longest
/// side)^2) and tags listing triangles or edges that do not exist; warnings for nodes of no
/// triangle, triangle angles below kShellAngleWarning and turns between neighbours above
/// kShellTurnWarning.
MeshReport check_mesh(const Mesh& mesh, const std::vector<std::string>& required_tags = {});

}  // namespace plisse
