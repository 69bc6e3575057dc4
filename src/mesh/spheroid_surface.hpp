#pragma once
/// Triangulation of a (partial) sphere or oblate spheroid with Gmsh (shell and airbag generators).
#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <unordered_map>

#include "mesh/generate.hpp"
#include "mesh/layered_shell.hpp"

namespace plisse {

/// Finer elements about the pole (0, b, 0) of a spheroid: edge `size` within the distance
/// `radius` of it, growing linearly by `kGrowth` per unit distance beyond, up to the surface's
/// edge h. Distances are straight (chord) ones. `size` 0 means no refinement.
struct PoleRefinement {
  static constexpr double kGrowth = 0.2;
  double size = 0.0;    ///< [mm]
  double radius = 0.0;  ///< [mm]

  bool active() const { return size > 0.0; }
  /// The target edge at chord distance `distance` from the pole, for surface edge `h`.
  double size_at(double distance, double h) const {
    if (!active()) return h;
    return std::min(h, size + kGrowth * std::max(0.0, distance - radius));
  }
  /// The distance beyond which the edge is h again.
  double outer_radius(double h) const { return radius + (h - size) / kGrowth; }
};

/// Triangulates the part kept by `symmetry` (see Symmetry) of the spheroid
///   x^2/a^2 + y^2/b^2 + z^2/a^2 = 1     (a: equatorial radius in the x-z plane, b: polar
///                                         semi-axis along y; a sphere when a = b)
/// with target edge length `h` [mm] (smaller where 12 elements per 2 pi radius of curvature need
/// it), through Gmsh's OpenCASCADE kernel: quarter arcs of the meridian ellipse (x >= 0, in the
/// x-y plane) swept about the y axis by quarter turns over the kept part, glued into one
/// conforming surface and meshed by Gmsh's default 2-D mesher. Nodes are then put exactly on the
/// surface by radial scaling, p <- p / sqrt(x^2/a^2 + y^2/b^2 + z^2/a^2); nodes on a cut plane
/// first get that coordinate set to exactly 0 (they are within round-off of it), which the
/// scaling keeps. `pole` refines about (0, b, 0) through a Gmsh Threshold field on the distance to
/// that point. Throws Error if Gmsh fails.
SurfaceTriangulation mesh_spheroid_surface(double a, double b, double h, Symmetry symmetry,
                                           const PoleRefinement& pole = {});

/// Appends the nodes (its boundary's included, by increasing Gmsh tag: the same order in every
/// process) and 3-node triangles Gmsh meshed on its surface entity `surface_tag` to `surface`;
/// `index` maps Gmsh node tags to the nodes already appended, so that entities glued along a curve
/// share its nodes. Call inside a GmshSession, after meshing.
void append_gmsh_triangles(int surface_tag, SurfaceTriangulation& surface,
                           std::unordered_map<std::size_t, int>& index);

/// Orients the triangles of `surface` along the surface normal `normal(p)` (Gmsh orients each
/// OpenCASCADE face on its own), then repairs triangles whose three corners lie on one cut plane
/// of `planes` (x = 0, y = 0, z = 0; coordinate exactly 0). A 2-D mesher can make those where the
/// cut curve bends strongly over one element, and prisms stacked on them would be flat. Each is
/// repaired by flipping the edge it shares with a non-flat neighbour: with the neighbour written
/// (c, a, d) along the normal and b the flat triangle's third corner, the pair becomes
/// (b, a, d), (d, c, b). A flip is kept only if both new triangles face along the normal (cosine
/// > 0.1, so the quadrilateral c, b, a, d is convex) and neither is flat; throws Error if a flat
/// triangle cannot be repaired.
void orient_and_repair_surface(SurfaceTriangulation& surface, const std::array<bool, 3>& planes,
                               const std::function<Vec3d(const Vec3d&)>& normal);

/// Area of the full oblate spheroid (a >= b) [mm^2]:
///   A = 2 pi a^2 (1 + (1 - e^2)/e atanh e),  e^2 = 1 - b^2/a^2   (4 pi a^2 when e = 0).
double spheroid_area(double a, double b);

/// Estimated number of triangles `mesh_spheroid_surface(a, b, h, symmetry, pole)` makes: the
/// integral over the kept part of 1 / (sqrt(3)/4 s^2), with the element size
/// s = min(h, 2 pi rho / 12, the pole's size there) and rho the smaller principal radius of
/// curvature, by a midpoint rule along the meridian (x = a cos t, y = b sin t; area element
/// x ds times the kept azimuth). Within about 30 % of Gmsh's counts.
double estimate_spheroid_triangles(double a, double b, double h, Symmetry symmetry,
                                   const PoleRefinement& pole = {});

/// Fraction of a body symmetric about the three coordinate planes that `symmetry` keeps
/// (1, 1/2, 1/4, 1/8).
double kept_fraction(Symmetry symmetry);

}  // namespace plisse
