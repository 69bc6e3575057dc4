#pragma once
/// Structured tetrahedral mesh of a thin-walled open tube (tube generator: the air beam), and its
/// mid-surface as a shell.
#include <vector>

#include "mesh/mesh.hpp"

namespace plisse {

/// Number of element divisions about the axis of a tube of mid radius `radius` [mm] with target
/// element size `h` [mm]: round(pi radius / h), at least 3, for the half tube; twice that for the
/// full one, so the two meshes have the same nodes on z >= 0.
int tube_divisions_around(double radius, double h, bool half);

/// The stations x_0 = 0 < x_1 < ... < x_N = `length` [mm] of a tube's cells along its axis.
/// Uniform, N = round(length / h) (at least 1), when `end_h` is 0. Otherwise graded from the end x
/// = 0: the cell length follows h(x) = end_h + (h - end_h) min(x / end_length, 1), N =
/// round(Phi(L)) with Phi(x) = the integral of 1 / h from 0 to x, and x_i solves Phi(x_i) = i
/// Phi(L) / N (closed forms: Phi = ln(h(x) / end_h) / g with g = (h - end_h) / end_length over the
/// grading, then linear), so the cells grow smoothly from about end_h to about h (docs/meshes.md).
std::vector<double> tube_stations(double length, double h, double end_h = 0.0,
                                  double end_length = 0.0);

/// N of tube_stations, without making them (the generator's size estimate).
double tube_cells_along(double length, double h, double end_h = 0.0, double end_length = 0.0);

/// The tube whose axis is the x axis from x = 0 to x = `length` [mm], with the wall between the
/// cylinders r = radius - thickness/2 and r = radius + thickness/2 (r^2 = y^2 + z^2), the whole
/// tube or (`half`) its part z >= 0. Structured in (x, angle, r): round(length / h) divisions
/// along x (at least 1), tube_divisions_around(radius, h, half) about the axis (angle phi from +y
/// towards +z: y = r cos phi, z = r sin phi) and exactly `layers` through the wall; each cell cut
/// into 6 tetrahedra like the box (Kuhn), the same way in every cell, so the full tube closes on
/// itself conformingly. Corner nodes lie exactly on the layer cylinders, the end planes x = 0 and
/// x = length, and (half tube) z = 0.
/// Tags: `inner`, `outer` (the two cylinders), `left` (x = 0), `right` (x = length), and for the
/// half tube `sym_z` (z = 0). `order` 2 adds one node per edge on the true cylinders: at the mean
/// x, the mean radius of its two corners and the mean of their directions about the axis.
/// `stations`, when given, are the cells' stations along x instead (tube_stations).
Mesh make_tube_mesh(double radius, double length, double thickness, int layers, double h, bool half,
                    int order, std::vector<double> stations = {});

/// The shell mid-surface of the same tube: the cylinder r = `radius` [mm] from x = 0 to x =
/// `length`, whole or (`half`) z >= 0, on the grid of make_tube_mesh's layer cylinders (the same
/// divisions along x and about the axis, so its nodes are those of a solid layer of that radius),
/// each cell cut into two triangles by its diagonal from (x_i, phi_k) to (x_i+1, phi_k+1) and
/// numbered so that every normal points away from the axis. Nodes lie exactly on the cylinder
/// (y = r cos phi, z = r sin phi), on x = 0 and x = length, and (half tube) on z = 0.
/// Surface tags `inner` and `outer` both list every triangle (Mesh::shell_face_side -1 and +1);
/// edge tags `left` (x = 0), `right` (x = length) and, for the half tube, `sym_z` (z = 0).
/// `stations` as for make_tube_mesh.
Mesh make_tube_surface(double radius, double length, double h, bool half,
                       std::vector<double> stations = {});

}  // namespace plisse
