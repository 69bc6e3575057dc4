#include "element/strain_energy.hpp"

#include <variant>

namespace plisse::mini {

StrainEnergy compute_strain_energy(const TetGeometry& g, const ElemVec& x_e,
                                   const AnyMaterial& material, double inverse_bulk_modulus,
                                   const BubbleVec& bubble) {
  return std::visit(
      [&](const auto& model) {
        return compute_strain_energy(g, x_e, model, inverse_bulk_modulus, bubble);
      },
      material);
}

}  // namespace plisse::mini
