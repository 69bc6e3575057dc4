#pragma once
/// The materials of a model's elements: one model for the whole body, or several assigned by
/// volume tag (a fabric bag with a rubber bladder, a membrane on a stiffer base), and rigid
/// elements, which the assembly skips: their nodes move with a prescribed rigid motion (the model
/// builder constrains them), so they carry no unknowns of their own.
#include <cstddef>
#include <utility>
#include <vector>

#include "material/inelastic.hpp"
#include "material/registry.hpp"

namespace plisse {

struct ElementMaterials {
  /// The material index of a rigid element.
  static constexpr int kRigid = -1;

  /// The models, and their 1/κ [1/MPa] (0: exactly incompressible), index by index.
  std::vector<AnyMaterial> materials;
  std::vector<double> inverse_bulk_moduli;
  /// Per tetrahedron: its index into `materials`, or kRigid. Empty: every element has material 0.
  std::vector<int> of_element;
  /// Per tetrahedron: the region whose pressure unknowns it takes at the corners it shares with
  /// another region's tetrahedra (>= 0; negative for a rigid one), so that the pressure may jump
  /// between regions (solver/pressure_twins.hpp). Empty: one continuous pressure field. A shell
  /// has no pressure unknowns and ignores it.
  std::vector<int> pressure_region;
  /// The viscoelasticity and Mullins softening of each model, index by index (material/
  /// inelastic.hpp). Empty: every model is elastic.
  std::vector<InelasticLaw> laws;

  /// Every element of one material.
  static ElementMaterials uniform(AnyMaterial material, double inverse_bulk_modulus) {
    ElementMaterials m;
    m.materials.push_back(std::move(material));
    m.inverse_bulk_moduli.push_back(inverse_bulk_modulus);
    return m;
  }
  /// The material index of element e.
  int of(int e) const { return of_element.empty() ? 0 : of_element[static_cast<std::size_t>(e)]; }
  bool rigid(int e) const { return of(e) == kRigid; }
  /// The law of model m when its points carry history, else nullptr (elastic).
  const InelasticLaw* law(int m) const {
    if (m < 0 || static_cast<std::size_t>(m) >= laws.size()) return nullptr;
    const InelasticLaw& l = laws[static_cast<std::size_t>(m)];
    return l.elastic() ? nullptr : &l;
  }
  /// Doubles of history per quadrature point of model m's elements (0: elastic or rigid).
  int history_size(int m) const {
    const InelasticLaw* l = law(m);
    return l == nullptr ? 0 : l->history_size();
  }
};

}  // namespace plisse
