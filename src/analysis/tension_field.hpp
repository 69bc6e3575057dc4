#pragma once
/// Tension-field state of a membrane: taut, wrinkled or slack per through-thickness column, from
/// the in-plane principal values of the column-averaged Cauchy stress
/// (docs/theory/wrinkles.md, section 6).
///
/// Typical call after a converged step (per-element mean Cauchy stress sigma and J):
///   const auto outer = tagged_triangles(mesh, "outer");                // once per mesh
///   const auto columns = assign_columns(mesh.nodes, mesh.tets, outer);  // once per mesh
///   const TensionField tf = compute_tension_field(mesh.nodes, mesh.tets, outer, columns, u,
///                                                 sigma, J);
///   // tf.element_state -> VTU cell field "wrinkle_state" (0 taut, 1 wrinkled, 2 slack)
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// The state of a membrane column; the values are the ones written to output files.
enum class MembraneState : int { taut = 0, wrinkled = 1, slack = 2 };

/// "taut" | "wrinkled" | "slack".
const char* to_string(MembraneState state);

struct TensionFieldSettings {
  /// Stress below which a principal value counts as not tensile [MPa]; default (nullopt):
  /// relative_tolerance times the largest |sigma_1| over all columns (T4).
  std::optional<double> tolerance;
  double relative_tolerance = 1e-6;
};

struct TensionField {
  std::vector<MembraneState> element_state;   ///< per tetrahedron: its column's state
  std::vector<MembraneState> triangle_state;  ///< per outer triangle (column)
  /// Per outer triangle: in-plane principal values (sigma_1 >= sigma_2) of the column's
  /// volume-averaged Cauchy stress [MPa].
  std::vector<std::array<double, 2>> principal_stress;
  std::array<int, 3> n_elements{};   ///< elements per state, indexed by MembraneState
  std::array<int, 3> n_triangles{};  ///< triangles per state
  double tolerance = 0.0;            ///< the tolerance used [MPa]
};

/// Tension-field state (wrinkles.md, T1-T4).
///  - `nodes`, `tets`: reference mesh; `triangles`: the outer surface (outward right-hand order);
///  - `column`: per tetrahedron, its triangle (from assign_columns on the reference mesh);
///  - `displacement`: per node [mm] (the tangent planes are those of the deformed triangles);
///  - `cauchy_stress`: per tetrahedron, its mean Cauchy stress [MPa];
///  - `J`: per tetrahedron, det F (mean), for deformed-volume weights J V0; empty: weights V0.
/// A triangle whose column is empty (no centroid nearest to it) takes the stress of the
/// tetrahedron it is a face of. Throws Error on inconsistent sizes or indices, or if such a
/// triangle is no tetrahedron's face.
TensionField compute_tension_field(
    const std::vector<Vec3d>& nodes, const std::vector<std::array<int, 4>>& tets,
    const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& column,
    const std::vector<Vec3d>& displacement, const std::vector<Mat3d>& cauchy_stress,
    const std::vector<double>& J, const TensionFieldSettings& options = {});

/// Tension-field state of a shell (element: shell; wrinkles.md, T1s): its elements are the
/// mid-surface triangles, each its own column, whose stress is the element's Cauchy stress
/// averaged through the thickness.
///  - `nodes`: reference positions; `elements`: the shell's triangles (mesh.triangles), whose
///    order the stresses follow;
///  - `surface`: the measured surface's triangles (a face tag of the shell, which lists every
///    triangle for the generated shells) as indices into `elements`; triangle_state and
///    principal_stress are theirs, in this order;
///  - `displacement`: per node [mm] (the tangent planes are those of the deformed triangles);
///  - `cauchy_stress`: per element, its thickness-averaged Cauchy stress [MPa].
/// Every element is classified (element_state, n_elements) with its own in-plane principal
/// values; the default tolerance is relative_tolerance times the largest |sigma_1| over the
/// elements (T4). Throws Error on inconsistent sizes or indices.
TensionField compute_shell_tension_field(const std::vector<Vec3d>& nodes,
                                         const std::vector<std::array<int, 3>>& elements,
                                         const std::vector<int>& surface,
                                         const std::vector<Vec3d>& displacement,
                                         const std::vector<Mat3d>& cauchy_stress,
                                         const TensionFieldSettings& options = {});

/// Same on `mesh` with the triangles tagged `outer_tag` (columns computed here; when calling
/// every step, compute them once with assign_columns and use the overload above). On a shell
/// mesh, compute_shell_tension_field with the tag's triangles (`J` is not used).
TensionField compute_tension_field(const Mesh& mesh, const std::vector<Vec3d>& displacement,
                                   const std::vector<Mat3d>& cauchy_stress,
                                   const std::vector<double>& J,
                                   const TensionFieldSettings& options = {},
                                   const std::string& outer_tag = "outer");

}  // namespace plisse
