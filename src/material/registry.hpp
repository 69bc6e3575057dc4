#pragma once
/// The material registry: the only map from input-file model names to model types, with each
/// model's formula and declared parameters (name, range, unit, help, default) and the rules that
/// tie parameters together (docs/architecture.md, "Coding conventions"). The same table validates
/// input, builds models, feeds `plisse materials` and generates docs/materials.md, so code, input
/// and manual agree.
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "core/parameter.hpp"
#include "material/arruda_boyce.hpp"
#include "material/fibre_reinforced.hpp"
#include "material/fung.hpp"
#include "material/gent.hpp"
#include "material/mooney_rivlin.hpp"
#include "material/neo_hookean.hpp"
#include "material/ogden.hpp"
#include "material/yeoh.hpp"

namespace plisse {

/// Every model; element code picks the alternative once per element block with std::visit.
using AnyMaterial =
    std::variant<NeoHookean, MooneyRivlin, Fung, Yeoh, Gent, ArrudaBoyce, Ogden, FibreReinforced>;

/// Parameter values by input key, e.g. {"c1": 0.0033}.
using MaterialValues = std::map<std::string, double>;

/// One broken rule. key: the input key to blame ("model" for an unknown model, else a parameter
/// name); rule: the rule in words with the offending values, e.g. "must be > 0 (got -1)".
struct ParamViolation {
  std::string key;
  std::string rule;
};

/// A rule between parameters, checked once every parameter is present and in range.
struct CrossRule {
  std::string key;                    ///< parameter the violation is reported against
  std::string statement;              ///< e.g. "c1 + c2 must be > 0"
  std::vector<std::string> involves;  ///< parameters whose values the message quotes
  std::function<bool(const MaterialValues&)> holds;  ///< gets every parameter (defaults filled in)
};

/// A registered model.
struct MaterialModelInfo {
  std::string name;           ///< input-file name, e.g. "mooney-rivlin"
  std::string formula;        ///< W in one line, in the isochoric invariants
  std::string shear_modulus;  ///< small-strain shear modulus in words, e.g. "mu = 2 (c1 + c2)"
  std::string reference;      ///< source of the formula
  std::string note;           ///< remarks on admissibility or domain; may be empty
  std::vector<ParamSpec> params;
  std::vector<CrossRule> rules;
  /// W(F Q) = W(F) for every rotation Q: what `plisse fit` and the Drucker watch of a run assume.
  bool isotropic = true;
  std::size_t variant_index = 0;  ///< index of the model's alternative in AnyMaterial
  /// Builds the model from complete values (every parameter present, defaults filled in).
  std::function<AnyMaterial(const MaterialValues&)> make;
};

/// All registered models, in documentation order. Built once; safe to call concurrently.
const std::vector<MaterialModelInfo>& material_models();

/// The model called `name`, or nullptr.
const MaterialModelInfo* find_material_model(const std::string& name);

/// Every problem with `values` for `model`: unknown model, unknown key, missing required key,
/// non-finite or out-of-range value, broken cross rule (checked only when all values are valid).
/// Empty when the model can be built.
std::vector<ParamViolation> validate_material(const std::string& model,
                                              const MaterialValues& values);

/// The model with the given parameters; omitted optional parameters take their defaults.
/// Precondition: validate_material(model, values) is empty; throws plisse::Error listing the
/// violations otherwise.
AnyMaterial make_material(const std::string& model, const MaterialValues& values);

/// The model with the given parameters without checking the registry's ranges and rules (omitted
/// optional parameters take their defaults): for a fitted set that breaks a rule, to draw it.
/// Throws plisse::Error for an unknown model or a missing required parameter.
AnyMaterial make_material_unchecked(const std::string& model, const MaterialValues& values);

/// Small-strain shear modulus of any model [MPa] (materials.md, M13).
double shear_modulus(const AnyMaterial& material);

/// The registered model name of the alternative held, e.g. "neo-hookean".
std::string material_name(const AnyMaterial& material);

/// The text of docs/materials.md (what `plisse materials --markdown` prints).
std::string materials_markdown();

}  // namespace plisse
