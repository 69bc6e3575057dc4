#pragma once
/// A wall closed over the rigid caps that tie its rims: the gas in a capped tube pushes on the
/// caps as well (docs/theory/cavities.md, C14-C17). Shared by the cavity and the pressure load.
#include <array>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"
#include "physics/model_term.hpp"
#include "physics/surface.hpp"

namespace plisse {

/// A cap as a wall's closure sees it: its name and the nodes it ties.
struct CapNodes {
  std::string name;
  std::set<int> nodes;
};

/// One rim of a wall closed by a cap (C14): the wall's open edges whose nodes the cap all ties,
/// each in the direction of the wall's face, closed by the cone from the apex
///   x_c = K (1/n) sum_k x_k   over the rim's n distinct nodes,
/// K = diag(keep): 0 for each coordinate plane x_j = 0 an end of an open rim lies in (a half or
/// quarter model), so that the cone's sides from x_c to those ends lie in the planes.
struct CapClosure {
  std::string cap;                      ///< the cap's name
  std::vector<std::array<int, 3>> rim;  ///< edges (a, b, edge node or -1), as the face runs them
  std::vector<int> nodes;               ///< the rim's distinct nodes, sorted
  Vec3d keep = Vec3d::Ones();           ///< diagonal of K
};

/// How the caps close `faces`.
struct WallClosure {
  std::vector<CapClosure> caps;  ///< one per cap that ties a rim
  /// The first open edge that neither a symmetry plane (closing_planes) nor a cap closes, as a
  /// sorted node pair; or an end of a cap's rim that lies on no plane x_j = 0.
  std::optional<std::array<int, 2>> open_edge;
  int planes = 0;  ///< the planes that close the rest, as closing_planes' bits
};

/// Closes `faces` over `caps` (C14): every open edge whose nodes (corners and edge node) one of
/// `caps` ties joins that cap's rim, the first such cap in the list; the other open edges must lie
/// in a plane x = 0, y = 0 or z = 0 (cavities.md, C2). A cap that ties no rim is left out.
WallClosure close_over_caps(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                            const std::vector<CapNodes>& caps, double relative_tolerance = 1e-8);

/// The apex x_c of `closure` in the state `state` (C14).
Vec3d closure_apex(const Mesh& mesh, const CapClosure& closure, std::span<const double> state);

/// Six times the volume the closure's cone adds, with the sign of cavity_volume's faces (C15):
///   6 V_cap = sum over the rim's faces (x_c, x_b, x_a) of minus their cone volumes (C1, C12).
double closure_six_volume(const Mesh& mesh, const CapClosure& closure,
                          std::span<const double> state);

/// The volume [mm^3] enclosed by `faces` and the cones of `closures` in `state` (C1, C12, C15):
/// cavity_volume itself when there are no closures (the same operations, so the same bits).
double closed_volume(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                     const std::vector<CapClosure>& closures, std::span<const double> state);

/// Adds the follower pressure `p` on the closure's cone (C16): residual += the cone faces' nodal
/// forces (loads.md, L2 or L8) carried to the rim's nodes through the apex and the cone's edge
/// nodes, which are linear in them, and with `tangent` their load stiffness (L3 or L9) carried the
/// same way (a dense block over the rim's nodes). With pressure_dof >= 0 (a cavity's p_c) also the
/// border: the column d r_u / d p_c (the forces per unit pressure) and the row d r_p / d x =
/// -d V_cap / d x (C17). Adds the cone's 6 V_cap to six_volume.
void add_cap_closure(const Mesh& mesh, const CapClosure& closure, double p,
                     std::span<const double> state, std::span<double> residual,
                     TangentSink* tangent, int pressure_dof, double& six_volume);

/// The tangent's pairs of add_cap_closure: every rim node with every rim node (each component),
/// and with pressure_dof when it is >= 0.
void add_cap_closure_couplings(const CapClosure& closure, int pressure_dof,
                               std::vector<std::pair<int, int>>& pairs);

}  // namespace plisse
