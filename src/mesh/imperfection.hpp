#pragma once
/// Geometric imperfections of the reference mesh, to seed wrinkling on purpose instead of by
/// numerical noise (docs/architecture.md, "Stability and wrinkling"; docs/theory/imperfections.md).
///
/// Both kinds give a displacement field d_j [mm] of the reference nodes with max_j |d_j| = a
/// exactly (a = the caller's relative amplitude x wall thickness):
///   random:  e_j = Π_j (ξ_k n_k),  k = k(j),   d_j = a e_j / max_l |e_l|                 (I1)
///            ξ_k in [-1, 1) seeded per outer-surface node k, n_k its outward area-weighted
///            unit normal, k(j) the outer-surface node nearest to node j in the reference mesh,
///            Π_j the projection that keeps node j in the symmetry planes it lies on;
///   mode:    d_j = a φ_j / max_l |φ_l|                                                  (I2)
/// The random field moves every node with its nearest outer node, so through-thickness columns
/// of a layered shell move rigidly: the wall keeps its thickness and the layers stay layers. On
/// the mid-surface of a shell (element: shell) the outer nodes are the surface's own nodes.
/// Applying a field re-runs the mesh check (mesh/quality.hpp) and refuses an amplitude that
/// inverts or degenerates an element.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// The seeded value in [-1, 1) of draw `k` of a std::mt19937_64 seeded with `seed`: the top 53
/// bits of the 64-bit output u give (u >> 11) 2^-52 - 1. std::uniform_real_distribution is not
/// used because its algorithm differs between standard libraries; this mapping is the same
/// everywhere, so a seed gives the same mesh on every platform.
double seeded_unit_value(std::uint64_t engine_output);

/// Nodes that must stay in a plane, given by the caller with the plane's normal: a shell's
/// symmetry edge, whose plane the mesh alone does not decide (the condition does,
/// shell_edge_plane_axis in physics/dirichlet.hpp). The component of d_j along `normal` is
/// removed at each of `nodes` (Π_j of I1).
struct HeldPlane {
  std::vector<int> nodes;        ///< node indices
  Vec3d normal = Vec3d::Zero();  ///< the plane's normal, any nonzero length (normalised here)
};

/// The random imperfection field (I1) [mm], one vector per mesh node.
///   outer_triangles: the outer surface (e.g. tag `outer`). On a solid mesh their orientation is
///     irrelevant (each is oriented by the tetrahedron it is a face of) and each must be a
///     boundary face of the mesh. On a shell mesh (mesh.is_shell()) they are mid-surface
///     triangles, taken in their own (consistent) orientation: their nodes are the outer nodes,
///     and every other node keeps d_j = 0 (imperfections.md, I1s).
///   amplitude: a [mm], > 0 and finite.
///   seed: draws are made in increasing order of the outer node index.
///   planar_tags: surface tags (e.g. symmetry planes sym_x, sym_z) whose nodes must stay in their
///     plane: the component of d_j along the plane's normal is removed at every node of the tag
///     before scaling. Each tag must be planar (checked: plisse::Error otherwise). Solid meshes
///     only: a shell's surface tags name its faces, not planes (use `held_planes`).
///   held_planes: nodes held in planes the caller names (a shell's symmetry edges), projected
///     after `planar_tags`, before scaling.
/// The nearest outer node is found on a uniform grid (O(n) expected); ties go to the lower index,
/// so the result does not depend on the search order. Throws plisse::Error on invalid input or
/// when the field vanishes (e.g. every outer node is on a plane of `planar_tags`).
std::vector<Vec3d> compute_random_imperfection(const Mesh& mesh,
                                               std::span<const std::array<int, 3>> outer_triangles,
                                               double amplitude, std::uint64_t seed,
                                               const std::vector<std::string>& planar_tags = {},
                                               const std::vector<HeldPlane>& held_planes = {});

/// The mode imperfection field (I2) [mm]: `shape` (one vector per node, any unit, e.g. the
/// `mode_1` point field of an earlier run) scaled so its largest nodal norm is `amplitude` [mm].
/// Throws plisse::Error when sizes differ, a value is not finite, or the shape is zero.
std::vector<Vec3d> compute_mode_imperfection(const Mesh& mesh, std::span<const Vec3d> shape,
                                             double amplitude);

/// X_j += d_j for every node, then checks the mesh (check_mesh). If the check fails (an element
/// inverted or degenerate), `mesh` is restored and plisse::Error is thrown: "imperfection
/// amplitude a = ... mm is too large for this mesh: ..." (for the caller to report as an
/// InputError at its imperfection key).
void apply_imperfection(Mesh& mesh, std::span<const Vec3d> displacement);

}  // namespace plisse
