#pragma once
/// Body force rho g (dead load on the reference volume), e.g. gravity.
#include <vector>

#include "mesh/mesh.hpp"
#include "physics/model_term.hpp"
#include "physics/ramp.hpp"

namespace plisse {

class BodyForce : public ModelTerm {
 public:
  /// `force_density` = rho g [N/mm^3] at the end of `ramp`. The nodal forces are
  /// f_a = ∫ rho g N_a dV = rho g V_e / 4 per corner; the bubble's share ∫ rho g N_b dV is not
  /// applied (it changes the solution only within elements, at the order of the discretisation
  /// error).
  BodyForce(const Mesh& mesh, std::string name, const Vec3d& force_density, Ramp ramp);
  void assemble(double t, std::span<const double> x, std::span<double> residual,
                TangentSink* tangent) override;

 private:
  std::vector<double> nodal_volume_;  ///< sum of V_e / 4 over the elements of each node [mm^3]
  std::string name_;
  Vec3d force_density_;
  Ramp ramp_;
};

}  // namespace plisse
