// The `material:` section: the model of the material registry and its parameters, the
// compressibility, the density, the fibre frame and the inelastic laws.
#include "case/sections.hpp"
#include "material/registry.hpp"
#include "schema/field.hpp"
#include "schema/table.hpp"
#include "terms/keys.hpp"

namespace plisse::case_detail {
namespace {

const Choices<bool> kIncompressibility{{"exact", true}, {"nearly", false}};

/// "`a`, `b`, `c`".
std::string code_list(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "`" : ", `") + w + "`";
  return out;
}

std::vector<std::string> model_names() {
  std::vector<std::string> out;
  for (const MaterialModelInfo& info : material_models()) out.push_back(info.name);
  return out;
}

}  // namespace

/// `material.viscoelastic`: up to three Maxwell elements (material/inelastic.hpp).
Schema<Viscoelasticity> viscoelastic_schema() {
  Schema<Viscoelasticity> s;
  s.real("beta1", &Viscoelasticity::beta1, Range::positive(), "–",
         "strength of Maxwell element 1 relative to the equilibrium (base model) response: the "
         "instantaneous stress is (1 + beta1 + beta2 + beta3) times the equilibrium one")
      .required();
  s.real("tau1", &Viscoelasticity::tau1, Range::positive(), "s", "relaxation time of element 1")
      .required();
  s.real("beta2", &Viscoelasticity::beta2, Range::positive(), "–",
         "strength of element 2 (absent: one element)")
      .doc.default_value = "none";
  s.real("tau2", &Viscoelasticity::tau2, Range::positive(), "s",
         "relaxation time of element 2 (with `beta2`)")
      .doc.default_value = "none";
  s.real("beta3", &Viscoelasticity::beta3, Range::positive(), "–",
         "strength of element 3 (needs element 2)")
      .doc.default_value = "none";
  s.real("tau3", &Viscoelasticity::tau3, Range::positive(), "s",
         "relaxation time of element 3 (with `beta3`)")
      .doc.default_value = "none";
  s.rule("`beta2` and `tau2` go together, as do `beta3` and `tau3`; element 3 needs element 2",
         [](const FieldMap& m, const Viscoelasticity&, const ReadContext&) {
           for (const std::string n : {"2", "3"}) {
             const bool beta = m.has("beta" + n), tau = m.has("tau" + n);
             if (beta && !tau) m.require("tau" + n);
             if (tau && !beta) m.require("beta" + n);
           }
           if (m.has("beta3") && !m.has("beta2"))
             m.require("beta3").fail_at_key(
                 "element 3 needs element 2: give beta2 and tau2 first (or rename this one)");
         });
  return s;
}

/// `material.mullins`: Ogden & Roxburgh's softening (material/inelastic.hpp).
Schema<MullinsSoftening> mullins_schema() {
  Schema<MullinsSoftening> s;
  s.real("r", &MullinsSoftening::r, Range{1.0, std::numeric_limits<double>::infinity(), true, true},
         "–",
         "extent of the softening: the stress falls to no less than (1 - 1/r) of the virgin "
         "material's")
      .required();
  s.real("m", &MullinsSoftening::m, Range::positive(), "MPa",
         "energy scale over which the softened curve rejoins the virgin one")
      .required();
  s.real("beta", &MullinsSoftening::beta, Range{0.0, 1.0, false, true}, "–",
         "growth of that scale with the largest energy reached, m + beta Wmax");
  return s;
}

/// `material:`. Its variant is the model; the model's parameters come from the material registry
/// (material/registry.hpp), which also checks them, and are read in read_material.
Schema<MaterialSection> material_schema() {
  Schema<MaterialSection> s;
  s.place(&MaterialSection::place, true);
  s.add({"model",
         "name",
         "–",
         "a registered model",
         "",
         {},
         code_list(model_names()) + " ([materials.md](materials.md))"},
        [](const Field& f, MaterialSection& m, ReadContext&) {
          m.model = f.text();
          if (find_material_model(m.model)) return;
          std::string rule =
              "unknown material model '" + m.model + "'; known models: " + join(model_names());
          if (const auto guess = schema::closest_match(m.model, model_names()))
            rule += " (did you mean '" + *guess + "'?)";
          f.fail(rule);
        })
      .required()
      .variant = true;
  s.choice<bool>("incompressibility", &MaterialSection::exact_incompressibility, kIncompressibility,
                 "exact: mixed u–p with κ = ∞ (the paper's case); nearly: finite bulk modulus");
  s.add({"bulk_modulus",
         "number",
         "MPa",
         Range::positive().describe(),
         "required with `nearly`",
         {},
         "κ"},
        [](const Field& f, MaterialSection& m, ReadContext&) {
          if (m.exact_incompressibility)
            f.fail_at_key(
                "bulk_modulus applies only with 'incompressibility: nearly' (exact "
                "incompressibility has an infinite bulk modulus)");
          m.bulk_modulus = f.real(Range::positive());
        })
      .when_absent([](const FieldMap& map, MaterialSection& m, ReadContext&) {
        if (m.exact_incompressibility) return;
        InputPlace p = map.find("incompressibility")->place();
        p.key = schema::child_path(map.self().path(), "bulk_modulus");
        throw InputError(p, "required with 'incompressibility: nearly' (bulk modulus in MPa, > 0)");
      });
  s.real("density", &MaterialSection::density, Range::non_negative(), "tonne/mm³",
         "needed (> 0) by gravity loads");
  s.add({"fibre_frame",
         schema::doc_choice({"global", "shell"}),
         "–",
         "",
         "`global`",
         {},
         "the frame of a fibre-reinforced model's directions `a1_*`, `a2_*`: global (x, y, z), "
         "or shell: each element's (meridian, hoop, normal) on a generated spherical shell or "
         "airbag (axis y) or tube (axis x), so `a1_x: 1` runs along the meridians (the tube's "
         "axis) and `a1_y: 1` around the circumference"},
        [](const Field& f, MaterialSection& m, ReadContext&) {
          m.shell_fibre_frame = f.choice(
              std::vector<std::pair<std::string, bool>>{{"global", false}, {"shell", true}});
          m.fibre_frame_place = f.place();
          if (m.model != "fibre-reinforced")
            f.fail_at_key("fibre_frame applies only to model 'fibre-reinforced' (got '" + m.model +
                          "')");
        });
  s.nested("viscoelastic", &MaterialSection::viscoelastic, viscoelastic_schema());
  s.nested("mullins", &MaterialSection::mullins, mullins_schema());
  s.rule(
      "`viscoelastic` (a Prony series of up to three Maxwell elements on the isochoric stress; the "
      "model is the long-term response) and `mullins` (Ogden & Roxburgh's softening below the "
      "largest energy reached) apply to every model, alone or together: see "
      "[theory/materials.md](theory/materials.md), V1-V7 and MR1-MR6; with them the times of "
      "ramps and load curves are physical seconds",
      nullptr);
  s.rule("`bulk_modulus` is required with `incompressibility: nearly` and refused with `exact`",
         nullptr);
  s.rule(
      "the model's parameters (e.g. `c1` for `neo-hookean`) are keys of this section too; their "
      "units, ranges, defaults and the rules between them are in [materials.md](materials.md)",
      nullptr);
  return s;
}

MaterialSection read_material(const Field& field, ReadContext& context) {
  static const Schema<MaterialSection> schema = material_schema();
  const FieldMap m = field.map();
  MaterialSection s;
  s.place = field.key_place();
  schema.read_key("model", m, s, context);
  const MaterialModelInfo* info = find_material_model(s.model);
  std::vector<std::string> params;
  for (const ParamSpec& p : info->params) params.push_back(p.name);
  std::vector<std::string> other_params;
  for (const MaterialModelInfo& other : material_models())
    for (const ParamSpec& p : other.params) other_params.push_back(p.name);
  schema.check_keys(m, {s.model}, "model '" + info->name + "'", params, other_params);
  schema.read_rows(m, s, context, {s.model});

  for (const ParamSpec& p : info->params) {
    const auto f = m.find(p.name);
    if (!f) continue;
    s.params[p.name] = f->real();  // type and finiteness here; ranges and rules by the registry
    s.param_places[p.name] = f->place();
  }
  const std::vector<ParamViolation> violations = validate_material(s.model, s.params);
  if (!violations.empty()) {
    const ParamViolation& v = violations.front();
    InputPlace p = s.place;
    if (const auto it = s.param_places.find(v.key); it != s.param_places.end())
      p = it->second;
    else if (v.key == "model")
      p = m.find("model")->place();
    p.key = schema::child_path(field.path(), v.key);
    std::string rule = v.rule;
    if (violations.size() > 1)
      rule += " (and " + std::to_string(violations.size() - 1) + " more problem" +
              (violations.size() > 2 ? "s" : "") + " in this material)";
    throw InputError(p, rule);
  }
  for (const ParamSpec& p : info->params)
    if (p.default_value && !s.params.count(p.name)) s.params[p.name] = *p.default_value;
  return s;
}

}  // namespace plisse::case_detail
