#pragma once
/// Triangulation of a flat circular panel with Gmsh (the `disc` generator: an airbag's panel).
#include "mesh/layered_shell.hpp"
#include "mesh/spheroid_surface.hpp"

namespace plisse {

/// Triangulates the part kept by `symmetry` (full; half: z >= 0; quarter: x >= 0 and z >= 0) of
/// the disc x^2 + z^2 <= radius^2 in the plane y = 0, with target edge `h` [mm], through Gmsh's
/// OpenCASCADE kernel and default 2-D mesher. `rim` refines along the rim: its `size` within the
/// distance `rim.radius` of the rim circle, growing by PoleRefinement::kGrowth per unit distance
/// beyond, up to h (a Gmsh Threshold field on the distance to the rim). Nodes on a cut plane get
/// that coordinate set to exactly 0, rim nodes are put exactly on the circle, every node has
/// y = 0, and every triangle faces +y. Throws Error if Gmsh fails. Octant symmetry has no meaning
/// for a flat panel (the caller refuses it).
SurfaceTriangulation mesh_disc_surface(double radius, double h, Symmetry symmetry,
                                       const PoleRefinement& rim = {});

/// Estimated number of triangles `mesh_disc_surface(radius, h, symmetry, rim)` makes: the
/// integral over the kept part of 1 / (sqrt(3)/4 s^2), s the target edge at each radius.
double estimate_disc_triangles(double radius, double h, Symmetry symmetry,
                               const PoleRefinement& rim = {});

}  // namespace plisse
