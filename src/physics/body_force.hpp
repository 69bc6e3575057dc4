#pragma once
/// Body force rho g (dead load on the reference volume), e.g. gravity.
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "mesh/mesh.hpp"
#include "physics/model_term.hpp"
#include "physics/ramp.hpp"

namespace plisse {

/// A `loads:` entry of type gravity, as the case file gives it (terms/gravity_load.cpp).
struct GravityLoadSettings {
  std::string name;                    ///< history columns `load_x:<name>` ...
  Vec3d acceleration = Vec3d::Zero();  ///< [mm/s^2], e.g. [0, -9810, 0]
  Ramp ramp;
  InputPlace place;
};

/// The consistent nodal volumes ∫ N_a dV [mm^3] of every node (docs/theory/loads.md): V_e / 4 per
/// corner of a linear tetrahedron (L6; the MINI bubble's share is not applied), for a 10-node
/// tetrahedron the integrals of its quadratic shape functions with the isoparametric Jacobian
/// (L10: -V_e / 20 per corner and V_e / 5 per edge node of a straight one), and on the
/// mid-surface of a shell (Mesh::is_shell) A_e t_e / 3 per corner of each triangle, A_e its
/// reference area and t_e its Mesh::triangle_thickness (L6s). Indexed by node;
/// the sum is the volume of the mesh. Throws plisse::Error for an invalid 10-node tetrahedron.
/// With `element_weight` (one per element: per tetrahedron, or per triangle of a shell) each
/// element's integrals are multiplied by its weight: Σ_e w_e ∫_e N_a dV (a density per element
/// gives the nodal masses).
std::vector<double> consistent_nodal_volumes(const Mesh& mesh,
                                             const std::vector<double>& element_weight = {});

class BodyForce : public ModelTerm {
 public:
  /// `force_density` = rho g [N/mm^3] at the end of `ramp`. The nodal forces are
  /// f_a = ∫ rho g N_a dV = rho g V_a with the consistent nodal volumes V_a
  /// (consistent_nodal_volumes), on linear and on second-order meshes.
  /// With `element_scale` (one factor per element, tetrahedron or shell triangle, e.g. its
  /// density when `force_density` is the acceleration g) element e's force density is
  /// element_scale[e] * force_density.
  BodyForce(const Mesh& mesh, std::string name, const Vec3d& force_density, Ramp ramp,
            const std::vector<double>& element_scale = {});
  void assemble(double t, std::span<const double> x, std::span<double> residual,
                TangentSink* tangent) override;

 private:
  std::vector<double> nodal_volume_;  ///< ∫ N_a dV of each node [mm^3]
  std::string name_;
  Vec3d force_density_;
  Ramp ramp_;
};

}  // namespace plisse
