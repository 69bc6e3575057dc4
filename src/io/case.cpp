// The case-file schema: one table per section (key, type, unit, range, default, meaning, the
// variants a key applies to, the struct member it fills) and the rules between keys, next to the
// section readers that use them. The tables also generate the key tables of docs/case-file.md
// (case_keys.hpp). Reading and locating values is in case_reader.cpp, the raw YAML text in
// yaml_text.cpp, `--set` in case_overrides.cpp, the checks that need the mesh in case_mesh.cpp;
// the `solver:` section's tables are in case_solver_schema.cpp.
#include "io/case.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "io/case_keys.hpp"
#include "io/case_overrides.hpp"
#include "io/case_reader.hpp"
#include "io/case_schema.hpp"
#include "io/case_solver_schema.hpp"
#include "io/yaml_text.hpp"
#include "material/registry.hpp"
#include "physics/rotation.hpp"

namespace plisse {
namespace {

using case_detail::Choices;
using case_detail::Field;
using case_detail::FieldMap;
using case_detail::format_number;
using case_detail::join;
using case_detail::KeyDoc;
using case_detail::ReadContext;
using case_detail::Schema;
using case_detail::solver_schema;

// A ring at +-90 degrees would be a single point: latitudes are open at the poles.
const Range kLatitude{-90.0, 90.0, true, true};

const Choices<BoundaryType> kBoundaryTypes{{"fixed", BoundaryType::fixed},
                                           {"symmetry", BoundaryType::symmetry},
                                           {"displacement", BoundaryType::displacement}};
const Choices<LoadType> kLoadTypes{{"pressure", LoadType::pressure},
                                   {"gravity", LoadType::gravity},
                                   {"traction", LoadType::traction},
                                   {"point-force", LoadType::point_force},
                                   {"follower-traction", LoadType::follower_traction}};
const Choices<CavityControl> kCavityControls{{"volume", CavityControl::volume},
                                             {"gas", CavityControl::gas}};
const Choices<DieShape> kDieShapes{
    {"plane", DieShape::plane}, {"sphere", DieShape::sphere}, {"cylinder", DieShape::cylinder}};
const Choices<ContactKind> kContactKinds{{"frictionless", ContactKind::frictionless},
                                         {"sticking", ContactKind::sticking},
                                         {"coulomb", ContactKind::coulomb}};
const Choices<bool> kIncompressibility{{"exact", true}, {"nearly", false}};
const Choices<char> kAxes{{"x", 'x'}, {"y", 'y'}, {"z", 'z'}};
const Choices<ElementFamily> kElementFamilies{{"mini", ElementFamily::mini},
                                              {"taylor-hood", ElementFamily::taylor_hood}};

SurfaceRef surface_ref(const Field& f) {
  const std::string name = f.text();
  if (name.empty()) f.fail("a surface tag name must not be empty");
  return {name, f.place()};
}

/// A vector that is not zero (a load of zero is a mistake, not a way to switch it off).
Vec3d non_zero_vector(const Field& f) {
  const Vec3d v = f.vec3();
  if (v.isZero(0.0)) f.fail("must not be the zero vector (leave the load out instead)");
  return v;
}

/// A direction, normalised; the zero vector is an error.
Vec3d unit_vector(const Field& f) {
  const Vec3d v = f.vec3();
  const double norm = v.norm();
  if (!(norm > 0.0) || !std::isfinite(norm))
    f.fail("must be a non-zero direction (its length is 0)");
  return v / norm;
}

/// `ramp: [start, end]` [s] with 0 <= start < end, or a load curve `[[t, factor], ...]`: at least
/// two points, t >= 0 strictly increasing, finite factors.
Ramp read_ramp(const Field& f) {
  if (f.node().IsSequence() && f.node().size() > 0 && f.node()[0].IsSequence()) {
    Ramp ramp;
    const std::vector<Field> points = f.items();
    if (points.size() < 2)
      f.fail("a load curve needs at least 2 points [t, factor], got " + f.describe());
    for (const Field& point : points) {
      if (!point.node().IsSequence() || point.node().size() != 2)
        point.fail("expected a point [t, factor] of 2 numbers, got " + point.describe());
      const std::vector<double> p = point.reals();
      if (p[0] < 0.0) point.fail("the time must be >= 0 (got " + format_number(p[0]) + ")");
      if (!ramp.table.empty() && !(p[0] > ramp.table.back()[0]))
        point.fail("the times must increase: " + format_number(p[0]) + " follows " +
                   format_number(ramp.table.back()[0]));
      ramp.table.push_back({p[0], p[1]});
    }
    ramp.start = ramp.table.front()[0];
    ramp.end = ramp.table.back()[0];
    return ramp;
  }
  if (!f.node().IsSequence() || f.node().size() != 2)
    f.fail(
        "expected a list of 2 numbers [start, end] in s, or a load curve [[t, factor], ...], "
        "got " +
        f.describe());
  const std::vector<double> t = f.reals();
  if (t[0] < 0.0) f.fail("ramp start must be >= 0 (got " + format_number(t[0]) + ")");
  if (!(t[1] > t[0]))
    f.fail("ramp end must be > start (got [" + format_number(t[0]) + ", " + format_number(t[1]) +
           "])");
  return {t[0], t[1]};
}

/// A surface tag of the mesh, with where it is named.
template <class S>
typename Schema<S>::Row& surface_key(Schema<S>& schema, std::string key,
                                     std::type_identity_t<SurfaceRef S::*> member,
                                     std::string help) {
  return schema.add({std::move(key), "surface tag", "–", "", "", {}, std::move(help)},
                    [member](const Field& f, S& s, ReadContext&) { s.*member = surface_ref(f); });
}

/// An optional surface tag of the mesh.
template <class S>
typename Schema<S>::Row& optional_surface_key(
    Schema<S>& schema, std::string key, std::type_identity_t<std::optional<SurfaceRef> S::*> member,
    std::string fallback, std::string help) {
  return schema.add(
      {std::move(key), "surface tag", "–", "", std::move(fallback), {}, std::move(help)},
      [member](const Field& f, S& s, ReadContext&) { s.*member = surface_ref(f); });
}

/// The entry's name, unique across conditions, loads, cavities, dies and probes.
template <class S>
typename Schema<S>::Row& name_key(Schema<S>& schema, std::type_identity_t<std::string S::*> member,
                                  std::string help) {
  return schema.add(
      {"name", "name", "–", "", "none", {}, std::move(help)},
      [member](const Field& f, S& s, ReadContext& context) { s.*member = context.unique_name(f); });
}

/// What every `ramp` key's help adds about load curves.
const std::string load_curve_help =
    "; a list of points [[t, factor], ...] is a load curve instead: the factor joins them "
    "linearly and holds the first and last values outside (load, hold, unload, cycles)";

/// A time ramp; default [0, solver.end_time].
template <class S>
typename Schema<S>::Row& ramp_key(Schema<S>& schema, std::type_identity_t<Ramp S::*> member,
                                  std::string help) {
  return schema
      .add({"ramp",
            "[start, end] or [[t, factor], ...]",
            "s",
            "0 <= start < end; t increasing",
            "[0, end_time]",
            {},
            std::move(help) + load_curve_help},
           [member](const Field& f, S& s, ReadContext&) { s.*member = read_ramp(f); })
      .when_absent([member](const FieldMap&, S& s, ReadContext& context) {
        s.*member = {0.0, context.end_time};
      });
}

/// A list of entries, each a map read by `entry`.
template <class S, class E>
typename Schema<S>::Row& list_key(Schema<S>& schema, std::string key,
                                  std::type_identity_t<std::vector<E> S::*> member,
                                  const Schema<E>& entry, std::string help) {
  auto& row = schema.add({std::move(key), "list", "", "", "empty", {}, std::move(help)},
                         [member, entry](const Field& f, S& s, ReadContext& context) {
                           for (const Field& item : f.items()) {
                             E e;
                             entry.read(item, e, context);
                             (s.*member).push_back(std::move(e));
                           }
                         });
  row.nested = entry.doc();
  return row;
}

/// "`a`, `b`, `c`".
std::string code_list(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "`" : ", `") + w + "`";
  return out;
}

std::vector<std::string> kind_names() {
  std::vector<std::string> out;
  for (const MeshKind& k : mesh_kinds()) out.push_back(k.name);
  return out;
}

std::vector<std::string> model_names() {
  std::vector<std::string> out;
  for (const MaterialModelInfo& info : material_models()) out.push_back(info.name);
  return out;
}

/// `mesh:`. Its variant is which of `file` and `generate` is given; the generators' options come
/// from the mesh registry (mesh_kinds) and are read in read_mesh.
Schema<MeshSection> mesh_schema() {
  Schema<MeshSection> s;
  s.place(&MeshSection::place, true);
  s.add({"file",
         "path",
         "–",
         "",
         "",
         {"file"},
         "a Gmsh `.msh` file (v2 or v4, ASCII or binary); a relative path is read from the "
         "directory of the case file. Physical groups of dimension 2 become surface tags"},
        [](const Field& f, MeshSection& m, ReadContext& context) {
          const std::string text = f.text();
          if (text.empty()) f.fail("the mesh file name must not be empty");
          m.file = case_detail::resolve_path(text, context.directory);
          m.file_place = f.place();
        });
  s.add({"thickness",
         "number",
         "mm",
         Range::positive().describe(),
         "none",
         {"file"},
         "the wall thickness of a shell read from a file: imperfections, branch switching and "
         "the wrinkle threshold are relative to it"},
        [](const Field& f, MeshSection& m, ReadContext&) {
          m.file_thickness = f.real(Range::positive());
        });
  s.add({"generate",
         case_detail::doc_choice(kind_names()),
         "–",
         "",
         "",
         {"generate"},
         "generate the mesh; the kind's options (below) may follow"},
        nullptr);
  s.rule("exactly one of `file` and `generate`", nullptr);
  return s;
}

/// The table of the generators' options (docs/case-file.md, block "mesh-options"), from the mesh
/// registry: kind, option, type, unit, range, default (MeshGenerationSpec's), meaning.
std::string mesh_options_markdown() {
  const MeshGenerationSpec defaults;
  std::string md =
      "| kind | option | type | unit | range | default | meaning |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const MeshKind& kind : mesh_kinds()) {
    bool first = true;
    for (const MeshOption& o : kind.options) {
      std::string type = "number", fallback;
      if (o.real) fallback = case_detail::doc_number(defaults.*o.real);
      if (o.integer) type = "integer", fallback = std::to_string(defaults.*o.integer);
      if (o.symmetry) {
        type = case_detail::doc_choice({"full", "half", "quarter", "octant"});
        fallback = "`" + to_string(defaults.*o.symmetry) + "`";
      }
      const std::string range = o.symmetry ? "" : Schema<MeshSection>::range_text(o.range);
      std::string help;  // a '|' in the help would end the cell
      for (const char c : o.help) help += c == '|' ? std::string("\\|") : std::string(1, c);
      md += "|" + (first ? " `" + kind.name + "` |" : std::string(" |")) + " `" + o.key + "` | " +
            type + " | " + (o.unit == "-" ? "–" : o.unit) + " |" +
            (range.empty() ? std::string(" |") : " " + range + " |") + " " + fallback + " | " +
            help + " |\n";
      first = false;
    }
  }
  return md;
}

MeshSection read_mesh(const Field& field, ReadContext& context) {
  static const Schema<MeshSection> schema = mesh_schema();
  const FieldMap m = field.map();
  MeshSection s;
  s.place = field.key_place();
  const auto file = m.find("file"), generate = m.find("generate");
  if (file && generate) generate->fail_at_key("give either 'file' or 'generate', not both");
  if (!file && !generate)
    throw InputError(s.place,
                     "needs either 'file: PATH' (a Gmsh .msh file) or 'generate: KIND' "
                     "(one of: " +
                         join(kind_names()) + ")");
  std::vector<std::string> all_options;
  for (const MeshKind& k : mesh_kinds())
    for (const MeshOption& o : k.options) all_options.push_back(o.key);

  if (file) {
    schema.check_keys(m, {"file"}, "a mesh read from a file", {}, all_options);
    schema.read_rows(m, s, context, {"file"});
    return s;
  }

  const std::string kind_name = generate->text();
  const MeshKind* kind = find_mesh_kind(kind_name);
  if (!kind) {
    std::string rule = "unknown mesh kind '" + kind_name + "'; known kinds: " + join(kind_names());
    if (const auto guess = case_detail::closest_match(kind_name, kind_names()))
      rule += " (did you mean '" + *guess + "'?)";
    generate->fail(rule);
  }
  std::vector<std::string> options;
  for (const MeshOption& o : kind->options) options.push_back(o.key);
  all_options.push_back("file");
  schema.check_keys(m, {"generate"}, "generate: " + kind->name, options, all_options);

  MeshGenerationSpec spec;
  spec.kind = kind->name;
  s.option_places["generate"] = generate->place();
  for (const MeshOption& o : kind->options) {
    const auto f = m.find(o.key);
    if (!f) continue;
    s.option_places[o.key] = f->place();
    if (o.real) {
      spec.*o.real = f->real(o.range);
    } else if (o.integer) {
      spec.*o.integer = f->integer(o.range);
    } else if (o.symmetry) {
      const std::string text = f->text();
      const auto sym = parse_symmetry(text);
      if (!sym) f->fail("must be one of: full, half, quarter, octant (got '" + text + "')");
      spec.*o.symmetry = *sym;
    }
  }
  s.generate = spec;
  return s;
}

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
          if (const auto guess = case_detail::closest_match(m.model, model_names()))
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
        p.key = case_detail::child_path(map.self().path(), "bulk_modulus");
        throw InputError(p, "required with 'incompressibility: nearly' (bulk modulus in MPa, > 0)");
      });
  s.real("density", &MaterialSection::density, Range::non_negative(), "tonne/mm³",
         "needed (> 0) by gravity loads");
  s.add({"fibre_frame",
         case_detail::doc_choice({"global", "shell"}),
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
    p.key = case_detail::child_path(field.path(), v.key);
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

/// A list of three numbers, `~` for a free (absent) component; `what` names them in the error.
std::array<std::optional<double>, 3> optional_components(const Field& f, const std::string& what) {
  if (!f.node().IsSequence() || f.node().size() != 3)
    f.fail("expected a list of 3 " + what + ", ~ for a free component, got " + f.describe());
  std::array<std::optional<double>, 3> out;
  const std::vector<Field> items = f.items();
  for (int k = 0; k < 3; ++k)
    if (!items[k].is_null()) out[k] = items[k].real();
  return out;
}

/// `boundary:` items: Dirichlet conditions on the nodes of a tagged surface.
Schema<BoundaryCondition> boundary_schema() {
  Schema<BoundaryCondition> s;
  s.place(&BoundaryCondition::place, false);
  s.variant<BoundaryType>("type", &BoundaryCondition::type, kBoundaryTypes,
                          "fixed: u = 0; symmetry: zero normal displacement (the surface must be "
                          "planar); displacement: prescribed components")
      .required();
  name_key(s, &BoundaryCondition::name,
           "when given, the reaction force on the surface is reported as `force_x:<name>`, "
           "`force_y:<name>`, `force_z:<name>`");
  surface_key(s, "surface", &BoundaryCondition::surface, "where the condition acts").required();
  s.add({"value",
         "list of 3 numbers or `~`",
         "mm",
         "",
         "",
         {"displacement"},
         "displacement at the end of the ramp; `~` leaves a component free; at least one "
         "component must be given"},
        [](const Field& f, BoundaryCondition& bc, ReadContext&) {
          bc.value = optional_components(f, "displacements [ux, uy, uz] in mm");
          if (!bc.value[0] && !bc.value[1] && !bc.value[2])
            f.fail("at least one component must be prescribed (all three are ~)");
        })
      .required();
  ramp_key(s, &BoundaryCondition::ramp, "time ramp of `value`").applies({"displacement"});
  return s;
}

/// `loads:` items.
Schema<Load> load_schema() {
  Schema<Load> s;
  s.place(&Load::place, false);
  s.variant<LoadType>("type", &Load::type, kLoadTypes,
                      "pressure: a follower pressure on a surface; gravity: a body force; "
                      "traction: a dead traction on a surface; point-force: a dead force on "
                      "the node nearest a point; follower-traction: normal and shear tractions "
                      "that turn with the deformed surface")
      .required();
  name_key(s, &Load::name,
           "history column `pressure:<name>` (pressure), and on a closed or symmetry-closed "
           "surface `volume:<name>` and `full_volume:<name>` (the enclosed volume); "
           "`load_x:<name>`, `load_y:<name>`, `load_z:<name>` (the applied force) and "
           "`work:<name>` (its work) for the others (docs/output.md)")
      .required();
  surface_key(s, "surface", &Load::surface, "the loaded surface")
      .required()
      .applies({"pressure", "traction", "follower-traction"});
  s.real("value", &Load::value, Range::any(), "MPa",
         "follower pressure at the end of the ramp; positive pushes against the outward normal "
         "of the body (inflates from `inner`)")
      .required()
      .applies({"pressure"});
  s.vec3("acceleration", &Load::acceleration, "mm/s²", "e.g. `[0, -9810, 0]`")
      .required()
      .applies({"gravity"});
  s.add({"traction",
         "vector",
         "MPa",
         "",
         "",
         {"traction"},
         "traction per unit undeformed area at the end of the ramp, fixed in direction and "
         "magnitude (a dead load); non-zero"},
        [](const Field& f, Load& load, ReadContext&) { load.traction = non_zero_vector(f); });
  s.add({"force",
         "vector",
         "N",
         "",
         "",
         {"traction", "point-force"},
         "traction: the total force at the end of the ramp, spread over the surface in "
         "proportion to undeformed area; point-force: the force on the node nearest `point` "
         "(required); dead, non-zero"},
        [](const Field& f, Load& load, ReadContext&) { load.force = non_zero_vector(f); });
  s.add({"point",
         "vector",
         "mm",
         "",
         "",
         {"point-force"},
         "where the force acts: on the mesh node nearest this point of the undeformed body "
         "(refused when farther from it than the longest edge at that node)"},
        [](const Field& f, Load& load, ReadContext&) {
          load.point = f.vec3();
          load.point_place = f.place();
        })
      .required();
  s.real("normal", &Load::normal, Range::any(), "MPa",
         "traction per unit deformed area along the deformed outward normal at the end of the "
         "ramp (a negative value pushes inwards, as a pressure)")
      .applies({"follower-traction"});
  s.real("shear", &Load::shear, Range::any(), "MPa",
         "traction per unit deformed area along `direction` projected onto the deformed surface, "
         "at the end of the ramp")
      .applies({"follower-traction"});
  s.add({"direction",
         "vector",
         "–",
         "",
         "",
         {"follower-traction"},
         "the shear's direction, normalised: the shear acts along its projection onto the "
         "deformed surface (nowhere where the surface is normal to it); required with a shear"},
        [](const Field& f, Load& load, ReadContext&) { load.direction = unit_vector(f); });
  ramp_key(s, &Load::ramp, "time ramp of the load");
  s.rule(
      "a follower-traction load needs a non-zero `normal` or `shear`, and `direction` with a "
      "shear",
      [](const FieldMap& m, const Load& load, const ReadContext&) {
        if (load.type != LoadType::follower_traction) return;
        if (load.normal == 0.0 && load.shear == 0.0)
          m.self().fail_at_key(
              "a follower traction needs a non-zero `normal` or `shear` (MPa per unit "
              "deformed area)");
        if (load.shear != 0.0 && !load.direction) m.require("direction");
      });
  s.rule("a traction load needs exactly one of `traction` and `force`",
         [](const FieldMap& m, const Load& load, const ReadContext&) {
           if (load.type != LoadType::traction) return;
           if (load.traction && load.force)
             m.require("force").fail_at_key(
                 "give either `traction` (per unit area) or `force` (in total), not both");
           if (!load.traction && !load.force)
             m.self().fail_at_key(
                 "a traction load needs `traction` (MPa, per unit undeformed area) or `force` "
                 "(N, in total)");
         });
  s.rule("a point-force load needs `force`",
         [](const FieldMap& m, const Load& load, const ReadContext&) {
           if (load.type == LoadType::point_force && !load.force) m.require("force");
         });
  s.rule("a gravity load needs `material.density` > 0, or a region's",
         [](const FieldMap& m, const Load& load, const ReadContext& context) {
           if (load.type == LoadType::gravity && !(context.density > 0.0))
             m.require("type").fail(
                 "a gravity load needs material.density > 0, or a region's material with a "
                 "density (got " +
                 format_number(context.density) + ")");
         });
  return s;
}

/// `cavities:` items: a closed surface (or one closed by symmetry planes) enclosing a fluid.
Schema<Cavity> cavity_schema() {
  Schema<Cavity> s;
  s.place(&Cavity::place, false);
  name_key(s, &Cavity::name,
           "history columns `volume:<name>`, `pressure:<name>`, and `full_volume:<name>` on a "
           "model cut by symmetry planes (docs/output.md)")
      .required();
  surface_key(s, "surface", &Cavity::surface, "the cavity's wall").required();
  s.variant<CavityControl>("control", &Cavity::control, kCavityControls,
                           "prescribed volume, or an ideal gas");
  ramp_key(s, &Cavity::ramp, "time ramp of the volume or the mass ratio");
  const auto target = [](VolumeTarget which, double Cavity::*member, Range range) {
    return [=](const Field& f, Cavity& c, ReadContext&) {
      c.*member = f.real(range);
      c.target = which;
      c.target_place = f.place();
    };
  };
  s.add({"volume_ratio",
         "number",
         "–",
         Range::positive().describe(),
         "1",
         {"volume"},
         "V(end of ramp) / V0; the default 1 holds the initial volume"},
        target(VolumeTarget::ratio, &Cavity::volume_ratio, Range::positive()));
  s.add({"volume",
         "number",
         "mm³",
         Range::positive().describe(),
         "",
         {"volume"},
         "V at the end of the ramp, absolute"},
        target(VolumeTarget::absolute, &Cavity::volume, Range::positive()));
  s.add({"volume_change",
         "number",
         "mm³",
         "",
         "",
         {"volume"},
         "V(end of ramp) − V0: what a cavity that starts flat (V0 = 0, e.g. under a clamped "
         "sheet) takes in; non-zero"},
        target(VolumeTarget::change, &Cavity::volume_change, Range::any()));
  s.rule("at most one of `volume_ratio`, `volume` and `volume_change`",
         [](const FieldMap& m, const Cavity&, const ReadContext&) {
           const std::vector<std::string> keys = {"volume_ratio", "volume", "volume_change"};
           std::vector<std::string> given;
           for (const std::string& key : keys)
             if (m.has(key)) given.push_back(key);
           if (given.size() > 1)
             m.require(given[1]).fail_at_key(
                 "give one of `volume_ratio`, `volume` and "
                 "`volume_change`, not both `" +
                 given[0] + "` and `" + given[1] + "`");
           if (const auto f = m.find("volume_change"); f && f->real() == 0.0)
             f->fail("must not be 0 (leave it out to hold the initial volume)");
         });
  s.real("initial_pressure", &Cavity::initial_pressure, Range::non_negative(), "MPa",
         "gauge pressure of the gas at t = 0, at the undeformed cavity volume (it fixes the "
         "amount of gas)")
      .applies({"gas"});
  s.real("mass_ratio", &Cavity::mass_ratio, Range::positive(), "–",
         "gas mass at end of ramp / initial mass")
      .applies({"gas"});
  s.real("ambient_pressure", &Cavity::ambient_pressure, Range::positive(), "MPa",
         "absolute ambient pressure")
      .applies({"gas"});
  return s;
}

/// `dies:` items: rigid analytic dies with prescribed motion.
Schema<Die> die_schema() {
  Schema<Die> move;
  move.vec3("displacement", &Die::displacement, "mm", "displacement reached at the end of `ramp`");
  ramp_key(move, &Die::ramp, "time ramp of the motion");

  Schema<Die> s;
  s.place(&Die::place, false);
  name_key(s, &Die::name,
           "history columns `force_x:<name>`, `force_y:<name>`, `force_z:<name>` (force of the "
           "body on the die, N), `contact_nodes:<name>` (nodes in contact or glued), "
           "`penetration:<name>` (largest penetration, mm); Coulomb: `stick_nodes:<name>`, "
           "`slip_nodes:<name>`. Point fields in the step files: `contact_<name>` (0 free, 1 "
           "sliding, 2 sticking), `contact_pressure_<name>` (MPa per reference area), "
           "`gap_<name>` (signed gap to the die, mm)")
      .required();
  s.variant<DieShape>("shape", &Die::shape, kDieShapes, "the die's surface").required();
  s.vec3("point", &Die::point, "mm",
         "plane: a point of it; sphere: centre; cylinder: a point of the axis")
      .required();
  s.variant<ContactKind>("contact", &Die::contact, kContactKinds,
                         "unilateral sliding contact; nodes that touch stay glued; or Coulomb "
                         "friction: a node sticks while its tangential traction is below "
                         "`friction` times its contact pressure, else slides");
  optional_surface_key(s, "surface", &Die::surface,
                       "whole boundary except the faces on symmetry planes",
                       "candidate contact surface");
  s.nested_here("move", move).when_absent([](const FieldMap&, Die& d, ReadContext& context) {
    d.ramp = {0.0, context.end_time};  // a die without `move` stays put; its ramp is unused
  });
  s.real("penalty", &Die::penalty, Range::non_negative(), "MPa/mm",
         "contact penalty; 0 chooses 10 μ / h (μ the small-strain shear modulus, h the mean edge "
         "length of the contact surface; docs/theory/contact.md, D11)");
  s.real("tolerance", &Die::tolerance, Range::positive(), "mm",
         "allowed penetration (and, for a sticking node of a Coulomb die, tangential slip in "
         "a step): the augmented-Lagrangian multipliers are updated until no node exceeds it "
         "(at most `solver.max_augmentations` times per step)");
  s.add({"normal",
         "vector",
         "–",
         "non-zero",
         "",
         {"plane"},
         "normal pointing towards the body; normalised"},
        [](const Field& f, Die& d, ReadContext&) { d.normal = unit_vector(f); })
      .required();
  s.add({"axis", "vector", "–", "non-zero", "", {"cylinder"}, "axis direction; normalised"},
        [](const Field& f, Die& d, ReadContext&) { d.axis = unit_vector(f); })
      .required();
  s.real("radius", &Die::radius, Range::positive(), "mm", "radius of the sphere or cylinder")
      .required()
      .applies({"sphere", "cylinder"});
  optional_surface_key(s, "region", &Die::region, "none", "glued to the die from the start")
      .applies({"sticking"});
  s.real("friction", &Die::friction, Range::non_negative(), "–",
         "Coulomb friction coefficient (0 slides without friction)")
      .required()
      .applies({"coulomb"});
  return s;
}

/// `contacts:` items: contact between tagged surfaces of the body.
Schema<SurfaceContactPair> contact_schema() {
  using Pair = SurfaceContactPair;
  Schema<Pair> s;
  s.place(&Pair::place, false);
  name_key(
      s, &Pair::name,
      "history columns `force_x:<name>`, `force_y:<name>`, `force_z:<name>` (force of the "
      "second surface on the first, N), `contact_nodes:<name>`, `penetration:<name>` "
      "(largest penetration, mm); point field `contact_<name>` (contact pressure per reference "
      "area at the nodes of the first surface, MPa)")
      .required();
  s.add({"surfaces",
         "list of 2 surface tags",
         "–",
         "two different tags",
         "",
         {},
         "the nodes of the first surface are kept out of the faces of the second (give the more "
         "finely meshed one first)"},
        [](const Field& f, Pair& p, ReadContext&) {
          if (!f.node().IsSequence() || f.node().size() != 2)
            f.fail("expected a list of 2 surface tags, got " + f.describe());
          const std::vector<Field> items = f.items();
          p.first = surface_ref(items[0]);
          p.second = surface_ref(items[1]);
          if (p.first->name == p.second->name)
            items[1].fail(
                "names the surface '" + p.first->name +
                "' twice: for contact of a surface with itself give `self: " + p.first->name + "`");
        });
  optional_surface_key(s, "self", &Pair::self, "none",
                       "a surface in contact with itself (folds, faces pressed together)");
  s.rule("exactly one of `surfaces` and `self`",
         [](const FieldMap& m, const Pair&, const ReadContext&) {
           if (m.has("surfaces") && m.has("self"))
             m.require("self").fail_at_key("give `surfaces` or `self`, not both");
           if (!m.has("surfaces") && !m.has("self"))
             m.self().fail_at_key("give `surfaces: [first, second]` or `self: <surface>`");
         });
  s.real("penalty", &Pair::penalty, Range::non_negative(), "MPa/mm",
         "contact penalty; 0 chooses 10 μ / h (μ the small-strain shear modulus, h the mean edge "
         "length of the surfaces; docs/theory/surface-contact.md)");
  s.real("tolerance", &Pair::tolerance, Range::positive(), "mm",
         "allowed penetration: the multipliers are updated until no node penetrates more (at "
         "most `solver.max_augmentations` times per step)");
  s.real("search_distance", &Pair::search_distance, Range::non_negative(), "mm",
         "a node pairs with a face when it lies within this distance of the face's plane; 0 "
         "chooses the mean edge length of the surfaces. A node that penetrates deeper in one "
         "Newton iteration is not seen");
  return s;
}

/// `caps:` items: rigid end caps.
Schema<Cap> cap_schema() {
  Schema<Cap> s;
  s.place(&Cap::place, false);
  name_key(s, &Cap::name,
           "history columns `force_x:<name>` ... (the cap's force on the body, N), "
           "`moment_x:<name>` ... (its moment about the moved reference point, N mm), "
           "`ux:<name>` ... (the reference point's displacement) and `rx:<name>` ... (the "
           "rotation vector, rad)")
      .required();
  surface_key(s, "surface", &Cap::surface, "the nodes tied to the cap").required();
  s.add({"point",
         "vector",
         "mm",
         "",
         "mean of the nodes",
         {},
         "the reference point the cap moves and turns about"},
        [](const Field& f, Cap& c, ReadContext&) { c.point = f.vec3(); });
  s.add({"displacement",
         "list of 3 numbers or `~`",
         "mm",
         "",
         "[~, ~, ~]",
         {},
         "the reference point's displacement at the end of the ramp; `~` leaves a component "
         "free (loaded by `force`)"},
        [](const Field& f, Cap& c, ReadContext&) {
          c.displacement = optional_components(f, "displacements");
        });
  s.add({"rotation",
         "list of 3 numbers or `~`",
         "rad",
         "angle < 2π",
         "[~, ~, ~]",
         {},
         "rotation vector at the end of the ramp (axis times angle); `~` leaves a component "
         "free (loaded by `moment`)"},
        [](const Field& f, Cap& c, ReadContext&) {
          c.rotation = optional_components(f, "rotation components");
          double s2 = 0.0;
          for (const auto& r : c.rotation) s2 += r ? *r * *r : 0.0;
          if (!(std::sqrt(s2) < kMaxRotationAngle))
            f.fail("the rotation angle " + format_number(std::sqrt(s2)) +
                   " rad must be below 2π (a rotation vector cannot describe more)");
        });
  s.vec3("force", &Cap::force, "N",
         "force on the cap at the end of the ramp, on its free displacement components");
  s.vec3("moment", &Cap::moment, "N mm",
         "moment on the cap at the end of the ramp, on its free rotation components (work "
         "conjugate to the rotation vector: about a fixed axis, the moment about that axis)");
  ramp_key(s, &Cap::ramp, "time ramp of the prescribed motion, force and moment");
  s.rule("`force` and `moment` only on free components (`~` in `displacement`, `rotation`)",
         [](const FieldMap& m, const Cap& c, const ReadContext&) {
           const char* axes = "xyz";
           for (int k = 0; k < 3; ++k) {
             if (c.displacement[k] && c.force[k] != 0.0)
               m.require("force").fail(std::string("force component ") + axes[k] +
                                       " acts on a prescribed displacement: give `~` for it "
                                       "in `displacement`, or no force");
             if (c.rotation[k] && c.moment[k] != 0.0)
               m.require("moment").fail(std::string("moment component ") + axes[k] +
                                        " acts on a prescribed rotation: give `~` for it in "
                                        "`rotation`, or no moment");
           }
         });
  return s;
}

/// `regions:` items: a volume tag with a material of its own, or rigid.
Schema<Region> region_schema() {
  Schema<Region> s;
  s.place(&Region::place, false);
  s.add({"volume",
         "volume tag",
         "–",
         "",
         "",
         {},
         "the region's tetrahedra (a Gmsh physical volume); a tetrahedron may be in one region "
         "only"},
        [](const Field& f, Region& r, ReadContext&) {
          r.volume = f.name();
          r.volume_place = f.place();
        });
  s.add({"box",
         "[[x, y, z], [x, y, z]]",
         "mm",
         "lower < upper",
         "",
         {},
         "instead of `volume`: the tetrahedra whose centroid lies in this box (lower and upper "
         "corners), for generated meshes, which have no volume tags"},
        [](const Field& f, Region& r, ReadContext&) {
          r.box_place = f.place();
          if (!f.node().IsSequence() || f.node().size() != 2)
            f.fail("expected two corners [[x, y, z], [x, y, z]], got " + f.describe());
          const std::vector<Field> corners = f.items();
          const std::array<Vec3d, 2> box = {corners[0].vec3(), corners[1].vec3()};
          for (int k = 0; k < 3; ++k)
            if (!(box[0][k] < box[1][k]))
              f.fail("the lower corner must be below the upper one in x, y and z (got " +
                     format_number(box[0][k]) + " and " + format_number(box[1][k]) + " in " +
                     std::string(1, "xyz"[k]) + ")");
          r.box = box;
        });
  s.rule("exactly one of `volume` and `box`",
         [](const FieldMap& m, const Region& r, const ReadContext&) {
           if (!r.volume.empty() && r.box)
             m.require("box").fail_at_key("give `volume` or `box`, not both");
           if (r.volume.empty() && !r.box)
             m.self().fail_at_key("give the region's `volume` tag or its `box`");
         });
  s.add({"material",
         "map",
         "",
         "",
         "none",
         {},
         "the region's model and parameters, with the keys of the case's `material` (model, "
         "parameters, incompressibility, bulk_modulus, density)"},
        [](const Field& f, Region& r, ReadContext& context) {
          // The largest density of the body, for the gravity-load rule.
          const double density = context.density;
          r.material = read_material(f, context);
          context.density = std::max(density, r.material->density);
        });
  s.boolean("rigid", &Region::rigid,
            "the region moves as a rigid body with the prescribed `displacement`: its elements "
            "are not assembled and its unknowns are eliminated (a stiff support, a die glued to "
            "the membrane)");
  s.add({"displacement",
         "vector",
         "mm",
         "",
         "[0, 0, 0] (held)",
         {},
         "a rigid region's translation at the end of the ramp"},
        [](const Field& f, Region& r, ReadContext&) { r.displacement = f.vec3(); });
  ramp_key(s, &Region::ramp, "time ramp of a rigid region's `displacement`");
  name_key(s, &Region::name,
           "a rigid region's history columns `force_x:<name>` ... (the reaction: the force the "
           "region exerts on the body, N)");
  s.rule("exactly one of `material` and `rigid: true`",
         [](const FieldMap& m, const Region& r, const ReadContext&) {
           if (r.rigid && r.material)
             m.require("material")
                 .fail_at_key("a rigid region has no material: remove `material` or `rigid`");
           if (!r.rigid && !r.material)
             m.self().fail_at_key("give the region a `material`, or make it `rigid: true`");
         });
  s.rule("`displacement`, `ramp` and `name` only with `rigid: true`",
         [](const FieldMap& m, const Region& r, const ReadContext&) {
           if (r.rigid) return;
           for (const char* key : {"displacement", "ramp", "name"})
             if (const auto f = m.find(key))
               f->fail_at_key(std::string("`") + key + "` applies only to a rigid region");
         });
  return s;
}

/// `probes:` items: named points reported as displacement columns.
const Choices<ProbeField> kProbeFields{{"displacement", ProbeField::displacement},
                                       {"position", ProbeField::position},
                                       {"pressure", ProbeField::pressure},
                                       {"cauchy", ProbeField::cauchy},
                                       {"von_mises", ProbeField::von_mises},
                                       {"principal_stretches", ProbeField::principal_stretches},
                                       {"principal_stresses", ProbeField::principal_stresses},
                                       {"J", ProbeField::J},
                                       {"thickness", ProbeField::thickness}};

Schema<Probe> probe_schema() {
  Schema<Probe> s;
  s.place(&Probe::place, false);
  name_key(s, &Probe::name, "names the probe's history columns (`ux:<name>`, ...)").required();
  s.add({"point",
         "vector",
         "mm",
         "",
         "",
         {},
         "a material point of the undeformed body: inside it, or on its surface (a point the "
         "mesh's flat facets miss goes to the nearest point of the boundary, and the log and "
         "summary.json give the distance; a point farther from the mesh than the longest edge "
         "of the element there is refused)"},
        [](const Field& f, Probe& probe, ReadContext&) {
          probe.point = f.vec3();
          probe.point_place = f.place();
        })
      .required();
  std::vector<std::string> words;
  for (const auto& [word, field] : kProbeFields) words.push_back(word);
  s.add({"fields",
         "list of " + case_detail::doc_choice(words),
         "–",
         "",
         "`[displacement]`",
         {},
         "what the probe reports, as history columns (docs/output.md, \"Probes\"): "
         "displacement, position and pressure interpolated at the point, and thickness on a "
         "wall; cauchy, von_mises, principal_stretches, principal_stresses and J are those of "
         "the element holding the point (the step files' cell fields)"},
        [](const Field& f, Probe& probe, ReadContext&) {
          probe.fields_place = f.place();
          if (!f.node().IsSequence() || f.node().size() == 0)
            f.fail("expected a non-empty list of fields, got " + f.describe());
          probe.fields.clear();
          for (const Field& item : f.items()) {
            const ProbeField field = item.choice(kProbeFields);
            if (std::find(probe.fields.begin(), probe.fields.end(), field) != probe.fields.end())
              item.fail("'" + item.text() + "' is listed twice");
            probe.fields.push_back(field);
          }
        });
  return s;
}

/// `output.wrinkles`.
Schema<WrinkleSettings> wrinkle_schema() {
  Schema<WrinkleSettings> s;
  s.place(&WrinkleSettings::place, true);
  s.choice<char>("axis", &WrinkleSettings::axis, kAxes,
                 "axis of the rings on which wrinkles are measured");
  s.vec3("center", &WrinkleSettings::center, "mm",
         "a point on that axis (the centre of the latitudes)");
  s.add({"rings_deg",
         "list of numbers",
         "deg",
         kLatitude.describe(),
         "empty (no wrinkle metrics)",
         {},
         "latitudes of the rings (0 is the equator; ±90 would be a single point)"},
        [](const Field& f, WrinkleSettings& w, ReadContext&) { w.rings_deg = f.reals(kLatitude); });
  s.real("threshold", &WrinkleSettings::threshold, Range::positive(), "–",
         "a ring is wrinkled when its amplitude exceeds threshold × wall thickness");
  s.integer("min_count", &WrinkleSettings::min_count, Range::at_least(1),
            "smaller full-circle wave counts (a shift, an ovalisation) are global shape changes, "
            "not wrinkles");
  s.real("peak_ratio", &WrinkleSettings::peak_ratio, Range::at_least(1.0), "–",
         "a harmonic m ≥ min_count is a wrinkle only if its amplitude exceeds peak_ratio × the "
         "envelope of the global shape there (docs/theory/wrinkles.md, W15–W16); larger is "
         "stricter");
  s.add({"surface",
         "surface tag",
         "–",
         "",
         "`" + WrinkleSettings{}.surface + "`",
         {},
         "the surface the rings are drawn on"},
        [](const Field& f, WrinkleSettings& w, ReadContext&) {
          w.surface = f.text();
          w.surface_place = f.place();
        });
  return s;
}

/// `output:`.
Schema<OutputSettings> output_schema() {
  Schema<OutputSettings> s;
  s.integer("every", &OutputSettings::every, Range::at_least(1),
            "write a VTU file every N converged steps (the last one always; step_0000.vtu, the "
            "undeformed body, first)");
  s.integer("checkpoint_every", &OutputSettings::checkpoint_every, Range::at_least(0),
            "write `checkpoint.bin` every N converged steps (0: only when interrupted); `plisse "
            "run CASE --resume DIR` continues from it");
  s.real("checkpoint_minutes", &OutputSettings::checkpoint_minutes, Range::non_negative(), "min",
         "also write `checkpoint.bin` after a converged step when this much wall time has passed "
         "since the run started or the last checkpoint (0: by step count only), so a long run "
         "loses at most about that much work");
  s.boolean("deformed", &OutputSettings::deformed,
            "write deformed instead of reference coordinates");
  s.choice<VtuCompression>("compression", &OutputSettings::compression,
                           {{"zlib", VtuCompression::zlib}, {"none", VtuCompression::none}},
                           "the step files' data: zlib-compressed (ParaView, VTK and meshio read "
                           "it; about a quarter smaller for a deformed state, ten times for "
                           "step 0) or raw (a little faster to write and read)");
  s.add({"stretch_axis",
         case_detail::doc_choice({"x", "y", "z"}),
         "–",
         "",
         "none",
         {},
         "adds the history column `stretch` (volume-averaged stretch along that axis)"},
        [](const Field& f, OutputSettings& o, ReadContext&) { o.stretch_axis = f.choice(kAxes); });
  s.nested<WrinkleSettings>("wrinkles", &OutputSettings::wrinkles, wrinkle_schema());
  return s;
}

/// The top level: one row per section, in the order the allowed keys are listed.
Schema<Case> case_schema() {
  Schema<Case> s;
  s.add({"title", "text", "–", "", "empty", {}, "one-line description, written to the run log"},
        [](const Field& f, Case& c, ReadContext&) { c.title = f.text(); })
      .null_is_absent();
  s.choice<ElementFamily>(
      "element", &Case::element, kElementFamilies,
      "mini: linear tetrahedra (P1+/P1); taylor-hood: 10-node tetrahedra (P2/P1), which bend right "
      "with one or two elements through a wall; generated meshes are then made second-order");
  s.add({"mesh", "map", "", "", "", {}, "the mesh, read from a file or generated"},
        [](const Field& f, Case& c, ReadContext& context) { c.mesh = read_mesh(f, context); })
      .required()
      .nested = mesh_schema().doc();
  s.add({"material", "map", "", "", "", {}, "the material model and its parameters"},
        [](const Field& f, Case& c, ReadContext& context) {
          c.material = read_material(f, context);
          context.density = c.material.density;
        })
      .required()
      .nested = material_schema().doc();
  list_key(s, "regions", &Case::regions, region_schema(),
           "volume tags with their own material, or rigid");
  list_key(s, "boundary", &Case::boundary, boundary_schema(), "Dirichlet conditions");
  list_key(s, "loads", &Case::loads, load_schema(),
           "pressure, gravity, traction and point-force loads");
  list_key(s, "cavities", &Case::cavities, cavity_schema(), "fluid-filled cavities");
  list_key(s, "dies", &Case::dies, die_schema(), "rigid dies");
  list_key(s, "caps", &Case::caps, cap_schema(), "rigid end caps");
  list_key(s, "contacts", &Case::contacts, contact_schema(),
           "contact between surfaces of the body, or of a surface with itself");
  list_key(s, "probes", &Case::probes, probe_schema(),
           "points whose displacement, stresses or thickness are reported at every step");
  s.nested<SolverSettings>("solver", &Case::solver, solver_schema());
  s.nested<OutputSettings>("output", &Case::output, output_schema());
  return s;
}

const Schema<Case>& the_case_schema() {
  static const Schema<Case> schema = case_schema();
  return schema;
}

/// Every key and scalar value of the case, from the file or from --set, is text a terminal and a
/// log can show as written: UTF-8 without control characters (after YAML's escapes, which can
/// make them). Walks the tree with an explicit stack: the depth is the input's.
void check_scalar_text(const YAML::Node& root, const case_detail::Source& source) {
  std::vector<std::pair<YAML::Node, std::string>> stack = {{root, ""}};
  while (!stack.empty()) {
    const auto [node, path] = stack.back();
    stack.pop_back();
    if (node.IsScalar()) {
      if (const std::string problem = case_detail::scalar_text_problem(node.Scalar());
          !problem.empty())
        throw InputError(source.place(node, path), "the value " + problem);
    } else if (node.IsMap()) {
      for (const auto& item : node) {
        const std::string key = item.first.IsScalar() ? item.first.Scalar() : std::string();
        if (const std::string problem = case_detail::scalar_text_problem(key); !problem.empty())
          throw InputError(source.place(item.first, path), "a key " + problem);
        stack.emplace_back(item.second, case_detail::child_path(path, key));
      }
    } else if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i)
        stack.emplace_back(node[i], case_detail::item_path(path, i));
    }
  }
}

}  // namespace

Case parse_case_string(const std::string& text, const std::string& name,
                       const std::vector<std::string>& overrides) {
  YAML::Node root = case_detail::load_case_document(text, name);
  if (!root.IsDefined() || root.IsNull())
    throw InputError({name, 0, 0, ""}, "the case file is empty");
  if (!root.IsMap())
    throw InputError({name, root.Mark().line + 1, root.Mark().column + 1, ""},
                     "expected a map of sections (mesh:, material:, ...) at the top level");
  const case_detail::Source source(name, case_detail::apply_overrides(root, overrides));
  check_scalar_text(root, source);
  const Field top_field(source, root, YAML::Node(), "");
  const FieldMap top = top_field.map();
  const Schema<Case>& schema = the_case_schema();
  schema.check_keys(top, {}, "");

  Case c;
  c.path = name;
  c.directory = std::filesystem::path(name).parent_path().string();
  ReadContext context;
  context.directory = c.directory;
  // Every ramp defaults to [0, solver.end_time]: the solver goes first.
  schema.read_key("solver", top, c, context);
  context.end_time = c.solver.end_time;
  for (const std::string& key : schema.keys())
    if (key != "solver") schema.read_key(key, top, c, context);
  return c;
}

Case parse_case_file(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_case_string(case_detail::read_case_text(path), path, overrides);
}

std::vector<std::string> case_key_sections() {
  std::vector<std::string> out = the_case_schema().keys();
  out.insert(std::find(out.begin(), out.end(), "mesh") + 1, "mesh-options");
  return out;
}

std::string case_keys_markdown(const std::string& section) {
  if (section == "mesh-options") return mesh_options_markdown();
  for (const auto& row : the_case_schema().rows()) {
    if (row.doc.key != section) continue;
    if (row.nested) return case_detail::render_markdown(*row.nested);
    return case_detail::render_markdown({{row.doc}, {}});
  }
  throw Error("no case-file section '" + section + "'; sections: " + join(case_key_sections()));
}

}  // namespace plisse
