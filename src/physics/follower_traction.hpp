#pragma once
/// Follower traction on a tagged surface: a normal component along the deformed outward normal and
/// a shear component along the projection of a fixed direction onto the deformed surface, both per
/// unit deformed area, with their consistent load stiffness (docs/theory/loads.md, L14-L16).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "mesh/surface_ref.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"
#include "physics/ramp.hpp"
#include "physics/surface.hpp"

namespace plisse {

/// A `loads:` entry of type follower-traction, as the case file gives it
/// (terms/follower_traction.cpp): a non-zero normal or shear, and a direction with a shear.
struct FollowerTractionSettings {
  std::string name;                ///< history columns `load_x:<name>` ...
  SurfaceRef surface;              ///< the loaded surface
  double normal = 0.0;             ///< [MPa] per unit deformed area along the outward normal
  double shear = 0.0;              ///< [MPa] per unit deformed area along `direction`'s projection
  std::optional<Vec3d> direction;  ///< normalised; required with a shear
  Ramp ramp;
  InputPlace place;
};

/// What a follower traction applies at the end of its ramp.
struct FollowerTractionValues {
  double normal = 0.0;               ///< [MPa] along the outward normal n (−pressure)
  double shear = 0.0;                ///< [MPa] along s, the unit projection of `direction`
  Vec3d direction = Vec3d::UnitX();  ///< unit vector; s = (d − (d·n) n) / |d − (d·n) n|
};

/// Below this |d − (d·n) n| the direction is taken as normal to the surface: the shear has no
/// direction there and is not applied (L16).
inline constexpr double kShearDirectionTolerance = 1e-6;

/// The external force of a follower traction on one face with deformed nodes `xs` (3 or 6 nodes,
/// corners first, outward oriented): f_a = ∫ N_a (σ a + τ |a| s) dξ dη with a = x_ξ × x_η (L14),
/// and when `k` is not null its derivative K_ab = ∂f_a/∂x_b (L15) into the row-major
/// 3n x 3n block `k`. `f` has 3n entries (node-major). A 3-node face is integrated exactly by its
/// centroid, a 6-node face by the degree-4 rule.
void follower_traction_face(const FollowerTractionValues& v, double factor,
                            std::span<const Vec3d> xs, std::span<double> f, double* k);

class FollowerTraction : public ModelTerm {
 public:
  /// Borrows `mesh`. `constraints` decide, for a purely normal traction, whether the load
  /// stiffness is symmetric (pressure_stiffness_is_symmetric); with a shear it is not.
  FollowerTraction(const Mesh& mesh, std::string name, const std::string& surface,
                   const FollowerTractionValues& values, Ramp ramp,
                   const std::vector<ConstrainedComponent>& constraints);

  bool symmetric() const override { return symmetric_; }
  void assemble(double t, std::span<const double> x, std::span<double> residual,
                TangentSink* tangent) override;
  void accept_step(std::span<const double> x) override;
  void reject_step() override { t_current_ = t_accepted_; }
  std::vector<double> save_state() const override;
  /// Restores save_state(); plisse::Error when its size does not fit or a value is not finite.
  void load_state(std::span<const double> state) override;
  /// `load_x:<name>` ... (the resultant ∫ t da on the deformed surface [N]) and `work:<name>`.
  std::vector<std::string> history_columns() const override;
  std::vector<double> history_values(double t, std::span<const double> x) const override;

 private:
  /// The external nodal forces at (t, x), by loaded node (nodes_ order).
  std::vector<Vec3d> nodal_forces(double t, std::span<const double> x) const;
  /// W at x, whose nodal forces are `forces` (nodal_forces), after the last accepted step:
  /// W_n + ½ Σ (f_n + f) · (u − u_n)   (L16).
  double work(const std::vector<Vec3d>& forces, std::span<const double> x) const;

  const Mesh& mesh_;
  std::string name_;
  std::vector<SurfaceFace> faces_;
  std::vector<int> nodes_;            ///< the loaded nodes, sorted
  std::vector<int> face_node_index_;  ///< per face and node: index into nodes_
  FollowerTractionValues values_;
  Ramp ramp_;
  bool symmetric_;
  double t_current_ = 0.0, t_accepted_ = 0.0, work_ = 0.0;
  std::vector<Vec3d> u_accepted_, f_accepted_;  ///< at the last accepted step, by loaded node
};

}  // namespace plisse
