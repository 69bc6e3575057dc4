// The case-file schema: which keys each section has, their types, ranges and defaults, and the
// rules between them. Reading and locating values is in case_reader.cpp, `--set` in
// case_overrides.cpp, the checks that need the mesh in case_mesh.cpp. The user's reference for
// every key here is docs/case-file.md: keep the two in step.
#include "io/case.hpp"

#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>

#include "io/case_overrides.hpp"
#include "io/case_reader.hpp"
#include "material/registry.hpp"

namespace plisse {
namespace {

using case_detail::Field;
using case_detail::FieldMap;
using case_detail::format_number;
using case_detail::join;

const Range kFraction{0.0, 1.0, true, false};  // (0, 1]
const Range kOpenUnit{0.0, 1.0, true, true};   // (0, 1)
// A ring at +-90 degrees would be a single point: latitudes are open at the poles.
const Range kLatitude{-90.0, 90.0, true, true};

const std::vector<std::pair<std::string, BoundaryType>> kBoundaryTypes{
    {"fixed", BoundaryType::fixed},
    {"symmetry", BoundaryType::symmetry},
    {"displacement", BoundaryType::displacement}};
const std::vector<std::pair<std::string, LoadType>> kLoadTypes{{"pressure", LoadType::pressure},
                                                               {"gravity", LoadType::gravity}};
const std::vector<std::pair<std::string, CavityControl>> kCavityControls{
    {"volume", CavityControl::volume}, {"gas", CavityControl::gas}};
const std::vector<std::pair<std::string, DieShape>> kDieShapes{
    {"plane", DieShape::plane}, {"sphere", DieShape::sphere}, {"cylinder", DieShape::cylinder}};
const std::vector<std::pair<std::string, ContactKind>> kContactKinds{
    {"frictionless", ContactKind::frictionless}, {"sticking", ContactKind::sticking}};
const std::vector<std::pair<std::string, Scheme>> kSchemes{
    {"total-lagrangian", Scheme::total_lagrangian}, {"incremental", Scheme::incremental}};
const std::vector<std::pair<std::string, LineSearch>> kLineSearches{{"bt", LineSearch::bt},
                                                                    {"basic", LineSearch::basic},
                                                                    {"l2", LineSearch::l2},
                                                                    {"cp", LineSearch::cp}};
const std::vector<std::pair<std::string, LinearSolverType>> kLinearSolverTypes{
    {"direct", LinearSolverType::direct}, {"iterative", LinearSolverType::iterative}};
const std::vector<std::pair<std::string, bool>> kIncompressibility{{"exact", true},
                                                                   {"nearly", false}};
const std::vector<std::pair<std::string, std::string>> kImperfectionKinds{{"random", "random"},
                                                                          {"mode", "mode"}};
const std::vector<std::pair<std::string, char>> kAxes{{"x", 'x'}, {"y", 'y'}, {"z", 'z'}};

/// Largest case file read [bytes]; real ones are a few kB.
constexpr std::size_t kMaxCaseFileBytes = std::size_t{16} << 20;

const std::vector<std::string> kSections{"title",    "mesh", "material", "boundary", "loads",
                                         "cavities", "dies", "probes",   "solver",   "output"};

/// State shared while reading one case: ramp default and the names already used.
struct Reader {
  double end_time = 1.0;
  /// name -> (key path of the entry, its place): boundary conditions, loads, cavities, dies and
  /// probes share one namespace because their history columns ("force_x:<name>",
  /// "pressure:<name>", ...) must not collide.
  std::map<std::string, std::pair<std::string, InputPlace>> names;

  std::string unique_name(const FieldMap& entry) {
    return unique_name(entry.require("name"), entry);
  }

  std::string unique_name(const Field& f, const FieldMap& entry) {
    const std::string name = f.name();
    const auto [it, inserted] = names.try_emplace(name, entry.self().path(), f.place());
    if (!inserted) {
      const InputPlace& first = it->second.second;
      f.fail("name '" + name + "' is already used by " + it->second.first +
             (first.line > 0 ? " (line " + std::to_string(first.line) + ")" : std::string()) +
             "; names of boundary conditions, loads, cavities, dies and probes must be unique");
    }
    return name;
  }

  /// `ramp: [start, end]` [s]; default [0, solver.end_time].
  Ramp ramp(const FieldMap& entry) const {
    const auto f = entry.find("ramp");
    if (!f) return {0.0, end_time};
    if (!f->node().IsSequence() || f->node().size() != 2)
      f->fail("expected a list of 2 numbers [start, end] in s, got " + f->describe());
    const std::vector<double> t = f->reals();
    if (t[0] < 0.0) f->fail("ramp start must be >= 0 (got " + format_number(t[0]) + ")");
    if (!(t[1] > t[0]))
      f->fail("ramp end must be > start (got [" + format_number(t[0]) + ", " + format_number(t[1]) +
              "])");
    return {t[0], t[1]};
  }
};

SurfaceRef surface_ref(const Field& f) {
  const std::string name = f.text();
  if (name.empty()) f.fail("a surface tag name must not be empty");
  return {name, f.place()};
}

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<std::string> kind_names() {
  std::vector<std::string> out;
  for (const MeshKind& k : mesh_kinds()) out.push_back(k.name);
  return out;
}

MeshSection read_mesh(const Field& field, const std::string& directory) {
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
    m.check_keys({"file", "thickness"}, "a mesh read from a file", all_options);
    if (const auto t = m.find("thickness")) s.file_thickness = t->real(Range::positive());
    const std::string text = file->text();
    if (text.empty()) file->fail("the mesh file name must not be empty");
    std::filesystem::path p(text);
    if (p.is_relative() && !directory.empty()) p = std::filesystem::path(directory) / p;
    s.file = p.string();
    s.file_place = file->place();
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
  std::vector<std::string> allowed{"generate"};
  for (const MeshOption& o : kind->options) allowed.push_back(o.key);
  m.check_keys(allowed, "generate: " + kind->name, with(all_options, {"file"}));

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

MaterialSection read_material(const Field& field) {
  const FieldMap m = field.map();
  MaterialSection s;
  s.place = field.key_place();
  const Field model = m.require("model");
  s.model = model.text();
  std::vector<std::string> models;
  for (const MaterialModelInfo& info : material_models()) models.push_back(info.name);
  const MaterialModelInfo* info = find_material_model(s.model);
  if (!info) {
    std::string rule = "unknown material model '" + s.model + "'; known models: " + join(models);
    if (const auto guess = case_detail::closest_match(s.model, models))
      rule += " (did you mean '" + *guess + "'?)";
    model.fail(rule);
  }
  std::vector<std::string> allowed{"model", "incompressibility", "bulk_modulus", "density"};
  for (const ParamSpec& p : info->params) allowed.push_back(p.name);
  std::vector<std::string> other_params;
  for (const MaterialModelInfo& other : material_models())
    for (const ParamSpec& p : other.params) other_params.push_back(p.name);
  m.check_keys(allowed, "model '" + info->name + "'", other_params);

  s.exact_incompressibility = m.choice("incompressibility", true, kIncompressibility);
  const auto bulk = m.find("bulk_modulus");
  if (s.exact_incompressibility && bulk)
    bulk->fail_at_key(
        "bulk_modulus applies only with 'incompressibility: nearly' (exact "
        "incompressibility has an infinite bulk modulus)");
  if (!s.exact_incompressibility) {
    if (!bulk) {
      InputPlace p = m.find("incompressibility")->place();
      p.key = case_detail::child_path(field.path(), "bulk_modulus");
      throw InputError(p, "required with 'incompressibility: nearly' (bulk modulus in MPa, > 0)");
    }
    s.bulk_modulus = bulk->real(Range::positive());
  }
  s.density = m.real("density", 0.0, Range::non_negative());

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
      p = model.place();
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

BoundaryCondition read_boundary(const Field& field, Reader& reader) {
  const FieldMap m = field.map();
  BoundaryCondition bc;
  bc.place = field.place();
  const Field type = m.require("type");
  bc.type = type.choice(kBoundaryTypes);
  const std::string variant = "type '" + type.text() + "'";
  if (bc.type == BoundaryType::displacement)
    m.check_keys({"type", "name", "surface", "value", "ramp"}, variant);
  else
    m.check_keys({"type", "name", "surface"}, variant, {"value", "ramp"});
  if (const auto f = m.find("name")) bc.name = reader.unique_name(*f, m);
  bc.surface = surface_ref(m.require("surface"));
  if (bc.type != BoundaryType::displacement) return bc;

  const Field value = m.require("value");
  if (!value.node().IsSequence() || value.node().size() != 3)
    value.fail(
        "expected a list of 3 displacements [ux, uy, uz] in mm, ~ for a free component, got " +
        value.describe());
  const std::vector<Field> items = value.items();
  bool any = false;
  for (int k = 0; k < 3; ++k) {
    if (items[k].is_null()) continue;
    bc.value[k] = items[k].real();
    any = true;
  }
  if (!any) value.fail("at least one component must be prescribed (all three are ~)");
  bc.ramp = reader.ramp(m);
  return bc;
}

Load read_load(const Field& field, Reader& reader, const MaterialSection& material) {
  const FieldMap m = field.map();
  Load load;
  load.place = field.place();
  const Field type = m.require("type");
  load.type = type.choice(kLoadTypes);
  const std::string variant = "type '" + type.text() + "'";
  if (load.type == LoadType::pressure)
    m.check_keys({"type", "name", "surface", "value", "ramp"}, variant, {"acceleration"});
  else
    m.check_keys({"type", "name", "acceleration", "ramp"}, variant, {"surface", "value"});
  load.name = reader.unique_name(m);
  if (load.type == LoadType::pressure) {
    load.surface = surface_ref(m.require("surface"));
    load.value = m.require("value").real();
  } else {
    load.acceleration = m.require("acceleration").vec3();
    if (!(material.density > 0.0))
      type.fail("a gravity load needs material.density > 0 (got " +
                format_number(material.density) + ")");
  }
  load.ramp = reader.ramp(m);
  return load;
}

Cavity read_cavity(const Field& field, Reader& reader) {
  const FieldMap m = field.map();
  Cavity c;
  c.place = field.place();
  c.control = m.choice("control", CavityControl::volume, kCavityControls);
  const std::vector<std::string> common{"name", "surface", "control", "ramp"};
  const std::vector<std::string> volume{"volume_ratio"};
  const std::vector<std::string> gas{"initial_pressure", "mass_ratio", "ambient_pressure"};
  if (c.control == CavityControl::volume)
    m.check_keys(with(common, volume), "control 'volume'", gas);
  else
    m.check_keys(with(common, gas), "control 'gas'", volume);
  c.name = reader.unique_name(m);
  c.surface = surface_ref(m.require("surface"));
  c.volume_ratio = m.real("volume_ratio", c.volume_ratio, Range::positive());
  c.initial_pressure = m.real("initial_pressure", c.initial_pressure, Range::non_negative());
  c.mass_ratio = m.real("mass_ratio", c.mass_ratio, Range::positive());
  c.ambient_pressure = m.real("ambient_pressure", c.ambient_pressure, Range::positive());
  c.ramp = reader.ramp(m);
  return c;
}

/// A direction, normalised; the zero vector is an error.
Vec3d unit_vector(const Field& f) {
  const Vec3d v = f.vec3();
  const double norm = v.norm();
  if (!(norm > 0.0) || !std::isfinite(norm))
    f.fail("must be a non-zero direction (its length is 0)");
  return v / norm;
}

Die read_die(const Field& field, Reader& reader) {
  const FieldMap m = field.map();
  Die d;
  d.place = field.place();
  const Field shape = m.require("shape");
  d.shape = shape.choice(kDieShapes);
  d.contact = m.choice("contact", ContactKind::frictionless, kContactKinds);
  std::vector<std::string> allowed{"name",    "shape", "point",   "contact",
                                   "surface", "move",  "penalty", "tolerance"};
  if (d.shape == DieShape::plane) allowed.push_back("normal");
  if (d.shape == DieShape::cylinder) allowed.push_back("axis");
  if (d.shape != DieShape::plane) allowed.push_back("radius");
  if (d.contact == ContactKind::sticking) allowed.push_back("region");
  const std::string variant = "shape '" + shape.text() + "' with contact '" +
                              (d.contact == ContactKind::sticking ? "sticking" : "frictionless") +
                              "'";
  m.check_keys(allowed, variant, {"normal", "axis", "radius", "region"});

  d.name = reader.unique_name(m);
  d.point = m.require("point").vec3();
  if (d.shape == DieShape::plane) d.normal = unit_vector(m.require("normal"));
  if (d.shape == DieShape::cylinder) d.axis = unit_vector(m.require("axis"));
  if (d.shape != DieShape::plane) d.radius = m.require("radius").real(Range::positive());
  if (const auto f = m.find("region")) d.region = surface_ref(*f);
  if (const auto f = m.find("surface")) d.surface = surface_ref(*f);
  d.penalty = m.real("penalty", d.penalty, Range::non_negative());
  d.tolerance = m.real("tolerance", d.tolerance, Range::positive());
  d.ramp = {0.0, reader.end_time};  // a die without `move` stays put; its ramp is unused
  if (const auto move = m.find("move")) {
    const FieldMap mm = move->map();
    mm.check_keys({"displacement", "ramp"});
    if (const auto f = mm.find("displacement")) d.displacement = f->vec3();
    d.ramp = reader.ramp(mm);
  }
  return d;
}

Probe read_probe(const Field& field, Reader& reader) {
  const FieldMap m = field.map();
  m.check_keys({"name", "point"});
  Probe p;
  p.place = field.place();
  p.name = reader.unique_name(m);
  p.point = m.require("point").vec3();
  return p;
}

/// `solver.newton.linear`: the iterative solver's keys do not apply to the direct one.
LinearSolverSettings read_linear_solver(const Field& field) {
  const FieldMap m = field.map();
  LinearSolverSettings s;
  s.place = field.key_place();
  s.type = m.choice("type", s.type, kLinearSolverTypes);
  const std::vector<std::string> iterative{"rtol", "max_iterations", "restart"};
  if (s.type == LinearSolverType::direct)
    m.check_keys({"type"}, "type 'direct'", iterative);
  else
    m.check_keys(with({"type"}, iterative), "type 'iterative'");
  s.rtol = m.real("rtol", s.rtol, kOpenUnit);
  s.max_iterations = m.integer("max_iterations", s.max_iterations, Range::at_least(1));
  s.restart = m.integer("restart", s.restart, Range::at_least(1));
  return s;
}

SolverSettings read_solver(const Field& field, const std::string& directory) {
  const FieldMap m = field.map();
  m.check_keys({"scheme", "end_time", "steps", "max_steps", "min_step", "max_step", "growth",
                "cutback", "easy_iterations", "viscosity", "max_augmentations", "newton", "stability",
                "petsc_options"});
  SolverSettings s;
  s.scheme = m.choice("scheme", s.scheme, kSchemes);
  s.end_time = m.real("end_time", s.end_time, Range::positive());
  s.steps = m.integer("steps", s.steps, Range::at_least(1));
  s.max_steps = m.integer("max_steps", s.max_steps, Range::at_least(1));
  s.min_step = m.real("min_step", s.min_step, kFraction);
  s.max_step = m.real("max_step", s.max_step, kFraction);
  s.growth = m.real("growth", s.growth, Range::at_least(1.0));
  s.cutback = m.real("cutback", s.cutback, kOpenUnit);
  s.easy_iterations = m.integer("easy_iterations", s.easy_iterations, Range::at_least(1));
  s.viscosity = m.real("viscosity", s.viscosity, Range::non_negative());
  s.max_augmentations =
      m.integer("max_augmentations", s.max_augmentations, Range::at_least(0));
  if (const auto f = m.find("petsc_options"); f && !f->is_null()) {
    s.petsc_options = f->text();
    s.petsc_options_place = f->place();
    // PETSc reads "-name [value] -name [value] ...": a word before the first option, or two words
    // in a row, is not read as anything and PETSc ignores it without a word (a forgotten dash in
    // "ksp_type preonly" silently kept the default solver).
    std::istringstream words(s.petsc_options);
    bool after_value = true;  // nothing may come before the first "-option"
    for (std::string word; words >> word;) {
      const bool option = word.size() > 1 && word[0] == '-';
      if (!option && after_value)
        f->fail("'" + word +
                "' is neither a PETSc option (options start with '-') nor the value of the "
                "option before it; expected e.g. '-ksp_type preonly -pc_type lu'");
      after_value = !option;
    }
  }
  if (s.min_step > s.max_step)
    (m.has("min_step") ? *m.find("min_step") : *m.find("max_step"))
        .fail("min_step must be <= max_step (got min_step " + format_number(s.min_step) +
              ", max_step " + format_number(s.max_step) + ")");
  if (s.steps > s.max_steps)
    (m.has("steps") ? *m.find("steps") : *m.find("max_steps"))
        .fail("steps must be <= max_steps (got steps " + std::to_string(s.steps) + ", max_steps " +
              std::to_string(s.max_steps) + ")");

  if (const auto f = m.find("newton")) {
    const FieldMap n = f->map();
    n.check_keys({"rtol", "atol", "max_iterations", "line_search", "linear"});
    NewtonSettings& ns = s.newton;
    ns.rtol = n.real("rtol", ns.rtol, kOpenUnit);
    ns.atol = n.real("atol", ns.atol, Range::non_negative());
    ns.max_iterations = n.integer("max_iterations", ns.max_iterations, Range::at_least(1));
    ns.line_search = n.choice("line_search", ns.line_search, kLineSearches);
    if (const auto l = n.find("linear"); l && !l->is_null()) ns.linear = read_linear_solver(*l);
  }
  if (const auto f = m.find("stability")) {
    const FieldMap st = f->map();
    st.check_keys({"check", "branch_switch", "modes", "imperfection", "imperfection_kind", "seed",
                   "imperfection_from", "imperfection_mode", "branch_amplitude"});
    StabilitySettings& ss = s.stability;
    ss.place = f->key_place();
    ss.check = st.boolean("check", ss.check);
    ss.branch_switch = st.boolean("branch_switch", ss.branch_switch);
    ss.modes = st.integer("modes", ss.modes, Range::at_least(1));
    ss.imperfection = st.real("imperfection", ss.imperfection, Range::non_negative());
    ss.imperfection_kind = st.choice("imperfection_kind", ss.imperfection_kind, kImperfectionKinds);
    ss.seed = st.integer("seed", ss.seed, Range::at_least(0));
    ss.imperfection_mode = st.integer("imperfection_mode", ss.imperfection_mode, Range::at_least(1));
    ss.branch_amplitude = st.real("branch_amplitude", ss.branch_amplitude, Range::positive());
    if (const auto from = st.find("imperfection_from")) {
      if (ss.imperfection_kind != "mode")
        from->fail_at_key("imperfection_from needs 'imperfection_kind: mode'");
      const std::string text = from->text();
      if (text.empty()) from->fail("must name a run directory or a .vtu file");
      std::filesystem::path p(text);
      if (p.is_relative() && !directory.empty()) p = std::filesystem::path(directory) / p;
      ss.imperfection_from = p.string();
    }
    if (ss.imperfection_kind == "mode" && ss.imperfection > 0.0 && ss.imperfection_from.empty())
      throw InputError(ss.place,
                       "'imperfection_kind: mode' needs 'imperfection_from: DIR', the run whose "
                       "eigenmode shapes the imperfection");
    if (ss.branch_switch && !ss.check)
      st.find("branch_switch")
          ->fail(
              "branch_switch needs 'check: true' (the instability it switches at is found by "
              "the stability check)");
  }
  return s;
}

OutputSettings read_output(const Field& field) {
  const FieldMap m = field.map();
  m.check_keys({"every", "checkpoint_every", "deformed", "stretch_axis", "wrinkles"});
  OutputSettings s;
  s.every = m.integer("every", s.every, Range::at_least(1));
  s.checkpoint_every = m.integer("checkpoint_every", s.checkpoint_every, Range::at_least(0));
  s.deformed = m.boolean("deformed", s.deformed);
  if (const auto f = m.find("stretch_axis")) s.stretch_axis = f->choice(kAxes);
  if (const auto f = m.find("wrinkles")) {
    const FieldMap w = f->map();
    w.check_keys({"axis", "center", "rings_deg", "threshold", "min_count", "surface"});
    s.wrinkles.place = f->key_place();
    s.wrinkles.axis = w.choice("axis", s.wrinkles.axis, kAxes);
    if (const auto c = w.find("center")) s.wrinkles.center = c->vec3();
    s.wrinkles.min_count = w.integer("min_count", s.wrinkles.min_count, Range::at_least(1));
    if (const auto sf = w.find("surface")) {
      s.wrinkles.surface = sf->text();
      s.wrinkles.surface_place = sf->place();
    }
    if (const auto r = w.find("rings_deg")) s.wrinkles.rings_deg = r->reals(kLatitude);
    s.wrinkles.threshold = w.real("threshold", s.wrinkles.threshold, Range::positive());
  }
  return s;
}

/// Length of the well-formed UTF-8 sequence of 2 to 4 bytes at text[i] (RFC 3629, section 4), or 0.
std::size_t utf8_sequence_length(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  std::size_t n = 0;
  if (byte(i) >= 0xc2 && byte(i) <= 0xdf) n = 2;
  if (byte(i) >= 0xe0 && byte(i) <= 0xef) n = 3;
  if (byte(i) >= 0xf0 && byte(i) <= 0xf4) n = 4;
  if (n == 0 || i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
  return n;
}

/// Offset of the first byte YAML does not allow in a UTF-8 stream (YAML 1.2, section 5.1,
/// c-printable): a control character other than tab, line feed and carriage return, DEL, or a
/// byte that does not begin a well-formed UTF-8 sequence; npos when there is none. yaml-cpp
/// passes such bytes into messages and values, so a binary file gave errors full of raw bytes.
/// Streams with a UTF-16 or UTF-32 byte order mark are left to yaml-cpp.
std::size_t first_non_text_byte(const std::string& text) {
  using namespace std::string_view_literals;
  for (const std::string_view bom : {"\xFE\xFF"sv, "\xFF\xFE"sv, "\0\0\xFE\xFF"sv})
    if (std::string_view(text).substr(0, bom.size()) == bom) return std::string::npos;
  for (std::size_t i = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0; i < text.size();) {
    const auto ch = static_cast<unsigned char>(text[i]);
    if (ch >= 0x80) {
      const std::size_t n = utf8_sequence_length(text, i);
      if (n == 0) return i;
      i += n;
      continue;
    }
    if ((ch < 0x20 && ch != '\t' && ch != '\n' && ch != '\r') || ch == 0x7f) return i;
    ++i;
  }
  return std::string::npos;
}

/// Offset of the start of 0-based line `line` of `text` (npos past the end).
std::size_t line_start(const std::string& text, int line) {
  std::size_t start = 0;
  for (int l = 0; l < line && start != std::string::npos; ++l) {
    start = text.find('\n', start);
    if (start != std::string::npos) ++start;
  }
  return start;
}

/// Whether 0-based line `line` of `text` has a tab in its indentation.
bool indented_with_tab(const std::string& text, int line) {
  const std::size_t start = line_start(text, line);
  for (std::size_t i = start; i != std::string::npos && i < text.size(); ++i) {
    if (text[i] == '\t') return true;
    if (text[i] != ' ') return false;
  }
  return false;
}

/// Finds a quoted scalar that is never closed. yaml-cpp ends such a scalar at the end of the input
/// instead of reporting it, so `title: "abc` swallows the rest of the file into one text value and
/// the sections after it silently vanish. The parser's events give each scalar's mark (a byte
/// offset, at the scalar's tag or anchor if it has one); the quote found there must be closed.
class UnclosedQuoteFinder : public YAML::EventHandler {
 public:
  explicit UnclosedQuoteFinder(const std::string& text) : text_(text) {
    if (text_.rfind("\xEF\xBB\xBF", 0) == 0) bom_ = 3;  // yaml-cpp's offsets skip a UTF-8 BOM
  }
  /// The mark of the first unclosed quoted scalar, if any.
  const std::optional<YAML::Mark>& found() const { return found_; }
  /// Documents seen so far, and where the second one starts (its first node, else its start).
  int documents() const { return documents_; }
  std::optional<YAML::Mark> second_document() const {
    return second_node_ ? second_node_ : second_document_;
  }

  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t,
                const std::string&) override {
    note(mark);
    if (tag == "?" || found_) return;  // plain scalars have no quotes
    std::size_t i = static_cast<std::size_t>(mark.pos) + bom_;
    // Skip the node's properties: "!tag" and "&anchor", each followed by blanks.
    while (i < text_.size() && (text_[i] == '!' || text_[i] == '&')) {
      while (i < text_.size() && !std::isspace(static_cast<unsigned char>(text_[i]))) ++i;
      while (i < text_.size() && (text_[i] == ' ' || text_[i] == '\t')) ++i;
    }
    if (i >= text_.size() || (text_[i] != '"' && text_[i] != '\'')) return;  // block scalar
    if (!closed(i)) found_ = mark;
  }
  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ == 2) second_document_ = mark;
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { note(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { note(mark); }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    note(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    note(mark);
  }
  void OnMapEnd() override {}

 private:
  void note(const YAML::Mark& mark) {
    if (documents_ == 2 && !second_node_) second_node_ = mark;
  }
  /// Whether the quote at `open` has its closing quote: `\"` escapes inside double quotes
  /// (YAML 1.2, section 7.3.1), `''` inside single quotes (section 7.3.2).
  bool closed(std::size_t open) const {
    const char quote = text_[open];
    for (std::size_t i = open + 1; i < text_.size(); ++i) {
      if (quote == '"' && text_[i] == '\\') {
        ++i;
      } else if (text_[i] == quote) {
        if (quote == '\'' && i + 1 < text_.size() && text_[i + 1] == '\'') {
          ++i;
          continue;
        }
        return true;
      }
    }
    return false;
  }

  const std::string& text_;
  std::size_t bom_ = 0;
  std::optional<YAML::Mark> found_;
  int documents_ = 0;
  std::optional<YAML::Mark> second_document_, second_node_;
};

}  // namespace

Case parse_case_string(const std::string& text, const std::string& name,
                       const std::vector<std::string>& overrides) {
  if (const std::size_t at = first_non_text_byte(text); at != std::string::npos) {
    const auto before = text.begin() + static_cast<std::ptrdiff_t>(at);
    const int line = 1 + static_cast<int>(std::count(text.begin(), before, '\n'));
    const std::size_t newline = at == 0 ? std::string::npos : text.rfind('\n', at - 1);
    const int column = static_cast<int>(newline == std::string::npos ? at + 1 : at - newline);
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned char>(text[at]));
    throw InputError({name, line, column, ""},
                     std::string("the case file is not YAML text: byte ") + byte +
                         " is not a printable UTF-8 character (is it a binary file?)");
  }
  // One pass over the events first, stopping at a second document: yaml-cpp 0.7 returns empty
  // documents forever on some malformed text (a lone ','; yaml-cpp issue #1040), so LoadAll may
  // only see text with at most one document.
  UnclosedQuoteFinder finder(text);
  {
    std::istringstream in(text);
    YAML::Parser parser(in);
    try {
      while (finder.documents() < 2 && parser.HandleNextDocument(finder)) {
      }
    } catch (const YAML::Exception&) {  // LoadAll below reports it with its place
    }
  }
  if (const auto& m = finder.second_document()) {
    // A second document starts at a '---' line, or where yaml-cpp gave up on the first one (a
    // stray ',' or ']' at the top level): say which.
    bool marker = false;  // a '---' line at the mark or before it, past blank and comment lines
    for (int l = m->is_null() ? -1 : m->line; l >= 0 && !marker; --l) {
      const std::size_t start = line_start(text, l);
      if (start == std::string::npos) continue;
      const std::string line = text.substr(start, text.find('\n', start) - start);
      marker = line.compare(0, 3, "---") == 0;
      const std::size_t first = line.find_first_not_of(" \t\r");
      if (l < m->line && first != std::string::npos && line[first] != '#') break;
    }
    throw InputError({name, m->is_null() ? 0 : m->line + 1, m->is_null() ? 0 : m->column + 1, ""},
                     marker ? "a case file holds one YAML document, this is a second one (remove "
                              "the '---' line before it or split the file)"
                            : "YAML syntax error: the case's top-level map cannot continue here "
                              "(a stray ',', ']' or '}'?)");
  }
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    const bool marked = !e.mark.is_null();
    std::string rule = "YAML syntax error: " + e.msg;
    // yaml-cpp's messages for a tab in the indentation ("illegal map value", ...) do not say so.
    if (marked && (indented_with_tab(text, e.mark.line) ||
                   (e.mark.line > 0 && indented_with_tab(text, e.mark.line - 1))))
      rule += " (this line or the one before is indented with a tab: YAML indents with spaces)";
    throw InputError({name, marked ? e.mark.line + 1 : 0, marked ? e.mark.column + 1 : 0, ""},
                     rule);
  }
  if (const auto& m = finder.found())
    throw InputError({name, m->line + 1, m->column + 1, ""},
                     "YAML syntax error: this quoted value is never closed (its closing quote "
                     "is missing, so it would run to the end of the file)");
  YAML::Node root = documents.empty() ? YAML::Node() : documents.front();
  if (!root.IsDefined() || root.IsNull())
    throw InputError({name, 0, 0, ""}, "the case file is empty");
  if (!root.IsMap())
    throw InputError({name, root.Mark().line + 1, root.Mark().column + 1, ""},
                     "expected a map of sections (mesh:, material:, ...) at the top level");
  const case_detail::Source source(name, case_detail::apply_overrides(root, overrides));
  const Field top_field(source, root, YAML::Node(), "");
  const FieldMap top = top_field.map();
  top.check_keys(kSections);

  Case c;
  c.path = name;
  c.directory = std::filesystem::path(name).parent_path().string();
  Reader reader;
  if (const auto f = top.find("solver")) c.solver = read_solver(*f, c.directory);
  reader.end_time = c.solver.end_time;
  if (const auto f = top.find("title"); f && !f->is_null()) c.title = f->text();
  c.mesh = read_mesh(top.require("mesh"), c.directory);
  c.material = read_material(top.require("material"));
  if (const auto f = top.find("boundary"))
    for (const Field& item : f->items()) c.boundary.push_back(read_boundary(item, reader));
  if (const auto f = top.find("loads"))
    for (const Field& item : f->items()) c.loads.push_back(read_load(item, reader, c.material));
  if (const auto f = top.find("cavities"))
    for (const Field& item : f->items()) c.cavities.push_back(read_cavity(item, reader));
  if (const auto f = top.find("dies"))
    for (const Field& item : f->items()) c.dies.push_back(read_die(item, reader));
  if (const auto f = top.find("probes"))
    for (const Field& item : f->items()) c.probes.push_back(read_probe(item, reader));
  if (const auto f = top.find("output")) c.output = read_output(*f);
  return c;
}

Case parse_case_file(const std::string& path, const std::vector<std::string>& overrides) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError({path, 0, 0, ""}, "the case file does not exist");
  if (fs::is_directory(path, ec))
    throw InputError({path, 0, 0, ""}, "is a directory, not a case file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0, ""}, "the case file cannot be opened for reading");
  // Read at most kMaxCaseFileBytes + 1: a device such as /dev/zero (or a huge file given by
  // mistake) would otherwise fill the memory before the YAML parser sees a byte.
  std::string text(kMaxCaseFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxCaseFileBytes)
    throw InputError({path, 0, 0, ""}, "the case file is larger than " +
                                           std::to_string(kMaxCaseFileBytes >> 20) +
                                           " MiB; a case file is a short YAML text");
  return parse_case_string(text, path, overrides);
}

}  // namespace plisse
