#pragma once
/// Structured tetrahedral mesh of a box (cube and sheet generators), and the structured mid-plane
/// of the sheet as a shell.
#include <array>
#include <functional>

#include "core/types.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// [0, extent.x] x [0, extent.y] x [0, extent.z] with `cells` hexahedral cells per direction, each
/// cut into the 6 tetrahedra around its main diagonal (Kuhn / Freudenthal subdivision: tet
/// (a, b, c) for each permutation of the axes follows corner 000 -> +e_a -> +e_b -> +e_c = 111).
/// All cells are cut alike, so neighbouring cells share their face diagonals (conforming).
/// Nodes on the faces x = 0, x = extent.x etc. have that coordinate exactly.
/// Tags: left x = 0, right x = Lx, front y = 0, back y = Ly, bottom z = 0, top z = Lz, and
/// sym_x = left, sym_y = front, sym_z = bottom. All tetrahedra positive; 6 nx ny nz of them.
/// `order` 2 adds the straight edge midpoints as edge nodes (10-node tetrahedra, 6-node
/// triangles; add_straight_edge_nodes), which are exact for the flat-sided box.
Mesh make_box_mesh(const Vec3d& extent, const std::array<int, 3>& cells, int order = 1);

/// The shell mid-surface of a sheet: the rectangle [0, length] x [0, width] in the plane z = `z`
/// [mm] with cells[0] x cells[1] cells, each cut into two triangles by its diagonal from
/// (i, j) to (i + 1, j + 1) (the faces of make_box_mesh's Kuhn cells on a plane z = const),
/// numbered counter-clockwise seen from +z, so every normal is +z. Nodes are those of
/// make_box_mesh's plane of the same z (x = length i / nx, exactly length at i = nx; the same in
/// y). Surface tags `bottom` and `top` both list every triangle (Mesh::shell_face_side -1 and +1);
/// edge tags `left` = `sym_x` (x = 0), `right` (x = length), `front` = `sym_y` (y = 0), `back`
/// (y = width). The shell's thickness and neighbours are left to make_shell_surface.
Mesh make_rectangle_surface(double length, double width, double z, const std::array<int, 2>& cells);

/// Appends to `mesh.tets` the 6 Kuhn tetrahedra (above) of every cell of a structured grid of
/// cells[0] x cells[1] x cells[2] cells, cell (i, j, k) having the corner nodes
/// node(i + a, j + b, k + c), a, b, c in {0, 1}; `node` may wrap an index (a closed tube).
/// Odd permutations give negatively oriented tetrahedra: callers fix them with
/// orient_generated_tets.
void append_kuhn_tets(Mesh& mesh, const std::array<int, 3>& cells,
                      const std::function<int(int, int, int)>& node);

}  // namespace plisse
