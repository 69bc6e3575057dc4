#pragma once
/// Dead loads given as forces on nodes: a surface traction per unit undeformed area, a total force
/// spread over a surface, a concentrated force on one node (docs/theory/loads.md, L11-L13). Their
/// nodal forces are fixed vectors scaled by a ramp, so they add nothing to the tangent.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "mesh/surface_ref.hpp"
#include "physics/model_term.hpp"
#include "physics/ramp.hpp"
#include "physics/surface.hpp"

namespace plisse {

/// A `loads:` entry of type traction, as the case file gives it (terms/traction_load.cpp): exactly
/// one of `traction` and `force`.
struct TractionLoadSettings {
  std::string name;               ///< history columns `load_x:<name>` ...
  SurfaceRef surface;             ///< the loaded surface
  std::optional<Vec3d> traction;  ///< [MPa] per unit undeformed area, non-zero
  std::optional<Vec3d> force;     ///< [N] in total, spread in proportion to undeformed area
  Ramp ramp;
  InputPlace place;
};

/// A `loads:` entry of type point-force, as the case file gives it (terms/point_force.cpp).
struct PointForceSettings {
  std::string name;             ///< history columns `load_x:<name>` ...
  std::optional<Vec3d> force;   ///< [N] on the node nearest `point`, non-zero; required
  Vec3d point = Vec3d::Zero();  ///< [mm], a point of the undeformed body
  InputPlace point_place;       ///< where `point` is written
  Ramp ramp;
  InputPlace place;
};

/// The consistent nodal areas ∫ N_a dA [mm^2] of the nodes of `faces` on the undeformed mesh
/// (loads.md, L11): A_e / 3 per corner of a 3-node face; for a 6-node face the degree-4 rule on
/// |X_ξ × X_η| (on a straight face 0 per corner and A_e / 3 per edge node). Pairs (node, area),
/// sorted by node; the areas sum to the area of the surface.
std::vector<std::pair<int, double>> consistent_nodal_areas(const Mesh& mesh,
                                                           const std::vector<SurfaceFace>& faces);

/// One node's share of a dead load.
struct NodalForce {
  int node = 0;
  Vec3d force = Vec3d::Zero();  ///< [N] at the end of the ramp
};

/// The nodal forces of the dead traction `traction` [MPa] on `faces`: f_a = T ∫ N_a dA (L11).
std::vector<NodalForce> traction_forces(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                                        const Vec3d& traction);

/// The nodal forces that spread the total force `force` [N] over `faces` in proportion to
/// undeformed area: the traction force / A (L12); they sum to `force`. Throws plisse::Error when
/// the faces have no area.
std::vector<NodalForce> total_force(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                                    const Vec3d& force);

/// Fixed nodal forces scaled by a ramp: external force λ(t) f_a on node a. History columns
/// `load_x:<name>`, `load_y:<name>`, `load_z:<name>` (the applied total λ Σ f_a [N]) and
/// `work:<name>` (the work done on the body since t = 0 [N mm = mJ], by the trapezoidal rule over
/// the accepted steps, L13: exact while the ramp is constant or the response linear in λ).
class DeadLoad : public ModelTerm {
 public:
  DeadLoad(std::string name, std::vector<NodalForce> forces, Ramp ramp);

  void assemble(double t, std::span<const double> x, std::span<double> residual,
                TangentSink* tangent) override;
  void accept_step(std::span<const double> x) override;
  void reject_step() override { t_current_ = t_accepted_; }
  std::vector<double> save_state() const override;
  /// Restores save_state(); plisse::Error when the state has not 3 finite values.
  void load_state(std::span<const double> state) override;
  std::vector<std::string> history_columns() const override;
  std::vector<double> history_values(double t, std::span<const double> x) const override;

  /// Σ f_a [N]: the total at the end of the ramp.
  Vec3d total() const { return total_; }

 private:
  /// S(x) = Σ f_a · u_a [N mm]: the work of the full load over the displacement x.
  double projected_displacement(std::span<const double> x) const;
  /// W at (t, x) after the last accepted step (L13).
  double work(double t, std::span<const double> x) const;

  std::string name_;
  std::vector<NodalForce> forces_;
  Ramp ramp_;
  Vec3d total_ = Vec3d::Zero();
  double t_current_ = 0.0;   ///< time of the last assembly: the step being solved
  double t_accepted_ = 0.0;  ///< time of the last accepted step
  double s_accepted_ = 0.0;  ///< S at the last accepted step
  double work_ = 0.0;        ///< W at the last accepted step
};

}  // namespace plisse
