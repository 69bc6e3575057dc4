#pragma once
/// Generated meshes (through the Gmsh API): cube, spherical shell, airbag, sheet, tube; and the
/// mid-surfaces of all but the cube as shells, and a flat circular panel (disc) as a shell only.
///
/// The options of each kind are declared once in `mesh_kinds()` (key, unit, range, help, default);
/// the case-file parser (`mesh:` section) and `plisse mesh KIND --key value` both read that table,
/// so input keys, command-line options and documentation cannot disagree.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/parameter.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// Which part of a symmetric body is meshed. The kept part is x >= 0 (sym_x), z >= 0 (sym_z) and
/// y >= 0 (sym_y): half keeps z >= 0, quarter keeps x >= 0 and z >= 0, octant keeps all three.
/// y is the polar axis of shells (the paper's die moves along -y).
enum class Symmetry { full, half, quarter, octant };

/// All generator inputs. Which members a kind uses is declared in `mesh_kinds()`.
struct MeshGenerationSpec {
  std::string kind;  ///< "cube" | "spherical-shell" | "airbag" | "sheet" | "tube" | "disc"
  // cube: [0, edge]^3
  double edge = 5.0;  ///< [mm]
  int divisions = 4;  ///< element divisions per edge
  // spherical-shell: inner radius, wall thickness
  double inner_radius = 10.0;  ///< [mm]
  // airbag: oblate closed shell, equatorial radius and total height of the mid-surface;
  // tube: mid-surface radius (radius) and length (length); disc: its radius
  double radius = 50.0;  ///< [mm]
  double height = 20.0;  ///< [mm]
  // sheet: [0, length] x [0, width] x [0, thickness]
  double length = 50.0;  ///< [mm]
  double width = 50.0;   ///< [mm]
  // shared by shell, airbag, sheet
  double thickness = 1.0;              ///< wall/sheet thickness [mm]
  int layers = 3;                      ///< tetrahedra through the thickness (exactly); not a
                                       ///< shell's (generate_shell_surface ignores it)
  double element_size = 1.0;           ///< target in-surface element size [mm]
  Symmetry symmetry = Symmetry::full;  ///< shell and airbag; tube: full or half
  // shell and airbag: finer elements about the +y pole (0 = none; docs/meshes.md)
  double pole_element_size = 0.0;  ///< edge at the pole [mm]
  double pole_radius = 0.0;        ///< distance from the pole meshed at pole_element_size [mm]
  // disc: finer elements along the rim (0 = none; the pole's rule, PoleRefinement)
  double rim_element_size = 0.0;  ///< edge at the rim [mm]
  double rim_width = 0.0;         ///< distance from the rim meshed at rim_element_size [mm]
  // tube: cells along the axis graded from the end x = 0 (0 = uniform; tube_stations)
  double end_element_size = 0.0;  ///< cell length at x = 0 [mm]
  double end_length = 0.0;        ///< distance from x = 0 over which it grows to element_size [mm]
  // all kinds
  int order = 1;  ///< 1: 4-node tetrahedra; 2: 10-node (one node per edge, on curved walls)
};

/// One declared generator option. Exactly one of the three member pointers is set.
struct MeshOption {
  std::string key;   ///< input key (snake_case); on the command line with dashes
  std::string unit;  ///< "mm", "-"
  std::string help;
  double MeshGenerationSpec::*real = nullptr;
  int MeshGenerationSpec::*integer = nullptr;
  Symmetry MeshGenerationSpec::*symmetry = nullptr;
  Range range = Range::any();  ///< for real and integer options
  /// For the symmetry option: the parts the kind can mesh ("full", "half", ...), in that order;
  /// validate_mesh_spec refuses the others.
  std::vector<std::string> symmetries = {};
};

struct MeshKind {
  std::string name;  ///< as in `generate: NAME` and `plisse mesh NAME`
  std::string help;  ///< one line: geometry and tags
  std::vector<MeshOption> options;
};

/// The declared kinds and their options (the only registry of generator names and keys).
const std::vector<MeshKind>& mesh_kinds();
/// The kind called `name`, or nullptr.
const MeshKind* find_mesh_kind(const std::string& name);
/// "full" | "half" | "quarter" | "octant" -> Symmetry; nullopt for anything else.
std::optional<Symmetry> parse_symmetry(const std::string& text);
std::string to_string(Symmetry s);

/// Generates the mesh described by `spec` (docs/meshes.md). Callers validate input against
/// `mesh_kinds()` first to report their own place; `generate_mesh` calls `validate_mesh_spec`
/// again, so an invalid spec never reaches the generators. Every tetrahedron is positively
/// oriented; boundary triangles have the outward normal by the right-hand rule. With
/// `spec.order` 2 the corner nodes, tetrahedra, triangles and tags are those of order 1, and one
/// node per edge follows them: the straight midpoint for the cube and the sheet, a point on the
/// true curved surfaces for the shell and the airbag (docs/meshes.md, "Second-order meshes").
Mesh generate_mesh(const MeshGenerationSpec& spec);

/// Generates the mid-surface of the shell `spec` describes (docs/meshes.md, "Shell meshes"): a
/// Mesh of linear triangles and no tetrahedra, made a shell of thickness `spec.thickness` by
/// make_shell_surface (mesh/shell_surface.hpp), for the kinds
/// - `sheet`: the plane z = thickness/2 over [0, length] x [0, width], structured like the solid
///   sheet's planes (the same nodes in x and y), normals +z;
/// - `spherical-shell`: the sphere of radius inner_radius + thickness/2; `airbag`: the spheroid
///   the solid airbag's wall is centred on; both triangulated by Gmsh as the solids' surfaces are
///   (mesh_spheroid_surface), nodes exactly on the surface, normals outward;
/// - `tube`: the cylinder of radius `radius` from x = 0 to length, structured like the solid
///   tube's layers, normals outward;
/// with the solid's `symmetry`, `element_size` and pole refinement. Nodes on a cut plane have
/// that coordinate exactly 0. Surface tags list every triangle: `bottom` and `top` (sheet) or
/// `inner` and `outer`, with Mesh::shell_face_side -1 and +1. Edge tags (Mesh::edges, edge_tags)
/// are the boundary edges in the planes of the solid's tags: `sym_x`, `sym_y`, `sym_z` (x, y, z =
/// 0) of a cut, the sheet's `left` = `sym_x`, `right`, `front` = `sym_y`, `back`, the tube's
/// `left` (x = 0) and `right` (x = length).
/// `layers` is ignored (not even range-checked). Throws InputError at "mesh.generate" for the
/// cube (it has no mid-surface), at "mesh.order" for order 2 (the shell triangle is linear), and
/// as validate_mesh_spec for the other options, with the size limit on triangles
/// (kMaxGeneratedTriangles) instead of tetrahedra.
Mesh generate_shell_surface(const MeshGenerationSpec& spec);

/// Checks `spec` without generating: the kind is known (key "mesh.generate"), each option of the
/// kind is in its declared range, the cross-option rules hold (e.g. airbag thickness below the
/// smallest radius of curvature of the mid-surface) and the estimated size is at most
/// kMaxGeneratedTets. Throws InputError with InputPlace key "mesh.<key>" and the rule.
void validate_mesh_spec(const MeshGenerationSpec& spec);

/// Estimated number of tetrahedra `generate_mesh(spec)` makes (exact for cube and sheet).
double estimate_n_tets(const MeshGenerationSpec& spec);

/// Largest accepted estimated mesh size (tetrahedra).
inline constexpr double kMaxGeneratedTets = 20e6;

/// Estimated number of triangles `generate_shell_surface(spec)` makes (exact for the sheet and
/// the tube), and its limit.
double estimate_n_shell_triangles(const MeshGenerationSpec& spec);
inline constexpr double kMaxGeneratedTriangles = 20e6;

}  // namespace plisse
