#include "material/registry.hpp"

#include <limits>
#include <optional>
#include <sstream>
#include <utility>

#include "core/error.hpp"

namespace plisse {
namespace {

std::string number(double v) {  // same format as core/parameter.cpp, so messages read alike
  std::ostringstream out;
  out.precision(12);
  out << v;
  return out.str();
}

/// A declared parameter bound to the model member it sets.
template <class Model>
struct BoundParam {
  ParamSpec spec;
  double Model::*member;
};

template <class Model>
BoundParam<Model> param(std::string name, double Model::*member, Range range, std::string unit,
                        std::string help, std::optional<double> default_value = std::nullopt) {
  return {ParamSpec{std::move(name), range, std::move(unit), std::move(help), default_value},
          member};
}

struct ModelText {
  std::string name, formula, shear_modulus, reference, note;
};

template <class Model>
MaterialModelInfo add(ModelText text, std::vector<BoundParam<Model>> params,
                      std::vector<CrossRule> rules = {}) {
  MaterialModelInfo info;
  info.name = std::move(text.name);
  info.formula = std::move(text.formula);
  info.shear_modulus = std::move(text.shear_modulus);
  info.reference = std::move(text.reference);
  info.note = std::move(text.note);
  for (const auto& p : params) info.params.push_back(p.spec);
  info.rules = std::move(rules);
  info.variant_index = AnyMaterial(std::in_place_type<Model>).index();
  if constexpr (requires { Model::kIsotropic; }) info.isotropic = Model::kIsotropic;
  info.make = [params](const MaterialValues& values) {
    Model model;
    for (const auto& p : params) model.*(p.member) = values.at(p.spec.name);
    return AnyMaterial(model);
  };
  return info;
}

std::vector<MaterialModelInfo> register_materials() {
  std::vector<MaterialModelInfo> models;
  models.push_back(add<NeoHookean>(
      {"neo-hookean", "W = c1 (Ī1 - 3)", "mu = 2 c1", "paper (Daanouni et al. 2009), Table 1", ""},
      {param("c1", &NeoHookean::c1, Range::positive(), "MPa",
             "Ī1 coefficient, half the shear modulus")}));
  models.push_back(add<MooneyRivlin>(
      {"mooney-rivlin", "W = c1 (Ī1 - 3) + c2 (Ī2 - 3)", "mu = 2 (c1 + c2)",
       "paper (Daanouni et al. 2009), Table 1 and eq. 7",
       "In incompressible uniaxial tension sigma = 2 (λ² - 1/λ)(c1 + c2/λ): c1 < 0 would soften at "
       "large stretch and is refused; c2 < 0, as fits to test data often give (plisse fit), "
       "softens in compression and is accepted with c1 + c2 > 0: a run logs the stretches over "
       "which the set is stable and warns when an element leaves them, since a material "
       "instability would be mistaken for wrinkling."},
      {param("c1", &MooneyRivlin::c1, Range::non_negative(), "MPa", "Ī1 coefficient"),
       param("c2", &MooneyRivlin::c2, Range::any(), "MPa",
             "Ī2 coefficient (< 0: stable over a limited range of stretch)")},
      {CrossRule{"c1", "c1 + c2 must be > 0", {"c1", "c2"}, [](const MaterialValues& v) {
                   return v.at("c1") + v.at("c2") > 0.0;
                 }}}));
  models.push_back(
      add<Fung>({"fung", "W = mu / (2 gamma) (exp(gamma (Ī1 - 3)) - 1)", "mu",
                 "paper (Daanouni et al. 2009), Table 1", ""},
                {param("mu", &Fung::mu, Range::positive(), "MPa", "small-strain shear modulus"),
                 param("gamma", &Fung::gamma, Range::positive(), "-",
                       "exponential stiffening coefficient")}));
  models.push_back(add<Yeoh>(
      {"yeoh", "W = c1 (Ī1 - 3) + c2 (Ī1 - 3)^2 + c3 (Ī1 - 3)^3", "mu = 2 c1",
       "Yeoh, Rubber Chem. Technol. 66 (1993) 754",
       "dW/dĪ1 = c1 + 2 c2 x + 3 c3 x^2 must stay positive for all x = Ī1 - 3 >= 0; a negative "
       "c2 is allowed when c2^2 < 3 c1 c3."},
      {param("c1", &Yeoh::c1, Range::positive(), "MPa",
             "linear coefficient, half the shear modulus"),
       param("c2", &Yeoh::c2, Range::any(), "MPa", "quadratic coefficient", 0.0),
       param("c3", &Yeoh::c3, Range::non_negative(), "MPa", "cubic coefficient", 0.0)},
      {CrossRule{"c2",
                 "c2 must be >= 0 or c2^2 < 3 c1 c3 (dW/dĪ1 > 0 for all Ī1 >= 3)",
                 {"c1", "c2", "c3"},
                 [](const MaterialValues& v) {
                   const double c1 = v.at("c1"), c2 = v.at("c2"), c3 = v.at("c3");
                   return c2 >= 0.0 || c2 * c2 < 3.0 * c1 * c3;
                 }}}));
  models.push_back(add<Gent>(
      {"gent", "W = -mu jm / 2 ln(1 - (Ī1 - 3) / jm)", "mu",
       "Gent, Rubber Chem. Technol. 69 (1996) 59",
       "Defined for Ī1 - 3 < jm only: a trial state at or past the limit makes the evaluation "
       "throw "
       "an inadmissible-deformation solver error (the step is rejected), never a silent NaN. "
       "jm -> infinity gives neo-Hookean with c1 = mu/2."},
      {param("mu", &Gent::mu, Range::positive(), "MPa", "small-strain shear modulus"),
       param("jm", &Gent::jm, Range::positive(), "-", "limit of Ī1 - 3 (chain extensibility)")}));
  models.push_back(add<ArrudaBoyce>(
      {"arruda-boyce",
       "W = mu sum_{i=1..5} alpha_i lambda_m^(2-2i) (Ī1^i - 3^i), "
       "alpha = (1/2, 1/20, 11/1050, 19/7000, 519/673750)",
       "mu (1 + 3/(5 lambda_m^2) + 99/(175 lambda_m^4) + 513/(875 lambda_m^6) + "
       "42039/(67375 lambda_m^8))",
       "Arruda & Boyce, J. Mech. Phys. Solids 41 (1993) 389 (five-term series)",
       "The five-term series is a polynomial in Ī1: it does not lock at lambda_m."},
      {param("mu", &ArrudaBoyce::mu, Range::positive(), "MPa",
             "network modulus (the shear modulus is slightly larger, see above)"),
       param("lambda_m", &ArrudaBoyce::lambda_m,
             Range{1.0, std::numeric_limits<double>::infinity(), true, true},  // > 1
             "-", "locking stretch of the chains")}));
  // Ogden's condition per term: μ_p α_p > 0, or μ_p = α_p = 0 for an absent term.
  const auto ogden_term_rule = [](const std::string& n, bool optional) {
    const std::string mu = "mu" + n, alpha = "alpha" + n;
    return CrossRule{alpha,
                     mu + " " + alpha + " must be > 0" +
                         (optional ? " (Ogden's condition), or both 0 to leave term " + n + " out"
                                   : " (Ogden's condition)"),
                     {mu, alpha},
                     [mu, alpha, optional](const MaterialValues& v) {
                       const double m = v.at(mu), a = v.at(alpha);
                       return m * a > 0.0 || (optional && m == 0.0 && a == 0.0);
                     }};
  };
  models.push_back(add<Ogden>(
      {"ogden",
       "W = Σ_p mu_p / alpha_p (λ̄1^alpha_p + λ̄2^alpha_p + λ̄3^alpha_p - 3), p = 1..3, "
       "λ̄_a = J^(-1/3) λ_a",
       "mu = (mu1 alpha1 + mu2 alpha2 + mu3 alpha3) / 2",
       "Ogden, Proc. R. Soc. Lond. A 326 (1972) 565",
       "A function of the principal stretches, not of Ī1 and Ī2: stress and tangent come from the "
       "principal directions of C, exact where stretches coincide (docs/theory/materials.md, "
       "O1-O7). Terms 2 and 3 are optional. alpha1 = 2 alone is neo-Hookean with c1 = mu1/2; "
       "alpha1 = 2 with alpha2 = -2 is Mooney-Rivlin with c1 = mu1/2, c2 = -mu2/2. Ogden's 1972 "
       "fit to Treloar's rubber: mu = 0.618, 0.00118, -0.00981 MPa with alpha = 1.3, 5, -2 "
       "(examples/balloon-ogden.yaml)."},
      {param("mu1", &Ogden::mu1, Range::any(), "MPa", "coefficient of term 1"),
       param("alpha1", &Ogden::alpha1, Range::any(), "-", "exponent of term 1"),
       param("mu2", &Ogden::mu2, Range::any(), "MPa", "coefficient of term 2", 0.0),
       param("alpha2", &Ogden::alpha2, Range::any(), "-", "exponent of term 2", 0.0),
       param("mu3", &Ogden::mu3, Range::any(), "MPa", "coefficient of term 3", 0.0),
       param("alpha3", &Ogden::alpha3, Range::any(), "-", "exponent of term 3", 0.0)},
      {ogden_term_rule("1", false), ogden_term_rule("2", true), ogden_term_rule("3", true)}));
  const auto not_zero = [](std::string n) {
    return CrossRule{n + "_x",
                     "the fibre direction (" + n + "_x, " + n + "_y, " + n + "_z) must not be zero",
                     {n + "_x", n + "_y", n + "_z"},
                     [n](const MaterialValues& v) {
                       return v.at(n + "_x") != 0.0 || v.at(n + "_y") != 0.0 ||
                              v.at(n + "_z") != 0.0;
                     }};
  };
  models.push_back(add<FibreReinforced>(
      {"fibre-reinforced",
       "W = c1 (Ī1 - 3) + Σ_f k1 / (2 k2) (exp(k2 (Ī4f - 1)²) - 1) over the families with "
       "Ī4f > 1, Ī4f = J^(-2/3) a_f · C a_f",
       "mu = 2 c1 (the fibres add nothing at F = I)",
       "Holzapfel, Gasser & Ogden, J. Elasticity 61 (2000) 1, eq. 4.3",
       "For woven fabrics and reinforced membranes: one or two fibre families, each a constant "
       "direction of the reference configuration (normalised by plisse), carrying load in "
       "extension only. Not isotropic, so `plisse fit` and the run's Drucker watch leave it out. "
       "k2 = 0 gives fibres of quadratic energy k1 (Ī4 - 1)² / 2 (docs/theory/materials.md, "
       "F1-F5)."},
      {param("c1", &FibreReinforced::c1, Range::positive(), "MPa",
             "matrix (neo-Hookean) coefficient, half the shear modulus"),
       param("k1", &FibreReinforced::k1, Range::non_negative(), "MPa", "fibre stiffness"),
       param("k2", &FibreReinforced::k2, Range::non_negative(), "-", "fibre stiffening", 0.0),
       param("a1_x", &FibreReinforced::a1_x, Range::any(), "-", "first fibre direction, x", 0.0),
       param("a1_y", &FibreReinforced::a1_y, Range::any(), "-", "first fibre direction, y", 0.0),
       param("a1_z", &FibreReinforced::a1_z, Range::any(), "-", "first fibre direction, z", 0.0),
       param("a2_x", &FibreReinforced::a2_x, Range::any(), "-",
             "second fibre direction, x (all three 0: one family)", 0.0),
       param("a2_y", &FibreReinforced::a2_y, Range::any(), "-", "second fibre direction, y", 0.0),
       param("a2_z", &FibreReinforced::a2_z, Range::any(), "-", "second fibre direction, z", 0.0)},
      {not_zero("a1")}));
  return models;
}

}  // namespace

const std::vector<MaterialModelInfo>& material_models() {
  static const std::vector<MaterialModelInfo> models = register_materials();
  return models;
}

const MaterialModelInfo* find_material_model(const std::string& name) {
  for (const auto& m : material_models()) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

std::vector<ParamViolation> validate_material(const std::string& model,
                                              const MaterialValues& values) {
  std::vector<ParamViolation> out;
  const MaterialModelInfo* info = find_material_model(model);
  if (info == nullptr) {
    std::string known;
    for (const auto& m : material_models()) known += (known.empty() ? "" : ", ") + m.name;
    out.push_back({"model", "unknown material model '" + model + "' (known: " + known + ")"});
    return out;
  }
  std::string names;
  for (const auto& p : info->params) names += (names.empty() ? "" : ", ") + p.name;
  for (const auto& [key, value] : values) {
    bool known = false;
    for (const auto& p : info->params) known = known || p.name == key;
    if (!known)
      out.push_back(
          {key, "unknown parameter for model '" + model + "' (parameters: " + names + ")"});
  }
  MaterialValues complete;
  bool all_valid = out.empty();
  for (const auto& p : info->params) {
    const auto it = values.find(p.name);
    if (it == values.end()) {
      if (p.default_value) {
        complete[p.name] = *p.default_value;
        continue;
      }
      out.push_back({p.name, "required by model '" + model + "' but missing (" + p.unit + ", " +
                                 p.range.describe() + ": " + p.help + ")"});
      all_valid = false;
      continue;
    }
    if (const auto broken = p.range.violation(it->second)) {
      out.push_back({p.name, *broken});
      all_valid = false;
      continue;
    }
    complete[p.name] = it->second;
  }
  if (!all_valid) return out;
  for (const auto& rule : info->rules) {
    if (rule.holds(complete)) continue;
    std::string got;
    for (const auto& name : rule.involves)
      got += (got.empty() ? "" : ", ") + name + " = " + number(complete.at(name));
    out.push_back({rule.key, rule.statement + " (got " + got + ")"});
  }
  return out;
}

AnyMaterial make_material(const std::string& model, const MaterialValues& values) {
  const std::vector<ParamViolation> violations = validate_material(model, values);
  if (!violations.empty()) {
    std::string msg = "invalid parameters for material model '" + model + "':";
    for (const auto& v : violations) msg += " " + v.key + ": " + v.rule + ";";
    msg.pop_back();
    throw Error(msg);
  }
  const MaterialModelInfo& info = *find_material_model(model);
  MaterialValues complete = values;
  for (const auto& p : info.params) {
    if (p.default_value) complete.emplace(p.name, *p.default_value);
  }
  return info.make(complete);
}

AnyMaterial make_material_unchecked(const std::string& model, const MaterialValues& values) {
  const MaterialModelInfo* info = find_material_model(model);
  if (info == nullptr) throw Error("unknown material model '" + model + "'");
  MaterialValues complete = values;
  for (const auto& p : info->params) {
    if (p.default_value) complete.emplace(p.name, *p.default_value);
    if (complete.find(p.name) == complete.end())
      throw Error("material model '" + model + "': parameter " + p.name + " missing");
  }
  return info->make(complete);
}

double shear_modulus(const AnyMaterial& material) {
  return std::visit([](const auto& m) { return m.shear_modulus(); }, material);
}

std::string material_name(const AnyMaterial& material) {
  for (const auto& m : material_models()) {
    if (m.variant_index == material.index()) return m.name;
  }
  throw Error("internal error: material alternative without a registry entry");
}

std::string materials_markdown() {
  std::ostringstream md;
  md << "# Material models\n\n"
     << "<!-- Generated by `plisse materials --markdown` from src/material/registry.cpp; do not "
        "edit:\n"
     << "     a unit test fails when this file and the registry disagree. -->\n\n"
     << "Isotropic hyperelastic models for incompressible or nearly incompressible membranes. "
        "Each\n"
     << "model gives the isochoric part of the strain energy: W(Ī1, Ī2), with Ī1 = J^(-2/3) I1 "
        "and\n"
     << "Ī2 = J^(-4/3) I2 the invariants of C = FᵀF with the volume change removed, or (Ogden) "
        "W of\n"
     << "the principal stretches with the volume change removed, λ̄_a = J^(-1/3) λ_a; the "
        "pressure\n"
     << "term -p J F⁻ᵀ belongs to the mixed element, not to the material. Stresses and tangents "
        "are\n"
     << "derived from W in shared code: see [theory/materials.md](theory/materials.md).\n\n"
     << "Units: mm, MPa, s, tonne/mm³. In a case file the model goes under `material:` with its\n"
     << "name as `model:` and its parameters as keys, for example\n\n"
     << "```yaml\nmaterial: {model: mooney-rivlin, c1: 0.0030, c2: 0.0003}\n```\n\n"
     << "A parameter without a default is required; values must be finite and within the range "
        "shown.\n"
     << "`plisse materials` prints the same table in the terminal.\n";
  md << "\nEvery model can also take **viscoelasticity** (`viscoelastic:`, a Prony series of up to "
        "three\n"
     << "Maxwell elements on the isochoric stress, the model being the long-term response) and "
        "**Mullins\n"
     << "softening** (`mullins:`, Ogden & Roxburgh's stress softening below the largest energy "
        "reached),\n"
     << "alone or together, for example\n\n"
     << "```yaml\nmaterial:\n  model: neo-hookean\n  c1: 0.25\n"
     << "  viscoelastic: {beta1: 0.8, tau1: 0.5, beta2: 0.3, tau2: 4.0}   # tau in s\n"
     << "  mullins: {r: 2.0, m: 0.05, beta: 0.1}\n```\n\n"
     << "Their keys are in [case-file.md](case-file.md) (`material` section), their equations in\n"
     << "[theory/materials.md](theory/materials.md) (V1-V7, MR1-MR6); "
        "`examples/cube-relaxation-viscoelastic.yaml`\n"
     << "and `examples/cube-cycles-mullins.yaml` show them against closed forms. "
        "`plisse fit` fits the\n"
     << "elastic models only.\n";
  for (const auto& m : material_models()) {
    md << "\n## " << m.name << "\n\n"
       << m.formula << "\n\n"
       << "- small-strain shear modulus: " << m.shear_modulus << "\n"
       << "- reference: " << m.reference << "\n";
    for (const auto& r : m.rules) md << "- rule: " << r.statement << "\n";
    if (!m.note.empty()) md << "- note: " << m.note << "\n";
    md << "\n| key | unit | range | default | meaning |\n|---|---|---|---|---|\n";
    for (const auto& p : m.params) {
      md << "| `" << p.name << "` | " << p.unit << " | " << p.range.describe() << " | "
         << (p.default_value ? number(*p.default_value) : std::string("required")) << " | "
         << p.help << " |\n";
    }
  }
  return md.str();
}

}  // namespace plisse
