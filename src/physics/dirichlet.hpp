#pragma once
/// Dirichlet conditions (fixed, prescribed, symmetry) turned into constrained displacement
/// components of nodes.
#include <vector>

#include "mesh/mesh.hpp"
#include "physics/boundary_condition.hpp"
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

/// The mirror planes of a model: bit k (1: x = 0, 2: y = 0, 4: z = 0) is set when a `symmetry`
/// condition of `conditions` holds a surface in the plane x_k = 0 (within `tol` of the surface's
/// extent). The planes that double a volume or force for the whole body (cavity_volume.hpp,
/// full_body_factor); a plane that merely closes a cavity, such as the base under a bulged sheet,
/// is not one.
int mirror_planes(const std::vector<BoundaryCondition>& conditions, const Mesh& mesh,
                  double tol = 1e-8);

/// The mirror planes among `mirrors` (bits as mirror_planes) that the surface `triangles` reaches:
/// one of its nodes lies on the plane, within `tol` of the surface's extent. A condition on such
/// a surface continues across the plane in the whole body; on one that does not reach it, the
/// mirror image is a separate surface.
int planes_reached(const Mesh& mesh, const std::vector<int>& triangles, int mirrors,
                   double tol = 1e-8);

/// The whole body's force from the modelled part's force `f` on something that each mirror plane
/// of `cut` maps onto itself (a condition's surface that reaches the plane, a die centred on it):
/// its mirror images add up, so the component normal to each such plane cancels and every other
/// component doubles, once per plane.
Vec3d whole_body_force(Vec3d f, int cut);

/// All constrained components of `conditions`, one per (node, component). A condition holds the
/// corners of its tagged triangles and, on a second-order mesh, their edge nodes. A node where two
/// conditions prescribe different motions of the same component is an InputError at the later
/// condition. Symmetry surfaces must be coordinate planes (x, y or z = const).
std::vector<ConstrainedComponent> collect_constraints(
    const std::vector<BoundaryCondition>& conditions, const Mesh& mesh);

}  // namespace plisse
