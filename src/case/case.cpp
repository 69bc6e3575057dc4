// The case file's top level: one row per section (the sections' tables are in *_section.cpp, the
// term sections are read by the term kinds of src/terms), the check of every scalar's text, and
// parsing a case from its file or text. The tables also generate the key tables of
// docs/case-file.md (keys.hpp). The raw YAML text is in yaml_text.cpp, `--set` in overrides.cpp,
// the checks that need the mesh in mesh_checks.cpp.
#include "case/case.hpp"

#include <algorithm>
#include <filesystem>

#include "case/keys.hpp"
#include "case/overrides.hpp"
#include "case/petsc_option_text.hpp"
#include "case/sections.hpp"
#include "case/solver_section.hpp"
#include "case/yaml_text.hpp"
#include "schema/field.hpp"
#include "schema/table.hpp"
#include "terms/keys.hpp"

namespace plisse {
namespace {

using namespace case_detail;
using schema::Choices;
using schema::Field;
using schema::FieldMap;
using schema::join;
using schema::ReadContext;
using schema::Schema;

const Choices<ElementFamily> kElementFamilies{{"mini", ElementFamily::mini},
                                              {"taylor-hood", ElementFamily::taylor_hood},
                                              {"shell", ElementFamily::shell}};

const Choices<RegionPressure> kRegionPressures{{"discontinuous", RegionPressure::discontinuous},
                                               {"continuous", RegionPressure::continuous}};

/// A term section (terms/term_kind.hpp): a list of entries, each read by its kind.
void term_list_key(Schema<Case>& schema, const std::string& key) {
  auto& row = schema.add({key, "list", "", "", "empty", {}, term_section(key).help},
                         [key](const Field& f, Case& c, ReadContext& context) {
                           for (const Field& item : f.items())
                             c.terms.push_back(read_term(key, item, context));
                         });
  row.nested = term_section_doc(key);
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
      "with one or two elements through a wall; generated meshes are then made second-order; "
      "shell: the rotation-free Kirchhoff-Love triangle on the wall's mid-surface (three unknowns "
      "a node), meshed from a Gmsh surface mesh or generated as the mid-surface of the kind");
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
  s.add({"region_pressure",
         schema::doc_choice({"discontinuous", "continuous"}),
         "–",
         "",
         "`discontinuous`",
         {},
         "mini and taylor-hood with regions: discontinuous gives each region its own pressure "
         "unknowns at the corner nodes it shares with another region, so that the pressure jumps "
         "across their interface as the hydrostatic stress of bonded materials does; continuous "
         "shares one pressure field, which smears the jump over the elements at the interface"},
        [](const Field& f, Case& c, ReadContext&) {
          c.region_pressure = f.choice(kRegionPressures);
          c.region_pressure_place = f.place();
        });
  for (const char* section : {"boundary", "loads", "cavities", "dies", "caps", "contacts"})
    term_list_key(s, section);
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
void check_scalar_text(const YAML::Node& root, const schema::Source& source) {
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
        stack.emplace_back(item.second, schema::child_path(path, key));
      }
    } else if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i)
        stack.emplace_back(node[i], schema::item_path(path, i));
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
  const schema::Source source(name, case_detail::apply_overrides(root, overrides));
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
  out.insert(std::find(out.begin(), out.end(), "solver") + 1, "petsc-options");
  return out;
}

std::string case_keys_markdown(const std::string& section) {
  if (section == "mesh-options") return mesh_options_markdown();
  if (section == "petsc-options") return petsc_options_markdown();
  for (const auto& row : the_case_schema().rows()) {
    if (row.doc.key != section) continue;
    if (row.nested) return schema::render_markdown(*row.nested);
    return schema::render_markdown({{row.doc}, {}});
  }
  throw Error("no case-file section '" + section + "'; sections: " + join(case_key_sections()));
}

}  // namespace plisse
