#pragma once
/// The isochoric strain-energy density W(F) of any registered model, without its derivatives: for
/// the stored-energy output, which needs W alone.
#include "core/types.hpp"
#include "material/isochoric_invariants.hpp"

namespace plisse {

/// W(F) [MPa]: through (Ī1, Ī2) for the invariant models, from the model's own `energy_density`
/// otherwise (Ogden's principal stretches). Throws InadmissibleDeformation if det F <= 0 or the
/// model rejects F.
template <class Model>
double compute_energy_density(const Model& model, const Mat3d& F) {
  if constexpr (requires { model.invariant_derivatives(3.0, 3.0); }) {
    const IsochoricKinematics k = compute_isochoric_kinematics(F);
    return model.invariant_derivatives(k.I1bar, k.I2bar).W;
  } else {
    return model.energy_density(F);
  }
}

}  // namespace plisse
