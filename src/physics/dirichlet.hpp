#pragma once
/// Dirichlet conditions (fixed, prescribed, symmetry) turned into constrained displacement
/// components of nodes.
#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "mesh/surface_ref.hpp"
#include "physics/ramp.hpp"

namespace plisse {

/// One constrained displacement component: u_component(node, t) = value * ramp.factor(t).
struct ConstrainedComponent {
  int node = 0;
  int component = 0;   ///< 0, 1, 2 = x, y, z
  double value = 0.0;  ///< [mm] at the end of the ramp
  Ramp ramp;
  double at(double t) const { return value * ramp.factor(t); }
};

/// The normal axis (0, 1, 2) of a planar, coordinate-aligned tagged surface, or -1 when the surface
/// is not a plane normal to x, y or z (relative tolerance `tol` on the triangle normals).
int coordinate_plane_axis(const Mesh& mesh, const std::vector<int>& triangles, double tol = 1e-8);

/// The mirror planes of a model: bit k (1: x = 0, 2: y = 0, 4: z = 0) is set when one of the
/// `symmetry` conditions' surfaces `symmetry_surfaces` lies in the plane x_k = 0 (within `tol` of
/// the surface's extent), the body lies on one side of that plane, and no symmetry surface of a
/// solid lies in the body's far face along the same axis (a slice between two symmetry planes,
/// plane strain or a periodic structure, has no whole body to sum over). The planes that double
/// a volume or force for the whole body (cavity_volume.hpp, full_body_factor); a plane that
/// merely closes a cavity, such as the base under a bulged sheet, is not one.
int mirror_planes(const std::vector<std::string>& symmetry_surfaces, const Mesh& mesh,
                  double tol = 1e-8);

/// The mirror planes among `mirrors` (bits as mirror_planes) that the surface `triangles` reaches:
/// one of its nodes lies on the plane, within `tol` of the surface's extent. A condition on such
/// a surface continues across the plane in the whole body; on one that does not reach it, the
/// mirror image is a separate surface.
int planes_reached(const Mesh& mesh, const std::vector<int>& triangles, int mirrors,
                   double tol = 1e-8);
/// planes_reached for the nodes `nodes` (a condition's, condition_nodes).
int planes_reached(const Mesh& mesh, const std::set<int>& nodes, int mirrors, double tol = 1e-8);

/// The axis k (0, 1, 2) of the plane x_k = const that holds every node of the shell edges `edges`
/// (indices into mesh.edges, within `tol` of the extent) and crosses the shell (the normals of
/// the triangles along it make at most 60 degrees with the plane; a faceted shell meeting it at a
/// right angle tilts by about h/R): the plane a symmetry edge of a shell mirrors through
/// (docs/theory/shell.md, KL8a). -1 when there is none. Precondition: mesh.is_shell().
int shell_edge_plane_axis(const Mesh& mesh, const std::vector<int>& edges, double tol = 1e-8);

/// The whole body's force from the modelled part's force `f` on something that each mirror plane
/// of `cut` maps onto itself (a condition's surface that reaches the plane, a die centred on it):
/// its mirror images add up, so the component normal to each such plane cancels and every other
/// component doubles, once per plane.
Vec3d whole_body_force(Vec3d f, int cut);
/// The same for a moment about the origin `m` (the mirror planes pass through it): a mirror image
/// of a moment is the moment reflected and turned round (an axial vector), so the images add up
/// to twice the component normal to the plane, and the others cancel, once per plane (two planes
/// leave nothing).
Vec3d whole_body_moment(Vec3d m, int cut);

/// The constrained components of a model's conditions, gathered one condition at a time, one per
/// (node, component). A node where two conditions prescribe different motions of the same
/// component is an InputError at the later condition; zero motions agree whatever their ramps.
class ConstraintSet {
 public:
  /// The components added next are the condition's at `place`, on the surface `surface` (named
  /// when a later condition conflicts with one of them).
  void begin(const InputPlace& place, const std::string& surface);
  /// u_component(node, t) = value * ramp.factor(t).
  void add(int node, int component, double value, const Ramp& ramp);
  /// Every component, ordered by (node, component).
  std::vector<ConstrainedComponent> components() const;

 private:
  struct Held {
    ConstrainedComponent component;
    std::string surface;  ///< of the condition that added it
  };
  std::map<std::pair<int, int>, Held> by_dof_;
  InputPlace place_;
  std::string surface_;
};

/// The nodes a condition on `surface` holds: the corners of its tagged triangles and, on a
/// second-order mesh, their edge nodes; on a shell mesh the nodes of the edge tag of that name
/// (Mesh::edge_tags), else of the surface tag. InputError at the surface's place when the mesh has
/// no such tag.
std::set<int> condition_nodes(const Mesh& mesh, const SurfaceRef& surface);

/// The edge tag a condition on a shell names (Mesh::edge_tags), or nullptr: on a solid mesh, and
/// for a surface tag of a shell.
const std::vector<int>* shell_edge_tag(const Mesh& mesh, const std::string& name);

/// `fixed`: every displacement component of the surface's nodes is zero.
void fix_surface(const Mesh& mesh, const SurfaceRef& surface, ConstraintSet& set);

/// `symmetry`: the displacement normal to the surface's plane is zero. The surface must be a
/// coordinate plane (x, y or z = const), on a shell an edge in such a plane that meets the shell
/// at a right angle (shell_edge_plane_axis): else an InputError at its place.
void hold_in_plane(const Mesh& mesh, const SurfaceRef& surface, ConstraintSet& set);

/// `displacement`: the given components of `value` [mm], times `ramp`; an empty one stays free.
void prescribe_surface(const Mesh& mesh, const SurfaceRef& surface,
                       const std::array<std::optional<double>, 3>& value, const Ramp& ramp,
                       ConstraintSet& set);

/// Largest distance of a tagged surface's nodes from their least-squares plane, and the tolerance
/// a symmetry surface's may reach: kPlanarityTolerance times the mean edge of its triangles.
struct Planarity {
  double deviation = 0.0;  ///< [mm]
  double tolerance = 0.0;  ///< [mm]
};
/// Symmetry surfaces may deviate from their best-fit plane by this fraction of their mean edge
/// length: far below any discretisation of a curved surface (a sphere of radius R meshed with
/// edges h has sagitta ~ h^2 / (8 R), i.e. 1e-3 h only when h < 0.008 R, and its nodes span the
/// whole cap), far above the round-off of coordinates written to a .msh file.
inline constexpr double kPlanarityTolerance = 1e-3;
Planarity planarity(const Mesh& mesh, const std::vector<int>& triangles);

}  // namespace plisse
